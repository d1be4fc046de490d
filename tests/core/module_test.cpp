// LoadModule and FileHoldingCode (core/src/module.cpp): the modules of this build tree are found
// from the test program's folder upwards and carry this build's version; a module that does not
// exist is an exception naming its file and where it was looked for, never a crash.
#include "koppel/core/module.hpp"
#include "koppel/core/version.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace koppel::module_test {

TEST_CASE("FileHoldingCode names this test program (its real path, not argv[0])", "[module]") {
  char self[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  REQUIRE(n > 0);
  // the reference: the kernel's own link to the running program
  CHECK(FileHoldingCode(reinterpret_cast<const void*>(&FileHoldingCode)) == std::filesystem::canonical(self).string());
}

TEST_CASE("LoadModule finds the Ceres module of this build, once, with this build's version", "[module]") {
  const ModuleTable& ceres = LoadModule("ceres");
  CHECK(std::string(ceres.version) == KOPPEL_VERSION_STRING);
  CHECK(&LoadModule("ceres") == &ceres);  // loaded once, kept
  CHECK(std::string(LoadModule("gif").version) == KOPPEL_VERSION_STRING);
}

TEST_CASE("LoadModule of a module that is not there throws, naming the file and the folders", "[module]") {
  try {
    LoadModule("no-such-module");
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK_THAT(what, Catch::Contains("libkoppel_no-such-module.so") && Catch::Contains("could not be loaded") &&
                         Catch::Contains("not found in") && Catch::Contains("/koppel"));
  }
}

}  // namespace koppel::module_test
