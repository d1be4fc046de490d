// The YAML files of `koppel synth motion` and `koppel synth function`, read with file:line
// diagnostics like every koppel input (every problem of a file reported at once).
//
// Motion (POSES.yaml): the poses of a moving plane, 2 to 5 of them, each the global position of
// a reference point of the plane and the plane's angle in degrees:
//   poses: [[0, 0, 0], [1.2, 0.4, 15], [2.1, 1.3, 40]]
//
// Function (SPEC.yaml):
//   type: four-bar            # or slider-crank (output a slider displacement); default four-bar
//   function: log10(x)        # a formula in x (muparser: log10, sqrt, sin, ^, ...)
//   x: [1, 10]                # the range of x
//   input: [15, 75]           # crank angles [deg] that x_from, x_to map to (linearly)
//   output: [105, 195]        # rocker angles [deg] (four-bar) or slider displacements (length) that f(x_from), f(x_to) map to
//   points: 3                 # Chebyshev spacing, or
//   at: [1.5, 5, 9]           # the precision points' x
//   frame: 1                  # four-bar A0B0 (default 1)
#pragma once

#include "koppel/synthesis/burmester.hpp"
#include "koppel/synthesis/function_synthesis.hpp"

#include <string>
#include <vector>

namespace koppel {

// (the files' contents; the API's MotionSpec and FunctionSpec are requests made in code)
struct MotionSpecFile {
  std::string path;
  std::vector<Pose> poses;  // angles in radians
};

// Throws InputError (mechanism_file.hpp); the file is read within kMaxInputBytes
// (koppel/core/input_file.hpp). The Parse... forms read the text of a file named `path`.
MotionSpecFile ReadMotionSpec(const std::string& path);
MotionSpecFile ParseMotionSpecText(const std::string& text, const std::string& path);

struct FunctionSpecFile {
  std::string path;
  std::string formula;
  FunctionRequest request;  // its function evaluates `formula` (angles in radians)
};

// Throws InputError; the formula is checked at both ends of the x range and at the precision points.
FunctionSpecFile ReadFunctionSpec(const std::string& path);
FunctionSpecFile ParseFunctionSpecText(const std::string& text, const std::string& path);

}  // namespace koppel
