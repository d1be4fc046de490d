// Temporary files removed on signals (core/src/temporary_files.cpp): in a child process that
// registers a file and is then sent SIGINT, SIGTERM or SIGHUP, the file is gone and the child died
// by that signal (the parent's waitpid says so); a forgotten file stays; a signal inherited as
// ignored stays ignored.
#include "koppel/core/temporary_files.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace koppel::temporary_files_test {
namespace {

struct ChildEnd {
  bool signalled = false;
  int signal_number = 0, exit_code = -1;
};

// Forks a child that installs the handlers, registers `path` (or registers and forgets it), and
// sends itself `signal_number` after `ignore` was set to SIG_IGN beforehand (0: none).
ChildEnd RunChild(const std::string& path, int signal_number, bool forget, int ignore = 0) {
  const pid_t child = ::fork();
  if (child == 0) {
    if (ignore != 0) ::signal(ignore, SIG_IGN);
    io::RemoveTemporaryFilesOnSignals();
    const int slot = io::RegisterTemporaryFile(path.c_str());
    if (slot < 0) ::_exit(3);
    if (forget) io::ForgetTemporaryFile(slot);
    ::kill(::getpid(), signal_number);
    ::_exit(0);  // reached only when the signal did not end the process
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ChildEnd end;
  end.signalled = WIFSIGNALED(status);
  end.signal_number = end.signalled ? WTERMSIG(status) : 0;
  end.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return end;
}

}  // namespace

TEST_CASE("SIGINT, SIGTERM and SIGHUP remove the registered files, then end the process by the signal", "[io][signals]") {
  test::TempDir dir;
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    INFO("signal " << signal_number);
    const std::string path = dir.Write(".table.csv.koppel-abc123", "half a table");
    const ChildEnd end = RunChild(path, signal_number, false);
    CHECK(end.signalled);
    CHECK(end.signal_number == signal_number);
    CHECK_FALSE(std::filesystem::exists(path));
  }
}

TEST_CASE("a forgotten temporary file stays, and an ignored signal stays ignored", "[io][signals]") {
  test::TempDir dir;
  const std::string renamed = dir.Write("table.csv", "a whole table");  // forgotten: already renamed into place
  const ChildEnd forgotten = RunChild(renamed, SIGTERM, true);
  CHECK(forgotten.signalled);
  CHECK(std::filesystem::exists(renamed));
  // nohup: SIGHUP was ignored before koppel started, so it neither ends the child nor removes the file
  const std::string held = dir.Write(".t.koppel-xyz", "half");
  const ChildEnd ignored = RunChild(held, SIGHUP, false, SIGHUP);
  CHECK_FALSE(ignored.signalled);
  CHECK(ignored.exit_code == 0);
  CHECK(std::filesystem::exists(held));
}

TEST_CASE("the table holds kMaxTemporaryFiles paths and refuses what it cannot hold", "[io][signals]") {
  std::vector<int> slots;
  for (int i = 0; i < io::kMaxTemporaryFiles; ++i) slots.push_back(io::RegisterTemporaryFile("/nonexistent/koppel-test"));
  CHECK(std::count(slots.begin(), slots.end(), -1) == 0);
  CHECK(io::RegisterTemporaryFile("/nonexistent/one-more") == -1);
  for (int slot : slots) io::ForgetTemporaryFile(slot);
  CHECK(io::RegisterTemporaryFile(std::string(io::kMaxTemporaryPath, 'x').c_str()) == -1);
  const int again = io::RegisterTemporaryFile("/nonexistent/koppel-test");
  CHECK(again >= 0);
  io::ForgetTemporaryFile(again);
}

}  // namespace koppel::temporary_files_test
