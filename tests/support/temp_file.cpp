#include "support/temp_file.hpp"

#include <random>
#include <sstream>

namespace koppel::test {

TempDir::TempDir() {
  std::random_device device;
  path_ = std::filesystem::temp_directory_path() / ("koppel-test-" + std::to_string(device()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::string TempDir::Write(const std::string& name, const std::string& text) const {
  const std::filesystem::path file = path_ / name;
  std::ofstream(file, std::ios::binary) << text;
  return file.string();
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string CatalogEntryPath(const std::string& id) { return std::string(KOPPEL_CATALOG_DIR) + "/" + id + ".yaml"; }

std::string TestDataPath(const std::string& name) { return std::string(KOPPEL_TEST_DATA_DIR) + "/" + name; }

}  // namespace koppel::test
