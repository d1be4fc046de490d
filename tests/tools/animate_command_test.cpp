// koppel animate run as a user would: the command writes a 36-frame GIF (read back in
// detail by tests/tools/export/gif_readback_test.py with Pillow), the --help example runs as
// written, bad input ends with exit 2 and a message naming the flag and the limit.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

namespace koppel::animate_command_test {
namespace {

std::string Mzc() { return test::CatalogEntryPath("mzc-crank-rocker"); }

}  // namespace

TEST_CASE("animate: the issue's command", "[cli][animate]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "m.gif").string();
  const test::RunResult r = test::RunKoppel("animate " + Mzc() + " --frames 36 -o " + out);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  const std::string gif = test::ReadText(out);
  CHECK(gif.rfind("GIF89a", 0) == 0);
  // the logical screen: 640 x 480, little-endian 16-bit after the signature
  CHECK(static_cast<unsigned char>(gif[6]) + 256 * static_cast<unsigned char>(gif[7]) == 640);
  CHECK(static_cast<unsigned char>(gif[8]) + 256 * static_cast<unsigned char>(gif[9]) == 480);
  CHECK(gif.back() == ';');  // the trailer
}

TEST_CASE("animate --help: the example runs as written", "[cli][animate]") {
  const test::RunResult help = test::RunKoppel("animate --help");
  REQUIRE(help.exit_code == 0);
  CHECK_THAT(help.out, Catch::Contains("1/100 s"));
  REQUIRE_THAT(help.out, Catch::Contains("koppel animate catalog/entries/mzc-crank-rocker.yaml --frames 36 -o m.gif"));
}

TEST_CASE("animate: bad input", "[cli][animate]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "bad.gif").string();
  struct Case {
    const char* flags;
    const char* message;
  };
  for (const Case& c : {Case{"--frames 0", "--frames: the number of frames must be 1 .. 3600 (kMaxAnimationFrames)"},
                        Case{"--frames 2.5", "--frames"},
                        Case{"--size 0x0", "16 .. 4096 px (kMaxAnimationSide)"},
                        Case{"--size 100000x100000", "kMaxAnimationSide"},
                        Case{"--size 4096x4096 --frames 3600", "kMaxAnimationPixels"},
                        Case{"--size 640", "--size: expected WIDTHxHEIGHT"},
                        Case{"--size 640x-1", "kMaxAnimationSide"},
                        Case{"--size 640x48z", "--size: expected WIDTHxHEIGHT"},
                        Case{"--fps 0", "frame rate"},
                        Case{"--fps 60", "frame rate"},
                        Case{"--trace nowhere", "no point 'nowhere'"},
                        Case{"--pin 1 --plate 1", "--pin/--plate"}}) {
    INFO(c.flags);
    const test::RunResult r = test::RunKoppel("animate " + Mzc() + " " + c.flags + " -o " + out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(c.message));
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

}  // namespace koppel::animate_command_test
