// Output files (tools/cli/output_file.cpp, core/output_file.hpp, README "Output files"): -o never
// writes through a symbolic link, never replaces a FIFO, a directory, a device or any file the
// command reads (every repro of issue 23, item 2), -o DIR naming a file is refused before any
// work (item 3), a read-only target is refused as `>` would refuse it and a closed pipe ends
// koppel by SIGPIPE (item 13); a link planted where the old code put its temporary file is never
// followed, a failed write leaves nothing behind, and a failed write to standard output exits 1.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <csignal>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

namespace koppel::output_file_test {
namespace {

namespace fs = std::filesystem;

// Runs a shell command line (it names the executable itself); exit code and stderr.
test::RunResult Shell(const std::string& command) {
  test::TempDir dir;
  const std::string err = (dir.path() / "err").string();
  const int status = std::system(("( " + command + " ) 2> " + err + " < /dev/null").c_str());
  test::RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = test::ReadText(err);
  return r;
}

std::string Koppel() { return KOPPEL_EXECUTABLE; }
std::string Entry() { return test::CatalogEntryPath("slider-crank-offset"); }
std::string Analyze(const std::string& out) { return "analyze " + Entry() + " --step 30 -o '" + out + "'"; }

// What the folder holds, apart from `except`.
std::vector<std::string> Listing(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& item : fs::directory_iterator(folder)) names.push_back(item.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("-o writes a new file and replaces a regular file atomically", "[cli][output]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "table.csv").string();
  const test::RunResult first = test::RunKoppel(Analyze(out));
  REQUIRE(first.exit_code == 0);
  const std::string table = test::ReadText(out);
  CHECK(table.rfind("phi,s,", 0) == 0);
  CHECK(table == test::RunKoppel("analyze " + Entry() + " --step 30").out);  // the same as stdout
  ::chmod(out.c_str(), 0640);
  REQUIRE(test::RunKoppel(Analyze(out)).exit_code == 0);
  struct stat info {};
  REQUIRE(::stat(out.c_str(), &info) == 0);
  CHECK((info.st_mode & 0777) == 0640);  // a replaced file keeps its permissions
  CHECK(Listing(dir.path()) == std::vector<std::string>{"table.csv"});  // no temporary left
}

TEST_CASE("-o refuses a symbolic link and leaves its target alone", "[cli][output]") {
  test::TempDir dir;
  const std::string victim = dir.Write("victim.txt", "precious\n");
  const std::string link = (dir.path() / "out.csv").string();
  fs::create_symlink(victim, link);
  const test::RunResult r = test::RunKoppel(Analyze(link));
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("symbolic link"));
  CHECK(test::ReadText(victim) == "precious\n");
  CHECK(fs::is_symlink(link));
}

TEST_CASE("-o refuses a FIFO, a directory and a device", "[cli][output]") {
  test::TempDir dir;
  const std::string fifo = (dir.path() / "pipe").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const test::RunResult f = test::RunKoppel(Analyze(fifo));  // would block forever if opened
  CHECK(f.exit_code == 2);
  CHECK_THAT(f.err, Catch::Contains("FIFO"));
  CHECK(fs::is_fifo(fifo));

  const test::RunResult d = test::RunKoppel(Analyze(dir.path().string()));
  CHECK(d.exit_code == 2);
  CHECK_THAT(d.err, Catch::Contains("directory"));

  const test::RunResult n = test::RunKoppel(Analyze("/dev/null"));
  CHECK(n.exit_code == 2);
  CHECK_THAT(n.err, Catch::Contains("device"));
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("-o refuses the mechanism file being read, also through another name", "[cli][output]") {
  test::TempDir dir;
  const std::string input = dir.Write("mech.yaml", test::ReadText(Entry()));
  const std::string hard_link = (dir.path() / "same.yaml").string();
  fs::create_hard_link(input, hard_link);
  for (const std::string& out : {input, hard_link, (dir.path() / "." / "mech.yaml").string()}) {
    const test::RunResult r = test::RunKoppel("analyze " + input + " --step 30 -o " + out);
    INFO(out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("input file"));
  }
  CHECK(test::ReadText(input) == test::ReadText(Entry()));

  // synth fit reads a problem and the mechanism it names: --yaml must not replace either
  const std::string mechanism = dir.Write("mzc.yaml", test::ReadText(test::CatalogEntryPath("mzc-crank-rocker")));
  std::string problem = test::ReadText(std::string(KOPPEL_TEST_DATA_DIR) + "/fit-mzc-precision-points.yaml");
  problem.replace(problem.find("../../catalog/entries/mzc-crank-rocker.yaml"), 43, "mzc.yaml");
  const std::string problem_path = dir.Write("problem.yaml", problem);
  for (const std::string& out : {mechanism, problem_path}) {
    const test::RunResult r = test::RunKoppel("synth fit " + problem_path + " --quiet --yaml " + out);
    INFO(out << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("input file"));
  }
  CHECK(test::ReadText(mechanism) == test::ReadText(test::CatalogEntryPath("mzc-crank-rocker")));
}

TEST_CASE("-o into a folder where no file can be made exits 2 and names the folder", "[cli][output]") {
  // /proc takes no new files, not even from root (CI runs as root, where chmod 0555 would not stop it)
  const test::RunResult proc = test::RunKoppel(Analyze("/proc/koppel-table.csv"));
  CHECK(proc.exit_code == 2);
  CHECK_THAT(proc.err, Catch::Contains("cannot create a file in '/proc'"));
  CHECK_FALSE(fs::exists("/proc/koppel-table.csv"));

  test::TempDir dir;
  const fs::path read_only = dir.path() / "read-only";
  fs::create_directory(read_only);
  ::chmod(read_only.c_str(), 0555);
  const test::RunResult r = test::RunKoppel(Analyze((read_only / "t.csv").string()));
  if (::geteuid() != 0) {  // root writes into a 0555 folder: only then the rule does not apply
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("cannot create a file in"));
    CHECK(Listing(read_only).empty());
  }
  ::chmod(read_only.c_str(), 0755);

  const test::RunResult missing = test::RunKoppel(Analyze((dir.path() / "no-such-folder" / "t.csv").string()));
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.err, Catch::Contains("No such file or directory"));
}

TEST_CASE("a link planted at the old temporary name is never followed", "[cli][output]") {
  test::TempDir dir;
  const std::string victim = dir.Write("victim.txt", "precious\n");
  const fs::path out = dir.path() / "out.csv";
  // `exec` keeps the shell's pid, so $$ is the pid koppel runs with: the old code wrote
  // out.csv.tmp.<pid> through this link into the victim
  const std::string command = "cd '" + dir.path().string() + "' && ln -s victim.txt out.csv.tmp.$$ && ln -s victim.txt out.csv.tmp && exec " +
                              Koppel() + " " + Analyze(out.string());
  const test::RunResult r = Shell("sh -c \"" + command + "\"");
  CHECK(r.exit_code == 0);
  CHECK(test::ReadText(victim) == "precious\n");
  CHECK(test::ReadText(out.string()).rfind("phi,s,", 0) == 0);
  const std::vector<std::string> names = Listing(dir.path());
  CHECK(names.size() == 4);  // out.csv, victim.txt and the two planted links: nothing else
}

TEST_CASE("a write that fails leaves neither a partial file nor a temporary behind", "[cli][output]") {
  test::TempDir dir;
  const fs::path out = dir.path() / "big.csv";
  // a 1 KiB file-size limit makes write(2) fail with EFBIG (the signal ignored, as `trap` does)
  const test::RunResult r =
      Shell("sh -c \"trap '' XFSZ; ulimit -f 1; exec " + Koppel() + " analyze " + Entry() + " --step 1 -o '" + out.string() + "'\"");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("cannot write '" + out.string() + "'"));
  CHECK(Listing(dir.path()).empty());
}

