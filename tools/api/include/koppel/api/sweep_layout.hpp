// The columns of a sweep table, the one place that names them: `koppel analyze`, Model::Sweep
// and the Python module lay their tables out by it. The input, then per output y (a point K: K_x,
// K_y) the columns y, y_d1, ..., y_d<order>, then `singular`.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <string>
#include <vector>

namespace koppel {

struct SweepColumns {
  std::vector<std::string> names;
  std::vector<std::string> units;   // "deg" or the length unit for values; "rad/rad^2", "mm/rad", ...
  std::vector<int> order_of_column; // derivative order; -1 for the input and the flag
  std::vector<bool> angle_value;    // the value of an angle: shown in degrees
};

// Column c >= 1 (up to the flag) holds number c - 1 of PositionSolver::OutputDerivatives.
// `length_unit` labels lengths: the file's unit (Loads::LengthUnit(), "mm"), "length" when unnamed.
SweepColumns SweepLayout(const Mechanism& mechanism, int order, const std::string& length_unit = "length");

}  // namespace koppel
