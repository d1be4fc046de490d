// Which output an analysis of one scalar output means: private to the API (analyses.cpp).
#pragma once

#include "koppel/api/model.hpp"

#include <string>

namespace koppel::api_detail {

// The index of scalar output `name` of the model's mechanism (empty: the first scalar output).
// InputError naming the model's file and the field `output` when there is none.
int ScalarOutput(const Model& model, const std::string& name);

}  // namespace koppel::api_detail
