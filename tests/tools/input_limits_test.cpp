// Every file every command reads is read within the input limit (issue 23, item 5): a device
// (/dev/zero), a symbolic link to one, a sparse file of 20 GB and a motor curve of 2.1 GB end in
// exit 2 naming kMaxInputBytes, at once and without an "internal error" (the old readers read
// gigabytes and ended in std::bad_alloc). Reference: README "Limits".
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace koppel::input_limits_test {
namespace {

// A file of `bytes` zeros that takes no disk space.
std::string Sparse(const test::TempDir& dir, const std::string& name, long long bytes) {
  const std::string path = (dir.path() / name).string();
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(::ftruncate(fd, bytes) == 0);
  ::close(fd);
  return path;
}

}  // namespace

TEST_CASE("every reader stops at the input limit, whatever the file is", "[cli][limits]") {
  test::TempDir dir;
  const std::string zero_link = (dir.path() / "z.csv").string();
  std::filesystem::create_symlink("/dev/zero", zero_link);
  const std::string sparse = Sparse(dir, "sparse.csv", 20LL << 30);
  const std::string big_motor = Sparse(dir, "BIG.csv", 2'100'000'000LL);
  const std::string mechanism = test::TestDataPath("slider-crank-loads.yaml");
  const std::vector<std::string> commands = {
      "synth motion /dev/zero",
      "synth function /dev/zero",
      "plot " + zero_link,
      "plot " + sparse,
      "simulate " + mechanism + " --motor " + big_motor + " --t 0:1",
      "simulate " + mechanism + " --motor /dev/zero --t 0:1",
      "synth path " + zero_link + " --atlas /dev/zero",
      "synth path " + sparse + " --atlas /dev/zero",
      "analyze " + sparse,
      "synth fit /dev/zero",
      "catalog find --like /dev/zero",
  };
  for (const std::string& command : commands) {
    const auto start = std::chrono::steady_clock::now();
    const test::RunResult r = test::RunKoppel(command);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(command << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("kMaxInputBytes"));
    CHECK(r.err.find("internal error") == std::string::npos);
    // 4 MB read at most: well under a second; the old readers spent many seconds on gigabytes
    CHECK(seconds < 5);
  }
}

TEST_CASE("an atlas is read as far as its checksummed header promises, not to the end of /dev/zero", "[cli][limits]") {
  test::TempDir dir;
  const test::RunResult zero = test::RunKoppel("atlas merge /dev/zero -o " + (dir.path() / "m.bin").string());
  CHECK(zero.exit_code == 2);
  CHECK_THAT(zero.err, Catch::Contains("not a koppel atlas"));
  const test::RunResult sparse = test::RunKoppel("atlas merge " + Sparse(dir, "a.bin", 20LL << 30) + " -o " + (dir.path() / "m.bin").string());
  CHECK(sparse.exit_code == 2);
  CHECK(sparse.err.find("internal error") == std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.path() / "m.bin"));
}

}  // namespace koppel::input_limits_test
