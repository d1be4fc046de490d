// Output claims and atomic writes (core/src/output_file.cpp, README "Output files"): what a
// claim refuses before any work (links, directories, FIFOs, devices, a target named twice, a
// file the user could not write with `>`, a folder where no file can be made, -o DIR naming a
// file), and that a write replaces a file whole, keeps its mode and leaves no temporary file.
#include "koppel/core/output_file.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace koppel::output_file_test {
namespace {

namespace fs = std::filesystem;

std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const io::FileError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<std::string> Listing(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& item : fs::directory_iterator(folder)) names.push_back(item.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs `action` in a child process as the user `nobody` (uid and gid 65534), as root must to
// meet a permission it would otherwise override; the child's exit code: 0 when `action`
// returned true.
int AsNobody(const std::function<bool()>& action) {
  const pid_t child = ::fork();
  if (child == 0) {
    const bool dropped = ::setgid(65534) == 0 && ::setuid(65534) == 0;
    ::_exit(!dropped ? 3 : action() ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("a claim refuses a link, a directory, a FIFO and a device", "[io][output]") {
  test::TempDir dir;
  const std::string victim = dir.Write("victim.txt", "precious\n");
  const std::string link = (dir.path() / "link.csv").string();
  fs::create_symlink(victim, link);
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile(link, "-o"); }), Catch::Contains("will not write '" + link + "': it is a symbolic link"));
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile(dir.path().string(), "-o"); }), Catch::Contains("it is a directory"));
  const std::string fifo = (dir.path() / "pipe").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile(fifo, "-o"); }), Catch::Contains("FIFO"));
  CHECK_THAT(ErrorOf([] { io::ClaimOutputFile("/dev/null", "-o"); }), Catch::Contains("device"));
  // standard output is always there
  CHECK(ErrorOf([] { io::ClaimOutputFile("-", "-o"); }) == "no error");
  CHECK(ErrorOf([] { io::ClaimOutputFile("", "-o"); }) == "no error");
  CHECK(Listing(dir.path()) == std::vector<std::string>{"link.csv", "pipe", "victim.txt"});  // the probes are gone
}

TEST_CASE("one target named by two outputs is refused", "[io][output]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "both.csv").string();  // not there yet: compared by path
  io::ClaimOutputFile(out, "-o");
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile((dir.path() / "." / "both.csv").string(), "--error-curve"); }),
             Catch::Contains("it is also the output of -o"));
}

TEST_CASE("a claim refuses a folder where no file can be made", "[io][output]") {
  // /proc takes no new files, not even from root
  CHECK_THAT(ErrorOf([] { io::ClaimOutputFile("/proc/koppel.csv", "-o"); }), Catch::Contains("cannot create a file in '/proc'"));
  test::TempDir dir;
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile((dir.path() / "missing" / "t.csv").string(), "-o"); }),
             Catch::Contains("No such file or directory"));
}

TEST_CASE("a file the user could not write with > is refused, not replaced through the rename", "[io][output]") {
  test::TempDir dir;
  ::chmod(dir.path().c_str(), 0777);  // the folder is writable to everyone: only the file's mode decides
  const std::string read_only = dir.Write("ro.csv", "kept\n");
  ::chmod(read_only.c_str(), 0444);
  const std::string expected = "you may not write to it (mode 0444";
  if (::geteuid() != 0) {
    CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile(read_only, "-o"); }), Catch::Contains(expected));
    CHECK_THAT(ErrorOf([&] { io::WriteFileAtomically(read_only, "new\n"); }), Catch::Contains(expected));
  } else {
    // root may write any file with `>`: as `nobody`, a 0444 file of root's is refused both ways
    CHECK(AsNobody([&] { return ErrorOf([&] { io::ClaimOutputFile(read_only, "-o"); }).find(expected) != std::string::npos; }) == 0);
    CHECK(AsNobody([&] { return ErrorOf([&] { io::WriteFileAtomically(read_only, "new\n"); }).find(expected) != std::string::npos; }) == 0);
    // and a 0644 file owned by root is another user's: `nobody` may not write it either
    ::chmod(read_only.c_str(), 0644);
    CHECK(AsNobody([&] { return ErrorOf([&] { io::ClaimOutputFile(read_only, "-o"); }).find("owner uid 0") != std::string::npos; }) == 0);
  }
  CHECK(test::ReadText(read_only) == "kept\n");
}

