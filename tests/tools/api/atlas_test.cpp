// The atlas as the API builds and merges it (tools/api/src/atlas.cpp): the references are the
// atlas file's documented layout (koppel/synthesis/atlas_file.hpp: a 36-byte header, 132 bytes an
// entry, an 8-byte checksum per section of 4096 entries), a single build that the merged shards
// must equal byte for byte, and the shard rule k < n.
#include "koppel/api/atlas.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

using namespace koppel;

namespace atlas_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

constexpr std::uint64_t kHeaderBytes = 36, kEntryBytes = 132, kSectionChecksumBytes = 8;

AtlasBuildSpec Spec(std::uint64_t count, int shard, int shards) {
  AtlasBuildSpec spec;
  spec.count = count;
  spec.seed = 5;
  spec.shard = shard;
  spec.shards = shards;
  spec.threads = 2;
  return spec;
}

}  // namespace
}  // namespace atlas_test

TEST_CASE("AtlasBuildProblem refuses what cannot be built, and nothing else", "[api]") {
  using namespace atlas_test;
  CHECK(AtlasBuildProblem(Spec(300, 0, 1)).empty());
  CHECK(AtlasBuildProblem(Spec(300, 1, 2)).empty());
  CHECK_FALSE(AtlasBuildProblem(Spec(0, 0, 1)).empty());     // nothing to draw
  CHECK_FALSE(AtlasBuildProblem(Spec(300, 2, 2)).empty());   // shard k of n needs k < n
  CHECK_FALSE(AtlasBuildProblem(Spec(AtlasCurveLimit() + 1, 0, 1)).empty());
  CHECK(AtlasBuildFits(Spec(300, 0, 1)));
}

TEST_CASE("BuildAtlasImage: the file's documented size; shards merged give the single build's bytes", "[api]") {
  using namespace atlas_test;
  const AtlasImage whole = BuildAtlasImage(Spec(300, 0, 1));
  CHECK(whole.curves == 300);
  CHECK(whole.closed > 0);      // the space holds cranks that turn fully ...
  CHECK(whole.closed < 300);    // ... and rockers
  CHECK(whole.bytes.size() == kHeaderBytes + 300 * kEntryBytes + kSectionChecksumBytes);

  const test::TempDir dir;
  double progress = -1;
  const AtlasImage p0 = BuildAtlasImage(Spec(300, 0, 2), [&](double f) { progress = f; });
  const AtlasImage p1 = BuildAtlasImage(Spec(300, 1, 2));
  CHECK(p0.curves + p1.curves == 300);
  CHECK(progress == 1.0);  // the last report: all drawn
  const std::string a = dir.Write("p0.bin", p0.bytes), b = dir.Write("p1.bin", p1.bytes);
  const Expected<AtlasImage> merged = MergeAtlasFiles({b, a});
  REQUIRE(merged);
  CHECK(merged->bytes == whole.bytes);
  CHECK(merged->closed == whole.closed);

  const Expected<AtlasImage> twice = MergeAtlasFiles({a, a});
  REQUIRE_FALSE(twice);
  CHECK(twice.error().find("appears twice") != std::string::npos);
}