TEST_CASE("a failed write to standard output exits 1 with a message", "[cli][output]") {
  const test::RunResult full = Shell(Koppel() + " analyze " + Entry() + " > /dev/full");
  CHECK(full.exit_code == 1);
  CHECK_THAT(full.err, Catch::Contains("cannot write to standard output: No space left on device"));
  // a table that fits into stdio's buffer fails only when it is flushed at the end
  const test::RunResult small = Shell(Koppel() + " analyze " + Entry() + " --from 0 --to 0 > /dev/full");
  CHECK(small.exit_code == 1);
  CHECK_THAT(small.err, Catch::Contains("cannot write to standard output"));
  // a closed stdout
  const test::RunResult closed = Shell(Koppel() + " --version >&-");
  CHECK(closed.exit_code == 1);
  CHECK_THAT(closed.err, Catch::Contains("cannot write to standard output"));
}

TEST_CASE("every command refuses an output that is one of its inputs, before any work (issue 23, item 2)", "[cli][output]") {
  test::TempDir dir;
  const std::string d = dir.path().string();
  const std::string spec = dir.Write("f.yaml", test::ReadText(test::TestDataPath("function-log10.yaml")));
  const std::string poses = dir.Write("P.yaml", test::ReadText(test::TestDataPath("motion-four-poses.yaml")));
  const std::string points = dir.Write("pts.csv", test::ReadText(test::TestDataPath("path-points.csv")));
  const std::string motor = dir.Write("m.csv", "rpm,Nm\n0,40\n2900,0\n3100,-5\n");
  REQUIRE(test::RunKoppel("atlas build --count 300 --quiet -o " + d + "/a.bin").exit_code == 0);
  REQUIRE(test::RunKoppel("synth chart slider-crank --phi0 110:130:10 --quiet -o " + d + "/chart.csv").exit_code == 0);
  const std::string atlas = test::ReadText(d + "/a.bin"), chart = test::ReadText(d + "/chart.csv");
  const std::string hard_link = d + "/same.yaml";
  fs::create_hard_link(spec, hard_link);
  const std::vector<std::string> commands = {
      "synth function " + spec + " --error-curve " + spec,
      "synth function " + spec + " -o " + spec,
      "synth function " + spec + " --output-file " + hard_link,  // the same file by another name
      "synth motion " + poses + " --output-file " + poses,
      "synth motion " + poses + " --curves " + poses,
      "synth path " + points + " --atlas " + d + "/a.bin --output-file " + d + "/a.bin",
      "synth path " + points + " --atlas " + d + "/a.bin --output-file " + points,
      "simulate " + test::TestDataPath("slider-crank-loads.yaml") + " --motor " + motor + " --t 0:1 -o " + motor,
      "plot " + d + "/chart.csv -o " + d + "/chart.csv",
  };
  for (const std::string& command : commands) {
    const test::RunResult r = test::RunKoppel(command);
    INFO(command << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("input file") && Catch::Contains("never writes over"));
    CHECK(r.out.empty());
    CHECK(r.err.find("koppel synth") == std::string::npos);  // no summary: nothing was computed
  }
  CHECK(test::ReadText(spec) == test::ReadText(test::TestDataPath("function-log10.yaml")));
  CHECK(test::ReadText(poses) == test::ReadText(test::TestDataPath("motion-four-poses.yaml")));
  CHECK(test::ReadText(points) == test::ReadText(test::TestDataPath("path-points.csv")));
  CHECK(test::ReadText(motor) == "rpm,Nm\n0,40\n2900,0\n3100,-5\n");
  CHECK(test::ReadText(d + "/a.bin") == atlas);
  CHECK(test::ReadText(d + "/chart.csv") == chart);
  // two outputs naming one file
  const test::RunResult both = test::RunKoppel("synth function " + spec + " -o " + d + "/x.yaml --error-curve " + d + "/./x.yaml");
  CHECK(both.exit_code == 2);
  CHECK_THAT(both.err, Catch::Contains("also the output of"));
}

