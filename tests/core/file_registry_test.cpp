// The run's register of input and output files (file_registry.hpp), on real files of a temporary
// directory: the reference is the header's definition (a file is known by device and inode, so a
// hard link is the same file; an output is also known by its absolute path; an entry whose path
// no longer leads to its inode is dropped). The register is global to the process: every case
// uses files of its own, which no other test has noted.
#include "file_registry.hpp"

#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <string>

namespace koppel::file_registry_test {
namespace {

using io::detail::FileIdentity;
using io::detail::IsInput;
using io::detail::NoteInput;
using io::detail::NoteOutput;

FileIdentity IdentityOf(const std::string& path) {
  struct stat info {};
  REQUIRE(::stat(path.c_str(), &info) == 0);
  return {info.st_dev, info.st_ino};
}

}  // namespace

TEST_CASE("an input is known by its identity once noted, and noted once", "[file_registry]") {
  test::TempDir dir;
  const std::string path = dir.Write("in.yaml", "x");
  const FileIdentity file = IdentityOf(path);
  CHECK_FALSE(IsInput(file));
  CHECK(NoteInput(file, path) == "");
  CHECK(IsInput(file));
  // read again (the API reloads): still no output claims it
  CHECK(NoteInput(file, path) == "");
  CHECK(IsInput(file));
  // a hard link is the same file
  const std::string link = (dir.path() / "link.yaml").string();
  std::filesystem::create_hard_link(path, link);
  CHECK(IdentityOf(link) == file);
  CHECK(IsInput(IdentityOf(link)));
  // another file is not an input
  CHECK_FALSE(IsInput(IdentityOf(dir.Write("other.yaml", "y"))));
}

TEST_CASE("an input whose path no longer leads to it is forgotten", "[file_registry]") {
  test::TempDir dir;
  const std::string path = dir.Write("gone.yaml", "x");
  const FileIdentity file = IdentityOf(path);
  CHECK(NoteInput(file, path) == "");
  std::filesystem::remove(path);
  // the stat of the noted path fails: the entry is stale and dropped
  CHECK_FALSE(IsInput(file));
}

TEST_CASE("an input that is a claimed output gets the claiming flag", "[file_registry]") {
  test::TempDir dir;
  const std::string path = dir.Write("out.csv", "");
  const FileIdentity file = IdentityOf(path);
  CHECK(NoteOutput(&file, path, "--output") == "");
  // read through a hard link: the same inode, the output's flag
  const std::string link = (dir.path() / "alias.csv").string();
  std::filesystem::create_hard_link(path, link);
  CHECK(NoteInput(IdentityOf(link), link) == "--output");
  CHECK_FALSE(IsInput(file));  // refused, not recorded
}

TEST_CASE("an output target is claimed once, by identity or by absolute path", "[file_registry]") {
  test::TempDir dir;
  // an existing file: a second claim through a hard link names the first flag
  const std::string path = dir.Write("plot.svg", "");
  const FileIdentity file = IdentityOf(path);
  CHECK(NoteOutput(&file, path, "--svg") == "");
  const std::string link = (dir.path() / "same.svg").string();
  std::filesystem::create_hard_link(path, link);
  const FileIdentity linked = IdentityOf(link);
  CHECK(NoteOutput(&linked, link, "--csv") == "--svg");
  // a file that does not exist yet: known by its path only
  const std::string fresh = (dir.path() / "new.csv").string();
  CHECK(NoteOutput(nullptr, fresh, "--csv") == "");
  CHECK(NoteOutput(nullptr, fresh, "--report") == "--csv");
  // another path is another target
  CHECK(NoteOutput(nullptr, (dir.path() / "new2.csv").string(), "--report") == "");
}

TEST_CASE("an output claim whose file was removed no longer claims that identity", "[file_registry]") {
  test::TempDir dir;
  const std::string path = dir.Write("a.csv", "");
  const FileIdentity file = IdentityOf(path);
  CHECK(NoteOutput(&file, path, "--output") == "");
  std::filesystem::remove(path);
  // another path with that identity (a reused inode) is not the claimed output; the stale claim
  // is dropped altogether, so its path may be claimed again
  const std::string other = (dir.path() / "b.csv").string();
  CHECK(NoteInput(file, other) == "");
  CHECK(NoteOutput(nullptr, path, "--svg") == "");
}

}  // namespace koppel::file_registry_test