TEST_CASE("a directory claim refuses a file, a device and a path through a file", "[io][output]") {
  test::TempDir dir;
  const std::string file = dir.Write("somefile", "");
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputDirectory(file, "-o"); }), Catch::Contains("it is a file, and -o names a directory"));
  CHECK_THAT(ErrorOf([] { io::ClaimOutputDirectory("/dev/null", "-o"); }), Catch::Contains("it is a device"));
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputDirectory(file + "/sub", "-o"); }), Catch::Contains("cannot use it as the directory"));
  CHECK_THAT(ErrorOf([] { io::ClaimOutputDirectory("/proc/koppel-designs", "-o"); }), Catch::Contains("cannot create a file in '/proc'"));
  // a directory that does not exist yet, or one that does, passes; nothing is made by the claim
  const std::string fresh = (dir.path() / "designs" / "four-bars").string();
  CHECK(ErrorOf([&] { io::ClaimOutputDirectory(fresh, "-o"); }) == "no error");
  CHECK_FALSE(fs::exists(fresh));
  CHECK(ErrorOf([&] { io::ClaimOutputDirectory(dir.path().string(), "-o"); }) == "no error");
  io::MakeOutputDirectory(fresh);
  CHECK(fs::is_directory(fresh));
  CHECK_THAT(ErrorOf([&] { io::MakeOutputDirectory(file); }), Catch::Contains("cannot make the directory"));
}

TEST_CASE("an atomic write makes a new file, replaces one keeping its mode, and leaves no temporary", "[io][output]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "table.csv").string();
  io::WriteFileAtomically(out, "a,b\n1,2\n");
  CHECK(test::ReadText(out) == "a,b\n1,2\n");
  ::chmod(out.c_str(), 0640);
  io::WriteFileAtomically(out, "a,b\n3,4\n");
  CHECK(test::ReadText(out) == "a,b\n3,4\n");
  struct stat info {};
  REQUIRE(::stat(out.c_str(), &info) == 0);
  CHECK((info.st_mode & 0777) == 0640);
  CHECK(Listing(dir.path()) == std::vector<std::string>{"table.csv"});
}

}  // namespace koppel::output_file_test

namespace koppel::output_file_test {

TEST_CASE("a write in pieces replaces the file only at Commit; abandoned, it leaves the old file and no temporary", "[io][output]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "table.csv").string();
  io::WriteFileAtomically(out, "old\n");
  {
    io::AtomicFileWriter file(out);
    file.Write("a,b\n");
    file.Write("1,2\n");
    CHECK(test::ReadText(out) == "old\n");  // the target is untouched until Commit
    CHECK(Listing(dir.path()).size() == 2);  // the target and the temporary
    file.Commit();
  }
  CHECK(test::ReadText(out) == "a,b\n1,2\n");
  CHECK(Listing(dir.path()) == std::vector<std::string>{"table.csv"});
  // an exception between the pieces: the writer is destroyed without Commit
  try {
    io::AtomicFileWriter file(out);
    file.Write("half a table");
    throw std::runtime_error("the sweep failed");
  } catch (const std::runtime_error&) {
  }
  CHECK(test::ReadText(out) == "a,b\n1,2\n");
  CHECK(Listing(dir.path()) == std::vector<std::string>{"table.csv"});
  // a write after Commit is a programming error, not a silent no-op
  io::AtomicFileWriter file(out);
  file.Commit();
  CHECK_THROWS_AS(file.Write("late"), std::logic_error);
  CHECK(test::ReadText(out).empty());
}

TEST_CASE("a write in pieces refuses what a whole write refuses, before any temporary is made", "[io][output]") {
  test::TempDir dir;
  const fs::path link = dir.path() / "link.csv";
  fs::create_symlink(dir.path() / "elsewhere.csv", link);
  CHECK_THAT(ErrorOf([&] { io::AtomicFileWriter file(link.string()); }), Catch::Contains("symbolic link"));
  CHECK(Listing(dir.path()) == std::vector<std::string>{"link.csv"});
}

}  // namespace koppel::output_file_test
