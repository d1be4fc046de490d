// The drawing for the workshop (koppel export --dxf): every link as a part at one pose (plates,
// holes, slots: parts.hpp) and the traced points' coupler curves over the drivable range of the
// assembly branch (cycle.hpp). Global coordinates in the mechanism's length unit, the frame's
// points where the file puts them (so a pivot at (0, 0) in the file is at the origin here).
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/plot/cycle.hpp"
#include "koppel/plot/parts.hpp"
#include "koppel/plot/plots.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel::plot {

struct WorkshopOptions {
  CycleOptions cycle;
  std::optional<double> at;  // input of the pose [rad | length]; default: the assembly hint's input
};

struct WorkshopDrawing {
  PlotStatus status = PlotStatus::kComplete;  // kPartial: a curve has a gap; kFailed: no pose (nothing drawn)
  std::string message;
  double input = 0;                // the pose's input [rad | length]
  CycleRange range;                // the curves' input range
  std::vector<Part> parts;         // the frame first
  std::vector<TracedCurve> curves; // one per traced point
};

// The pose is continued along the assembly branch from the nearest sample of the cycle, so an
// input beyond a limit of the drive is not reached (kFailed, the message says why). Throws
// std::invalid_argument when the options are not valid (CycleOptions::IsValid).
WorkshopDrawing DrawWorkshop(const Mechanism& mechanism, const WorkshopOptions& options);

}  // namespace koppel::plot
