// The YAML problem file of `koppel synth fit`:
//
//   mechanism: four-bar.yaml        # relative to the problem file
//   parameters:                     # the free ones; the others keep the file's values
//     l3: {start: 4, lower: 3, upper: 6}       # start defaults to the file's value
//   starts: 16                      # optional (default 16): the given start, then random ones within the bounds
//   require: {from: 0, to: 360}     # optional: the design must assemble over this input range
//   tolerance: 1e-6                 # optional (default 1e-6): a target is met within this, in its own
//                                   # unit (length, or degrees for an angle); or {length: 1e-4, angle: 0.01}
//   targets:
//     - {point: K, input: 0, at: [1.65, 8.31]}              # precision point at a prescribed input
//     - {point: K, input: 40, at: [3.4, 8.6], free_input: true}  # input free, 40 the start
//     - {output: psi, input: 90, value: 104.4, weight: 2}   # function generation (angles in degrees,
//                                                           # compared wrapped to (-180, 180])
//     - {straight: K, from: 150, to: 210, tolerance: 0.01}  # a target's own tolerance
//
// Inputs are in degrees for an R drive. Every problem is reported with file:line like the reader.
// The mechanism file is read once; the builder re-parses its text from memory.
#pragma once

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/synthesis/fit.hpp"

#include <string>
#include <vector>

namespace koppel {

struct FitProblem {
  std::string path;
  std::string mechanism_path;
  std::string mechanism_text;        // the mechanism file as the user wrote it (the fitted file edits it)
  MechanismFile base;                // the mechanism with its own parameter values
  std::vector<FitParameter> parameters;
  std::vector<FitTarget> targets;
  FitOptions options;
  MechanismBuilder builder;          // rebuilds `base` with parameter values as overrides
};

FitProblem ReadFitProblem(const std::string& path);

// The unit a report labels a value of `unit` with: "deg", or the mechanism file's length unit
// ("mm"; "length" when the file names none).
std::string FitUnitName(const FitProblem& problem, FitUnit unit);
// A free parameter's unit, read off where its value goes (MeasureOf, parameter_use.hpp): the
// file's length unit, "deg", or "parameter" for a value of no one measure (an angle inside
// cos( ), a ratio).
std::string FitParameterUnitName(const FitProblem& problem, const std::string& name);

}  // namespace koppel
