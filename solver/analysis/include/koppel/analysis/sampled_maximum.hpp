// The largest value of a function of the input known at samples, refined between them: Brent's
// method (Boost.Math brent_find_minima) in the bracket of every sample that is a local maximum of
// the samples, from its left to its right neighbour. For a function that is smooth between the
// samples but has no transfer functions of its own, e.g. the structural error of a function
// generator (function_synthesis.hpp), whose desired output is a user's formula; a mechanism's
// outputs get their extremes by Newton on y' (extremes.hpp).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct SampledMaximum {
  bool ok = false;     // false: no samples, or the function could not be evaluated in a bracket
  std::string message;
  double input = 0;    // where the maximum is
  double value = 0;    // the maximum; never below the largest sample
};

// `inputs` ordered (ascending or descending), `values` the function there; `evaluate(input)` the
// function at an input between two samples (nullopt where it cannot be had).
SampledMaximum RefineSampledMaximum(const std::vector<double>& inputs, const std::vector<double>& values,
                                    const std::function<std::optional<double>(double)>& evaluate);

}  // namespace koppel
