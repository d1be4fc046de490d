// The page of `koppel view`: one self-contained HTML file (no network, no server) with the
// scheme animated over the computed range (looping over a full turn, back and forth over a
// limited range), a slider for the input, play/pause and speed, the coupler curves of the point
// outputs traced, one uPlot chart per scalar output (value and derivatives) and per
// transmission angle, a cursor at the current input and the numbers there.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/plot/plots.hpp"
#include "koppel/solver/sweep.hpp"

#include <string>

namespace koppel::plot {

struct ViewOptions {
  SweepOptions range;  // radians (R drive) or length
  std::string title;
  std::string length_unit = "length";  // the file's length unit, for the charts' labels ("mm")
  bool IsValid(std::string* why) const;
};

// result.svg holds the HTML page. kPartial: the page shows what was computed, the message
// (also on the page) says where the solver stopped.
PlotResult ViewPage(const Mechanism& mechanism, const ViewOptions& options);

}  // namespace koppel::plot
