// `koppel atlas build|merge` end to end: shards merged in any order are the atlas one build writes
// (byte for byte), a shard given twice and malformed arguments or files are refused (exit 2), a
// damaged atlas is refused by every command that reads it (issue 23, item 9), and SIGINT or
// SIGTERM during a build leaves no temporary file and ends koppel by the signal (item 8).
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

namespace koppel::atlas_command_test {
namespace {

std::vector<std::string> Listing(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& item : std::filesystem::directory_iterator(folder)) names.push_back(item.path().filename().string());
  return names;
}

// Starts `koppel atlas build --count COUNT -o FOLDER/int.bin` and sends it `signal_number` as
// soon as its temporary file (.int.bin.koppel-XXXXXX) appears in the folder (inotify), that is
// while the atlas is being written. The wait status; `hit` says whether the signal was sent while
// the temporary file existed (false: the build finished first).
int SignalDuringWrite(const std::filesystem::path& folder, int signal_number, bool* hit) {
  const int watch = ::inotify_init1(IN_CLOEXEC);
  REQUIRE(watch >= 0);
  REQUIRE(::inotify_add_watch(watch, folder.c_str(), IN_CREATE) >= 0);
  const std::string out = (folder / "int.bin").string();
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execl(KOPPEL_EXECUTABLE, "koppel", "atlas", "build", "--count", "60000", "--quiet", "-o", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  *hit = false;
  alignas(inotify_event) char buffer[4096];
  pollfd wait_for{watch, POLLIN, 0};
  // the build takes seconds; a minute is a machine far slower than any CI
  while (!*hit && ::poll(&wait_for, 1, 60'000) > 0) {
    const ssize_t n = ::read(watch, buffer, sizeof buffer);
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      if (event->len > 0 && std::string(event->name).rfind(".int.bin.koppel-", 0) == 0) {
        ::kill(child, signal_number);
        *hit = true;
        break;
      }
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
  int status = 0;
  if (!*hit) ::kill(child, SIGKILL);
  ::waitpid(child, &status, 0);
  ::close(watch);
  return status;
}

}  // namespace

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

TEST_CASE("a damaged atlas is refused by synth path and atlas merge (issue 23, item 9)", "[cli][atlas]") {
  test::TempDir dir;
  const std::string d = dir.path().string();
  REQUIRE(test::RunKoppel("atlas build --count 300 --quiet -o " + d + "/a.bin").exit_code == 0);
  const std::string bytes = test::ReadText(d + "/a.bin");
  // one bit in an entry (curve 100's crank length), one in the header's count
  for (const std::size_t byte : {std::size_t{36 + 100 * 132 + 20}, std::size_t{20}}) {
    std::string damaged = bytes;
    damaged[byte] = static_cast<char>(damaged[byte] ^ 0x10);
    const std::string path = dir.Write("damaged.bin", damaged);
    const test::RunResult path_synthesis = test::RunKoppel("synth path " + test::TestDataPath("path-points.csv") + " --atlas " + path);
    INFO(byte << "\n" << path_synthesis.err);
    CHECK(path_synthesis.exit_code == 2);
    CHECK_THAT(path_synthesis.err, Catch::Contains("checksum") && Catch::Contains("damaged"));
    CHECK(path_synthesis.out.empty());
    const test::RunResult merge = test::RunKoppel("atlas merge " + path + " " + d + "/a.bin -o " + d + "/merged.bin");
    CHECK(merge.exit_code == 2);
    CHECK_THAT(merge.err, Catch::Contains("checksum"));
    CHECK_FALSE(std::filesystem::exists(d + "/merged.bin"));
  }
}

TEST_CASE("SIGINT or SIGTERM while atlas build writes leaves no temporary file (issue 23, item 8)", "[cli][atlas][signals]") {
  for (int signal_number : {SIGTERM, SIGINT}) {
    test::TempDir dir;
    bool hit = false;
    int status = 0;
    // the build may finish writing before the signal arrives: try again, a few times at most
    for (int attempt = 0; attempt < 5 && !hit; ++attempt) {
      std::filesystem::remove(dir.path() / "int.bin");
      status = SignalDuringWrite(dir.path(), signal_number, &hit);
      // renamed into place before the signal came: the window was missed
      if (hit && (!WIFSIGNALED(status) || std::filesystem::exists(dir.path() / "int.bin"))) hit = false;
    }
    INFO("signal " << signal_number);
    REQUIRE(hit);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal_number);
    for (const std::string& name : Listing(dir.path())) CHECK(name.find(".koppel-") == std::string::npos);
  }
}

}  // namespace koppel::atlas_command_test
