// A file in the system temp directory that removes itself: for tests that must read or write
// real files (catalog directories, mutated entries, CLI output).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace koppel::test {

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  // Writes `text` to `name` inside the directory and returns the full path.
  std::string Write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

std::string ReadText(const std::string& path);
std::string CatalogEntryPath(const std::string& id);  // catalog/entries/<id>.yaml
std::string TestDataPath(const std::string& name);    // tests/data/<name>

}  // namespace koppel::test
