// `koppel atlas build|merge` end to end: shards merged in any order are the atlas one build writes
// (byte for byte), a shard given twice and malformed arguments or files are refused (exit 2).
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

namespace koppel {

TEST_CASE("atlas build --shard and merge give the atlas one build writes", "[cli][atlas]") {
  test::TempDir dir;
  const std::string d = dir.path().string();
  REQUIRE(test::RunKoppel("atlas build --count 2500 --seed 9 -o " + d + "/whole.bin").exit_code == 0);
  for (int k = 0; k < 3; ++k)
    REQUIRE(test::RunKoppel("atlas build --count 2500 --seed 9 --shard " + std::to_string(k) + "/3 -o " + d + "/p" + std::to_string(k) + ".bin").exit_code == 0);
  const test::RunResult merged = test::RunKoppel("atlas merge " + d + "/p2.bin " + d + "/p0.bin " + d + "/p1.bin -o " + d + "/merged.bin");
  REQUIRE(merged.exit_code == 0);
  CHECK(test::ReadText(d + "/merged.bin") == test::ReadText(d + "/whole.bin"));
  const test::RunResult twice = test::RunKoppel("atlas merge " + d + "/p0.bin " + d + "/p0.bin -o " + d + "/bad.bin");
  CHECK(twice.exit_code == 2);
  CHECK_THAT(twice.err, Catch::Contains("appears twice"));
}

TEST_CASE("atlas refuses bad arguments and files", "[cli][atlas]") {
  test::TempDir dir;
  const std::string d = dir.path().string();
  CHECK(test::RunKoppel("atlas build --count 0 -o " + d + "/a.bin").exit_code == 2);
  CHECK(test::RunKoppel("atlas build --count -5 -o " + d + "/a.bin").exit_code == 2);
  CHECK(test::RunKoppel("atlas build --count 10 --shard 2/2 -o " + d + "/a.bin").exit_code == 2);
  CHECK(test::RunKoppel("atlas build --count 10 --shard 1 -o " + d + "/a.bin").exit_code == 2);
  CHECK(test::RunKoppel("atlas build --count 2000000000 -o " + d + "/a.bin").exit_code == 2);
  const test::RunResult notatlas = test::RunKoppel("atlas merge " + dir.Write("x.yaml", "name: x\n") + " -o " + d + "/m.bin");
  CHECK(notatlas.exit_code == 2);
  CHECK_THAT(notatlas.err, Catch::Contains("not a koppel atlas"));
  CHECK_FALSE(std::filesystem::exists(d + "/m.bin"));
}

}  // namespace koppel
