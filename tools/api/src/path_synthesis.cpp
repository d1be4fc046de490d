#include "koppel/api/path_synthesis.hpp"

#include "design_units.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/catalog/path_points.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/atlas_file.hpp"
#include "koppel/synthesis/path_synthesis.hpp"

#include <memory>

namespace koppel {

namespace {

PathRequest PathRequestOf(const PathSpec& spec) {
  PathRequest request;
  request.points = spec.points;
  request.open = spec.open;
  request.top = spec.top;
  request.candidates = spec.candidates;
  request.threads = spec.threads;
  request.space = spec.space;
  request.timing = spec.timing;
  request.timing_step = spec.timing_step;
  request.starts = spec.starts;
  request.seed = spec.seed;
  return request;
}

PathDesign PathDesignOf(const PathLinkage& l) {
  PathDesign d;
  d.error = l.error;
  d.sse = l.sse;
  d.phi_1 = l.phi_1;
  d.inputs = l.inputs;
  d.mu_min = l.mu_min;
  d.a0 = l.geometry.a0;
  d.b0 = l.geometry.b0;
  d.crank = l.crank;
  d.coupler = l.coupler;
  d.rocker = l.rocker;
  d.frame = l.frame;
  d.coupler_point = l.coupler_point;
  d.grashof = ToString(l.grashof);
  d.cognate_of = l.cognate_of;
  d.atlas_seed = l.source.seed;
  d.atlas_index = l.source.index;
  d.fit = l.fit;
  d.mechanism = l.mechanism;
  return d;
}

}  // namespace

TimedPathPoints ReadPathPointsFile(const std::string& path) { return ReadTimedPathPoints(path); }

std::string PathSpecProblem(const PathSpec& spec) {
  std::string why;
  return PathRequestOf(spec).IsValid(&why) ? std::string() : why;
}

PathDesigns SynthesisePathFromAtlas(const PathSpec& spec, const std::string& atlas_path) {
  PathDesigns out;
  const PathRequest request = PathRequestOf(spec);
  if (request.Timed() && !atlas_path.empty()) {
    out.invalid_request = true;
    out.message = "an atlas is not read when the timing is prescribed (a phi column or a timing step): the search is global; leave the atlas out";
    return out;
  }
  std::unique_ptr<AtlasIndex> atlas;
  if (!atlas_path.empty()) atlas = std::make_unique<AtlasIndex>(ReadAtlasFile(atlas_path));
  const PathResult result = atlas ? SynthesisePath(*atlas, request) : SynthesisePathGlobally(request);
  out.starts = result.starts;
  out.admitted_starts = result.admitted_starts;
  out.failed_reanalysis = result.failed_reanalysis;
  out.outside_space = result.outside_space;
  out.ok = result.ok();
  out.invalid_request = result.status == PathStatus::kInvalidRequest;
  out.message = result.message;
  out.duplicates = result.duplicates;
  out.atlas_curves = atlas ? atlas->entries().size() : 0;
  for (const PathLinkage& l : result.linkages) out.designs.push_back(PathDesignOf(l));
  return out;
}

std::string PathDesignYaml(const PathDesign& design, const std::string& name, const std::string& comment, const std::string& units) {
  Mechanism m = design.mechanism;
  m.name = name;
  const double from = RadToDeg(m.hint.input);
  const bool turns = design.grashof == ToString(GrashofType::kCrankRocker) || design.grashof == ToString(GrashofType::kDoubleCrank);
  const double to = design.inputs.empty() || turns ? from + 360 : RadToDeg(design.inputs.back());
  return WriteMechanismYaml(m, comment, {from, to, 1}, {}, UnitsFor(UnitsOf(units)));
}

}  // namespace koppel
