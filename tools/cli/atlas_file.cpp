#include "atlas_file.hpp"

#include "common.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace koppel::cli {

std::vector<AtlasEntry> ReadAtlasFile(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) {
    Complain(path + ": cannot read the atlas (" + ec.message() + ")");
    throw Exit{kExitBadInput};
  }
  // a size no atlas has is refused before it is read
  if (size > AtlasFileSize(kMaxAtlasCurves)) {
    Complain(path + ": larger than any atlas koppel writes");
    throw Exit{kExitBadInput};
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) {
    Complain(path + ": cannot read the atlas");
    throw Exit{kExitBadInput};
  }
  Expected<std::vector<AtlasEntry>> entries = ParseAtlas(bytes);
  if (!entries) {
    Complain(path + ": " + entries.error());
    throw Exit{kExitBadInput};
  }
  return std::move(*entries);
}

}  // namespace koppel::cli
