// The figure quantities a catalog card may name: one table row each with the name written in
// the file, the arguments it takes, the unit of its value and the function that recomputes it
// with the solver. The card reader checks every figure against its row (an unknown quantity or
// argument is an error with its line); `catalog check` calls the row's evaluator.
#pragma once

#include "koppel/catalog/card.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

class FigureContext;  // the analyses of one mechanism variant, shared by its figures (figures.hpp)

enum class ArgumentKind {
  kInput,   // a formula over the parameters in the drive's units: degrees for an R drive
  kNumber,  // a formula over the parameters, no unit
  kOrder,   // a whole number 1..8 (transfer function order)
  kJoint,   // the name of an R joint of the mechanism
};

struct FigureArgument {
  const char* name;
  ArgumentKind kind;
  bool required;
};

// The unit of a figure's value, which decides whether `unit: deg` is required or refused.
enum class ValueUnit {
  kOfOutput,  // the output's: an angle output gives degrees
  kOfInput,   // the drive's: an R drive gives degrees
  kPlain,     // a length, a ratio or a count
};

// Which output a quantity needs: any scalar or point component, a point (the whole curve), an
// angle output, or none (a figure of the mechanism as a whole).
enum class OutputUse { kAny, kPoint, kAngle, kNone };

// What an evaluator returns: the value in internal units (radians for angles), or why it could
// not be computed (a sweep that stopped, a stationary point not found ...).
struct FigureValue {
  std::optional<double> value;
  std::string why_not;
};

using FigureEvaluator = FigureValue (*)(FigureContext& context, const FigureCheck& figure);

// Whether an angle value is a position (compared modulo 360 deg: 360 is 0) or a span (a swing of
// 360 deg is not one of 0).
enum class AngleKind { kPosition, kSpan };

struct FigureQuantityInfo {
  FigureQuantity quantity;
  const char* name;  // as written after `quantity:`
  OutputUse output;
  ValueUnit unit;
  AngleKind angle;
  std::vector<FigureArgument> arguments;
  const char* meaning;  // one line, for `catalog show` and the README
  FigureEvaluator evaluate;
};

// Every quantity, in the order of the FigureQuantity enum.
const std::vector<FigureQuantityInfo>& FigureQuantities();
const FigureQuantityInfo& QuantityInfo(FigureQuantity quantity);
// nullptr for a name no row has.
const FigureQuantityInfo* FindFigureQuantity(const std::string& name);

}  // namespace koppel
