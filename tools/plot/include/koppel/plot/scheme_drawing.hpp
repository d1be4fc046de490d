// `koppel draw` as one call: the kinematic scheme (scheme.hpp) of a koppel::Model at one input,
// solved on the sweep's branch, with the coupler curve of a point over the sweep and the poses at
// the dead centres of an output (seed 000 "Bild 3"), named in the caption. Inputs in the API's
// units (koppel/api/model.hpp): degrees for an R drive, length for a P drive.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/plot/plots.hpp"  // PlotStatus

#include <optional>
#include <string>
#include <vector>

namespace koppel::plot {

// The most samples of the sweep behind a drawing: enough for any curve on a page.
inline constexpr double kMaxSchemeSamples = 20001;

struct SchemeRequest {
  std::optional<double> at;              // the pose drawn [deg | length]; unset: the assembly hint's input
  std::optional<double> from, to, step;  // the sweep [deg | length]; unset: the file's (Model::Span)
  AtBranchPoint at_branch_point = AtBranchPoint::kContinue;
  std::optional<PointRef> trace;         // draw this point's curve over the sweep
  std::string trace_name;                // as the user named it, for the legend
  bool dead_centres = false;             // overlay the dead-centre poses of `output`
  std::string output;                    // a scalar output ("": the first)
  // false with the reason for a step of 0 or a sweep of more than kMaxSchemeSamples samples
  bool IsValid(const Model& model, std::string* why) const;
};

struct SchemeDrawing {
  // failed: nothing drawn (the sweep computed nothing, the pose cannot be reached), `message`
  // says why; partial: drawn, `problems` say what is missing (a gap of the sweep, a dead centre
  // that could not be solved or found)
  PlotStatus status = PlotStatus::kComplete;
  std::string message;
  std::vector<std::string> problems;
  std::string svg;  // empty when failed
};

// InputError for a request that is not valid, or an output that is not a scalar one.
SchemeDrawing DrawSchemeOf(const Model& model, const SchemeRequest& request);

}  // namespace koppel::plot
