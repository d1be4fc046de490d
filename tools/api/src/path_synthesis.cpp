#include "koppel/api/path_synthesis.hpp"

#include "design_units.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/catalog/path_points.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/atlas_file.hpp"
#include "koppel/synthesis/path_synthesis.hpp"

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
  return request;
}

PathDesign PathDesignOf(const PathLinkage& l) {
  PathDesign d;
  d.error = l.error;
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

std::vector<Eigen::Vector2d> ReadPathPointsFile(const std::string& path) { return ReadPathPoints(path); }

std::string PathSpecProblem(const PathSpec& spec) {
  std::string why;
  return PathRequestOf(spec).IsValid(&why) ? std::string() : why;
}

PathDesigns SynthesisePathFromAtlas(const PathSpec& spec, const std::string& atlas_path) {
  const AtlasIndex atlas(ReadAtlasFile(atlas_path));
  const PathResult result = SynthesisePath(atlas, PathRequestOf(spec));
  PathDesigns out;
  out.ok = result.ok();
  out.invalid_request = result.status == PathStatus::kInvalidRequest;
  out.message = result.message;
  out.duplicates = result.duplicates;
  out.atlas_curves = atlas.entries().size();
  for (const PathLinkage& l : result.linkages) out.designs.push_back(PathDesignOf(l));
  return out;
}

std::string PathDesignYaml(const PathDesign& design, const std::string& name, const std::string& comment, const std::string& units) {
  Mechanism m = design.mechanism;
  m.name = name;
  const double from = RadToDeg(m.hint.input);
  return WriteMechanismYaml(m, comment, {from, from + 360, 1}, {}, UnitsFor(UnitsOf(units)));
}

}  // namespace koppel
