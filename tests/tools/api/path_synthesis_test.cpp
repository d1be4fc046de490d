// Path synthesis as the API runs it (tools/api/src/path_synthesis.cpp): the points of a
// crank-rocker's coupler curve (tests/data/path-points.csv, not in the atlas) against an atlas the
// API builds. References: the best design's own mechanism file, read back and swept by the API,
// whose coupler curve must pass every point (distance to the traced polyline); the frame as the
// pivots' distance; the request rule of at least four points (path_synthesis.hpp).
#include "koppel/api/atlas.hpp"
#include "koppel/api/model.hpp"
#include "koppel/api/path_synthesis.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace koppel;

namespace path_synthesis_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// [points' unit] a point off the design's curve, traced at 0.05 deg: the chord's sag between two
// samples (~1e-7 here) and the fit's error (~1e-13 on these exact points), with margin
constexpr double kOnCurve = 1e-5;

double DistanceToPolyline(const Eigen::Vector2d& p, const std::vector<double>& xs, const std::vector<double>& ys) {
  double best = INFINITY;
  for (size_t i = 0; i + 1 < xs.size(); ++i) {
    const Eigen::Vector2d a(xs[i], ys[i]), b(xs[i + 1], ys[i + 1]);
    const double t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return best;
}

}  // namespace
}  // namespace path_synthesis_test

TEST_CASE("SynthesisePathFromAtlas: the best design's mechanism file passes every point", "[api][path]") {
  using namespace path_synthesis_test;
  const test::TempDir dir;
  AtlasBuildSpec atlas;
  atlas.count = 3000;
  atlas.seed = 9;
  const std::string atlas_path = dir.Write("atlas.bin", BuildAtlasImage(atlas).bytes);
  PathSpec spec;
  spec.points = ReadPathPointsFile(KOPPEL_TEST_DATA_DIR "/path-points.csv").points;
  spec.top = 2;
  REQUIRE(PathSpecProblem(spec).empty());
  const PathDesigns found = SynthesisePathFromAtlas(spec, atlas_path);
  INFO(found.message);
  REQUIRE(found.ok);
  CHECK(found.atlas_curves == 3000);
  REQUIRE(found.designs.size() == 2);
  // ranked by error, but exact fits (errors at roundoff, far below 1e-10 here) keep their atlas order
  CHECK((found.designs[0].error <= found.designs[1].error || found.designs[0].error < 1e-10));
  const PathDesign& best = found.designs[0];
  CHECK(best.frame == Approx((best.b0 - best.a0).norm()).epsilon(1e-12));

  const Model model = Model::Parse(PathDesignYaml(best, "path-1", "the best design"), "path-1.yaml");
  CHECK(model.mechanism().name == "path-1");
  const SweepSpan span = model.Span(std::nullopt, std::nullopt, 0.05);
  const SweepTable curve = model.Sweep(span.from, span.to, span.step, 0);
  REQUIRE(curve.status == AnalysisStatus::kComplete);
  const std::vector<double> xs = curve.Column("P_x"), ys = curve.Column("P_y");
  double worst = 0;
  for (const Eigen::Vector2d& p : spec.points) worst = std::max(worst, DistanceToPolyline(p, xs, ys));
  CHECK(worst < kOnCurve);
}

TEST_CASE("PathSpecProblem: fewer than four points are refused", "[api][path]") {
  PathSpec spec;
  spec.points = {{0, 0}, {1, 0}, {1, 1}};
  CHECK_FALSE(PathSpecProblem(spec).empty());
  spec.points.emplace_back(0, 1);
  CHECK(PathSpecProblem(spec).empty());
}
