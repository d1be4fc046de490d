// The forces of a mechanism as pictures: the drive torque (force for a P drive) over the input,
// and the reaction of chosen joints as polar diagrams (the force vector's tip over the cycle, in
// the frame: what a bearing sees), from the same run as `koppel forces`.
#pragma once

#include "koppel/analysis/forces.hpp"
#include "koppel/plot/plots.hpp"

#include <vector>

namespace koppel::plot {

struct ForcesPlotOptions {
  ForcesOptions forces;     // range (radians or length), speed (empty: statics)
  std::vector<int> joints;  // joints whose reaction is drawn as a polar diagram
  bool IsValid(const Mechanism& mechanism, std::string* why) const;
};

// Rows without forces (singular poses, gaps) break the curves and are shaded; the result is then
// partial, as the forces command's exit code.
PlotResult ForcesPlot(const Mechanism& mechanism, const Loads& loads, const ForcesPlotOptions& options);

}  // namespace koppel::plot