TEST_CASE("-o DIR naming a file or a device is refused before any work (issue 23, item 3)", "[cli][output]") {
  test::TempDir dir;
  const std::string somefile = dir.Write("somefile", "mine\n");
  REQUIRE(test::RunKoppel("atlas build --count 300 --quiet -o " + (dir.path() / "a.bin").string()).exit_code == 0);
  const std::vector<std::string> commands = {
      "synth motion " + test::TestDataPath("motion-five-poses.yaml") + " -o " + somefile,
      "synth motion " + test::TestDataPath("motion-five-poses.yaml") + " -o /dev/null",
      "synth path " + test::TestDataPath("path-points.csv") + " --atlas " + (dir.path() / "a.bin").string() + " -o " + somefile,
      "synth path " + test::TestDataPath("path-points.csv") + " --atlas " + (dir.path() / "a.bin").string() + " -o " + somefile + "/sub",
      "cognates " + test::CatalogEntryPath("parallel-crank") + " --point K -o " + somefile,
      "synth mzc --lambda 1 --cognate-dir " + somefile,
  };
  for (const std::string& command : commands) {
    const test::RunResult r = test::RunKoppel(command);
    INFO(command << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("will not write"));
    CHECK(r.err.find("internal error") == std::string::npos);
    CHECK(r.err.find("koppel synth") == std::string::npos);  // refused before the work's summary
  }
  CHECK(test::ReadText(somefile) == "mine\n");
}

TEST_CASE("a read-only target is refused as > would refuse it (issue 23, item 13)", "[cli][output]") {
  test::TempDir dir;
  ::chmod(dir.path().c_str(), 0777);  // anyone may make files here: only the target's own mode decides
  const std::string target = dir.Write("ro.csv", "kept\n");
  ::chmod(target.c_str(), 0444);
  // root writes any file with `>`, so as root the rule is shown as the user nobody (setpriv, util-linux)
  const std::string as_user = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const test::RunResult r = Shell(as_user + Koppel() + " " + Analyze(target));
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("you may not write to it (mode 0444"));
  CHECK(test::ReadText(target) == "kept\n");
  // the shell agrees: `>` fails on it too
  CHECK(Shell(as_user + "sh -c 'echo x > " + target + "'").exit_code != 0);
}

TEST_CASE("a reader that closes the pipe early ends koppel by SIGPIPE, quietly (issue 23, item 13)", "[cli][output]") {
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  ::close(fds[0]);  // the reader is gone before koppel writes
  const pid_t child = ::fork();
  if (child == 0) {
    ::dup2(fds[1], 1);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 2);
    ::signal(SIGPIPE, SIG_DFL);  // as a shell starts it
    ::execl(KOPPEL_EXECUTABLE, "koppel", "analyze", Entry().c_str(), "--step", "30", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  int status = 0;
  ::waitpid(child, &status, 0);
  // README "Exit codes": the shell reports 128 + 13 = 141, like any filter in `| head`
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGPIPE);
}

}  // namespace koppel::output_file_test
