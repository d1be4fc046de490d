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
  std::vector<std::string> units;   // "deg" or "length" for values; "rad/rad^2", "length/rad", ...
  std::vector<int> order_of_column; // derivative order; -1 for the input and the flag
  std::vector<bool> angle_value;    // the value of an angle: shown in degrees
};

// Column c >= 1 (up to the flag) holds number c - 1 of PositionSolver::OutputDerivatives.
SweepColumns SweepLayout(const Mechanism& mechanism, int order);

}  // namespace koppel
