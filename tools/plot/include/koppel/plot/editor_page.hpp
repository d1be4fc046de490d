// The page of `koppel edit`: one self-contained HTML file (no network, no server) whose solver is
// koppel's own kernel compiled to WebAssembly (tools/edit). It draws the scheme, lets the user
// drag pivots and joint points and move parameter sliders (re-solving on the branch), traces the
// coupler curves, charts the transfer functions and the transmission angle, marks the dead
// centres and singular points, and exports YAML, SVG and PNG; window.koppel scripts it.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/plot/plots.hpp"

namespace koppel::plot {

// True when this build has the page (em++ was found when koppel was built).
bool EditorPageAvailable();

// result.svg holds the HTML page of `model`; kFailed when this build has no page (the message
// says why).
PlotResult EditorPage(const Model& model);

}  // namespace koppel::plot
