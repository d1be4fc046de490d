// What a sweep does where two branches cross: continue on the branch that continues the
// incoming one analytically (a parallelogram stays a parallelogram), stop there, or switch to
// the other branch. A header of its own, without the solver's types, because the API's headers
// name it (koppel/api/model.hpp: AtBranchPoint) and the front doors read its words.
// Defined in singular.cpp.
#pragma once

#include <optional>
#include <string>

namespace koppel {

enum class BranchPointAction { kContinue, kStop, kSwitch };
const char* ToString(BranchPointAction action);  // "continue", "stop", "switch"
std::optional<BranchPointAction> ParseBranchPointAction(const std::string& text);

}  // namespace koppel
