// koppel export run as a user would: the command writes a DXF (read back in detail by
// tests/tools/export/dxf_readback_test.py with ezdxf), the --help example runs as written, bad
// input ends with exit 2 and a message naming the flag, a pose beyond the drive's limit with 1.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

namespace koppel::export_command_test {
namespace {

std::string Mzc() { return test::CatalogEntryPath("mzc-crank-rocker"); }

}  // namespace

TEST_CASE("export --dxf: the issue's command", "[cli][export]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "m.dxf").string();
  const test::RunResult r = test::RunKoppel("export " + Mzc() + " --dxf --at 30 --trace K -o " + out);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  const std::string dxf = test::ReadText(out);
  CHECK(dxf.rfind("999\ndxflib", 0) == 0);  // dxflib's banner comment, then the sections
  CHECK(dxf.find("$INSUNITS") != std::string::npos);
  CHECK(dxf.find("curve-K") != std::string::npos);
  CHECK(dxf.substr(dxf.size() - 4) == "EOF\n");
}

TEST_CASE("export --help: the example runs as written", "[cli][export]") {
  const test::RunResult help = test::RunKoppel("export --help");
  REQUIRE(help.exit_code == 0);
  CHECK_THAT(help.out, Catch::Contains("$INSUNITS"));
  CHECK_THAT(help.out, Catch::Contains("length unit"));
  const std::string example = "koppel export catalog/entries/mzc-crank-rocker.yaml --dxf --at 30 --trace K -o m.dxf";
  REQUIRE_THAT(help.out, Catch::Contains(example));
  test::TempDir dir;
  const std::string out = (dir.path() / "m.dxf").string();
  CHECK(test::RunKoppel("export " + Mzc() + " --dxf --at 30 --trace K -o " + out).exit_code == 0);
}

TEST_CASE("export: bad input and unreachable poses", "[cli][export]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "bad.dxf").string();
  struct Case {
    const char* flags;
    int exit_code;
    const char* message;
  };
  for (const Case& c : {Case{"--dxf --trace Q", 2, "no point 'Q'"},
                        Case{"--dxf --pin 0.5 --plate 0.3", 2, "--pin/--plate: the pin diameter must be smaller than the plate width"},
                        Case{"--dxf --pin 0", 2, "must be positive"},
                        Case{"--dxf --pin 1/0", 2, "--pin"},
                        Case{"--at 30", 2, "--dxf"}}) {
    INFO(c.flags);
    const test::RunResult r = test::RunKoppel("export " + Mzc() + " " + c.flags + " -o " + out);
    CHECK(r.exit_code == c.exit_code);
    CHECK_THAT(r.err, Catch::Contains(c.message));
    CHECK_FALSE(std::filesystem::exists(out));
  }
  // the double rocker swings 49.2 .. 97.2 deg: 120 deg is beyond its limit, no file, exit 1
  const test::RunResult beyond = test::RunKoppel("export " + test::CatalogEntryPath("double-rocker") + " --dxf --at 120 -o " + out);
  CHECK(beyond.exit_code == 1);
  CHECK_THAT(beyond.err, Catch::Contains("cannot reach"));
  CHECK_FALSE(std::filesystem::exists(out));
  // the output is one of the inputs: refused
  CHECK(test::RunKoppel("export " + Mzc() + " --dxf -o " + Mzc()).exit_code == 2);
}

}  // namespace koppel::export_command_test
