// The atlas: its descriptor is invariant under the motions it claims (a rotated, scaled, moved,
// restarted and reversed copy of a curve reads the same), its draws are deterministic and
// independent of threads and shards (compared as written by atlas_file.hpp), and its curves close
// the loop they were drawn for. References: the loop closure |A - A0| = a, |B - A| = b,
// |B - B0| = c evaluated here, and Grashof's rule (a crank exists iff s + l <= p + q with the
// shortest link at the frame or the crank) for which draws turn fully.
#include "koppel/synthesis/atlas.hpp"
#include "koppel/synthesis/atlas_file.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>

namespace koppel::atlas_test {
namespace {

// Two descriptors of one curve sampled differently agree to this: the 64 points of equal arc
// length start elsewhere on a restarted copy, and the aliased harmonics (largest at the turning
// ends of a rocker's arc) differ by up to ~2e-3; neighbouring curves of a 10^4 atlas lie
// 2e-2 .. 2e-1 apart.
constexpr double kSameCurve = 5e-3;

double Distance(const CurveDescriptor& a, const CurveDescriptor& b) {
  double d = 0;
  for (int i = 0; i < kAtlasFeatures; ++i) d = std::max(d, std::abs(a.features[i] - b.features[i]));
  return d;
}

// The same closed path read in another frame: turned, scaled, moved, started elsewhere.
std::vector<Eigen::Vector2d> Moved(const std::vector<Eigen::Vector2d>& path, double turn, double scale, Eigen::Vector2d shift, int start) {
  std::vector<Eigen::Vector2d> out;
  for (size_t i = 0; i < path.size(); ++i) {
    const Eigen::Vector2d& p = path[(i + start) % path.size()];
    out.push_back(shift + scale * Eigen::Vector2d(std::cos(turn) * p.x() - std::sin(turn) * p.y(), std::sin(turn) * p.x() + std::cos(turn) * p.y()));
  }
  return out;
}

}  // namespace

TEST_CASE("the descriptor reads a moved, scaled, restarted and reversed curve the same", "[atlas]") {
  int closed = 0, open = 0;
  for (std::uint64_t i = 0; i < 40; ++i) {
    const AtlasEntry e = DrawAtlasEntry(7, i);
    AtlasCurve curve;
    REQUIRE(TraceAtlasCurve(e, 4000, &curve));
    CurveDescriptor d, moved, reversed;
    REQUIRE(DescribeCurve(curve.coupler_point, &d));
    REQUIRE(DescribeCurve(Moved(curve.coupler_point, 1.1 * i, 0.3 + 0.2 * i, {5, -2}, 37 * static_cast<int>(i)), &moved));
    std::vector<Eigen::Vector2d> back = curve.coupler_point;
    std::reverse(back.begin(), back.end());
    REQUIRE(DescribeCurve(back, &reversed));
    INFO("entry " << i << (e.closed ? " closed" : " open"));
    // the ambiguity (turn and shift by pi) may fall either way for a restarted copy
    CHECK(std::min(Distance(d, moved), Distance(d, OtherBranchOfAmbiguity(moved))) <= kSameCurve);
    CHECK(std::min(Distance(d, reversed), Distance(d, OtherBranchOfAmbiguity(reversed))) <= kSameCurve);
    // and the stored float descriptor is this one
    for (int k = 0; k < kAtlasFeatures; ++k) CHECK(std::abs(e.descriptor[k] - d.features[k]) <= kSameCurve);
    (e.closed ? closed : open)++;
  }
  CHECK(closed > 0);
  CHECK(open > 0);
  // the ambiguity is an involution
  CurveDescriptor d;
  AtlasCurve curve;
  REQUIRE(TraceAtlasCurve(DrawAtlasEntry(7, 0), 256, &curve));
  REQUIRE(DescribeCurve(curve.coupler_point, &d));
  CHECK(Distance(d, OtherBranchOfAmbiguity(OtherBranchOfAmbiguity(d))) == 0);
}

TEST_CASE("atlas draws lie in the documented space, close their loop, and turn fully exactly when Grashof says so", "[atlas]") {
  for (std::uint64_t i = 0; i < 2000; ++i) {
    const AtlasEntry e = DrawAtlasEntry(11, i);
    for (double l : {e.crank, e.coupler, e.rocker}) CHECK((l >= 0.2 - 1e-12 && l <= 5 + 1e-12));
    CHECK((e.p >= -1 && e.p <= 2 && e.q >= -1.5 && e.q <= 1.5));
    // Grashof: the crank turns fully iff s + l <= p + q and the shortest link is the crank or the frame
    const double links[] = {1.0, e.crank, e.coupler, e.rocker};
    const double s = *std::min_element(links, links + 4), l = *std::max_element(links, links + 4);
    const bool crank = s + l <= 1 + e.crank + e.coupler + e.rocker - s - l && (s == e.crank || s == 1.0);
    INFO("a " << e.crank << " b " << e.coupler << " c " << e.rocker);
    CHECK(static_cast<bool>(e.closed) == crank);
    AtlasCurve curve;
    REQUIRE(TraceAtlasCurve(e, 16, &curve));
    for (int k = 0; k < 16; ++k) {
      CHECK(std::abs(curve.a[k].norm() - e.crank) <= 1e-12);
      CHECK(std::abs((curve.b[k] - curve.a[k]).norm() - e.coupler) <= 1e-12);
      CHECK(std::abs((curve.b[k] - Eigen::Vector2d(1, 0)).norm() - e.rocker) <= 1e-9);
    }
  }
}

TEST_CASE("atlas builds do not depend on threads or shards; merge refuses a shard given twice", "[atlas]") {
  AtlasBuildOptions o;
  o.count = 3001;
  o.seed = 5;
  o.threads = 1;
  const std::string whole = SerialiseAtlas(BuildAtlas(o));
  o.threads = 2;
  CHECK(SerialiseAtlas(BuildAtlas(o)) == whole);
  std::vector<std::vector<AtlasEntry>> parts;
  o.shards = 3;
  for (o.shard = 2; o.shard >= 0; --o.shard) parts.push_back(BuildAtlas(o));
  CHECK(parts[0].size() + parts[1].size() + parts[2].size() == 3001);
  const Expected<std::vector<AtlasEntry>> merged = MergeAtlases(parts);
  REQUIRE(merged);
  CHECK(SerialiseAtlas(*merged) == whole);
  parts.push_back(parts[1]);
  const Expected<std::vector<AtlasEntry>> twice = MergeAtlases(parts);
  CHECK_FALSE(twice);
  CHECK_THAT(twice.error(), Catch::Contains("appears twice"));
  std::string error;
  o.shard = 3;
  CHECK_FALSE(o.IsValid(&error));
}

// Issue 23 item 7: --count 100000000 ended in std::bad_alloc after the work began. The estimate is
// the entries plus the file image (AtlasFileSize), checked before anything is allocated.
TEST_CASE("an atlas build that cannot fit in memory is refused up front with the figures", "[atlas]") {
  AtlasBuildOptions o;
  o.count = 100'000'000;
  const std::uint64_t bytes = AtlasBuildBytes(o);
  CHECK(bytes == o.count * sizeof(AtlasEntry) + AtlasFileSize(o.count));
  const Outcome refused = CheckAtlasBuildMemory(o, 4'000'000'000ULL, "ulimit -v");
  REQUIRE_FALSE(refused);
  CHECK_THAT(refused.error(), Catch::Contains("4 GB") && Catch::Contains("ulimit -v") && Catch::Contains("--shard"));
  CHECK(CheckAtlasBuildMemory(o, bytes, "physical memory"));  // exactly enough is enough
  // a shard needs its share only
  o.shards = 8;
  CHECK(AtlasBuildBytes(o) < bytes / 7);
}

TEST_CASE("an atlas build reports its progress, rising to 1, from the calling thread", "[atlas]") {
  AtlasBuildOptions o;
  o.count = 20'000;
  o.threads = 2;
  std::vector<double> reported;
  const std::vector<AtlasEntry> entries = BuildAtlas(o, [&](double f) { reported.push_back(f); });
  CHECK(entries.size() == 20'000);
  REQUIRE(reported.size() >= 2);
  CHECK(std::is_sorted(reported.begin(), reported.end()));
  CHECK(reported.front() >= 0.0);
  CHECK(reported.back() == 1.0);
}

}  // namespace koppel::atlas_test
