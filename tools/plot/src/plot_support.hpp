// What the plot builders share: display units of inputs and outputs, and runs of samples as
// curve subpaths.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/plot/figure.hpp"
#include "koppel/plot/sampled_run.hpp"

#include <string>
#include <vector>

namespace koppel::plot {

// Input as shown: degrees for an R drive, length for a P drive.
double ShownInput(const Mechanism& mechanism, double input);
std::string InputLabel(const Mechanism& mechanism, const std::string& length_unit);
// The input's name as shown: φ for phi, else as the file names it.
std::string InputName(const Mechanism& mechanism);
// "s' [length/rad]", "ψ [deg]", "ψ'' [rad/rad²]" for order k.
std::string DerivativeLabel(const Mechanism& mechanism, int output, const std::string& component, int k, const std::string& length_unit);
// Output value as shown: degrees for an angle output at order 0.
double ShownOutput(const Mechanism& mechanism, int output, int k, double value);

// One subpath per stretch of the run: (shown input, shown column value).
std::vector<std::vector<Eigen::Vector2d>> InputRuns(const Mechanism& mechanism, const SampledRun& run, int column, int output,
                                                    int k);
// Least and greatest y over the runs (for axis ranges); false when empty.
bool YRange(const std::vector<std::vector<Eigen::Vector2d>>& runs, double* low, double* high);

// A finite input range with a non-zero step and at most `max_samples` samples (a picture has a
// few thousand at most: more only bloats the file). *why says what is wrong.
bool RangeIsValid(const SweepOptions& range, int max_samples, std::string* why);

// Andrew's monotone chain: the convex hull, counter-clockwise, collinear points dropped (one
// point for points that all coincide, two for points on one line).
std::vector<Eigen::Vector2d> ConvexHull(std::vector<Eigen::Vector2d> points);

// The gaps and singular positions of the run marked on a panel (shaded and as rules).
void MarkGaps(const Mechanism& mechanism, const SampledRun& run, Panel& panel, bool label);

// A page template (koppel view, koppel edit) with {{NAME}} replaced in one pass (so a value never
// gets substituted into); an unknown NAME stays as it is.
std::string Fill(const std::string& page, const std::vector<std::pair<std::string, std::string>>& values);
// The one embedding of JSON in a page's <script> (koppel view, koppel edit): every <, > and &
// escaped (\u003c, \u003e, \u0026), so that neither "</script>" nor "<!--" (after which the HTML
// parser takes the rest of the page for script data, and the page's scripts never run) can
// appear whatever a name or title holds; U+2028 and U+2029 escaped too. The JSON means the same.
std::string ScriptSafe(const std::string& json);

// uPlot (script, style, licence), embedded by tools/view/view.cmake for the pages of koppel view
// and koppel edit.
namespace assets {
extern const char* const k_uplot_js;
extern const char* const k_uplot_css;
extern const char* const k_uplot_license;
}  // namespace assets

}  // namespace koppel::plot
