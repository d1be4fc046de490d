// The one file reader (core/src/input_file.cpp): every input is read within its limit whatever
// it is (a device, a sparse file, a pipe), a directory is refused, and every file read is
// registered so that no output of the same run replaces it, by any name (output_file.hpp).
#include "koppel/core/input_file.hpp"
#include "koppel/core/output_file.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <sys/stat.h>
#include <unistd.h>

namespace koppel::input_file_test {
namespace {

// The FileError's message, or "no error".
std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const io::FileError& e) {
    CHECK(e.kind() == io::FileError::Kind::kRefused);
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("a text input is read whole up to kMaxInputBytes and refused one byte beyond", "[io][limits]") {
  test::TempDir dir;
  const std::string at_limit = dir.Write("at-limit.txt", std::string(kMaxInputBytes, 'x'));
  CHECK(io::ReadInputFile(at_limit).size() == kMaxInputBytes);
  const std::string beyond = dir.Write("beyond.txt", std::string(kMaxInputBytes + 1, 'x'));
  CHECK_THAT(ErrorOf([&] { io::ReadInputFile(beyond); }), Catch::Contains(beyond) && Catch::Contains("kMaxInputBytes"));
}

TEST_CASE("a device or a sparse file of 20 GB is refused without reading gigabytes", "[io][limits]") {
  // /dev/zero has no size: the reader stops one byte past the limit
  CHECK_THAT(ErrorOf([] { io::ReadInputFile("/dev/zero"); }), Catch::Contains("/dev/zero") && Catch::Contains("larger than the input limit"));
  // a sparse regular file is refused by its size before a byte is read
  test::TempDir dir;
  const std::string sparse = (dir.path() / "sparse.csv").string();
  const int fd = ::open(sparse.c_str(), O_WRONLY | O_CREAT, 0600);
  REQUIRE(fd >= 0);
  REQUIRE(::ftruncate(fd, 20LL << 30) == 0);
  ::close(fd);
  const auto start = std::chrono::steady_clock::now();
  CHECK_THAT(ErrorOf([&] { io::ReadInputFile(sparse); }), Catch::Contains("larger than the input limit"));
  // reading 20 GB of zeros takes many seconds; refusing by the size, microseconds
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
}

TEST_CASE("a directory and a missing file are refused with the path", "[io]") {
  test::TempDir dir;
  CHECK_THAT(ErrorOf([&] { io::ReadInputFile(dir.path().string()); }), Catch::Contains("it is a directory"));
  CHECK_THAT(ErrorOf([&] { io::ReadInputFile((dir.path() / "missing.yaml").string()); }),
             Catch::Contains("missing.yaml: cannot open file: No such file or directory"));
}

TEST_CASE("InputFile reads in parts and knows a regular file's size", "[io]") {
  test::TempDir dir;
  const std::string path = dir.Write("parts.bin", "0123456789");
  io::InputFile file(path);
  REQUIRE(file.RegularFileSize());
  CHECK(*file.RegularFileSize() == 10);
  CHECK(file.Read(4) == "0123");
  CHECK(file.ReadRest(6) == "456789");  // six bytes left: at the limit
  CHECK(file.Read(1).empty());
  io::InputFile again(path);
  (void)again.Read(3);
  CHECK_THAT(ErrorOf([&] { again.ReadRest(6, "kTest"); }), Catch::Contains("kTest"));
}

TEST_CASE("a file read is an input: claiming it as an output is refused by any name", "[io][registry]") {
  test::TempDir dir;
  const std::string input = dir.Write("mech.yaml", "name: x\n");
  (void)io::ReadInputFile(input);
  const std::string hard_link = (dir.path() / "hard.yaml").string();
  std::filesystem::create_hard_link(input, hard_link);
  for (const std::string& name : {input, hard_link, (dir.path() / "." / "mech.yaml").string()}) {
    INFO(name);
    CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile(name, "-o"); }), Catch::Contains("it is an input file of this command"));
  }
  // a symbolic link to it is refused for being a link
  const std::string symlink = (dir.path() / "link.yaml").string();
  std::filesystem::create_symlink(input, symlink);
  CHECK_THAT(ErrorOf([&] { io::ClaimOutputFile(symlink, "-o"); }), Catch::Contains("symbolic link"));
  // and the write itself refuses it too (a file inside an output directory is checked only there)
  CHECK_THAT(ErrorOf([&] { io::WriteFileAtomically(hard_link, "text"); }), Catch::Contains("input file"));
  CHECK(test::ReadText(input) == "name: x\n");
}

TEST_CASE("a file claimed as an output is refused as an input, also through a link", "[io][registry]") {
  test::TempDir dir;
  const std::string target = dir.Write("spec.yaml", "function: x\n");
  io::ClaimOutputFile(target, "--error-curve");
  const std::string symlink = (dir.path() / "link.yaml").string();
  std::filesystem::create_symlink(target, symlink);
  for (const std::string& name : {target, symlink}) {
    INFO(name);
    CHECK_THAT(ErrorOf([&] { io::ReadInputFile(name); }), Catch::Contains("also named as the output of --error-curve"));
  }
}

}  // namespace koppel::input_file_test
