#include "file_registry.hpp"

#include <algorithm>
#include <mutex>
#include <sys/stat.h>
#include <vector>

namespace koppel::io::detail {
namespace {

struct Input {
  FileIdentity file;
  std::string path;
};

struct Claim {
  bool exists = false;
  FileIdentity file;
  std::string path, flag;
};

struct Registry {
  std::mutex mutex;
  std::vector<Input> inputs;
  std::vector<Claim> outputs;
};

Registry& Files() {
  static Registry registry;
  return registry;
}

// Whether `path` still leads to `file`.
bool StillThere(const std::string& path, FileIdentity file) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && FileIdentity{info.st_dev, info.st_ino} == file;
}

// The inputs that are `file`, the stale ones dropped first.
bool HasInput(Registry& r, FileIdentity file) {
  std::erase_if(r.inputs, [&](const Input& known) { return known.file == file && !StillThere(known.path, file); });
  return std::any_of(r.inputs.begin(), r.inputs.end(), [&](const Input& known) { return known.file == file; });
}

}  // namespace

std::string NoteInput(FileIdentity file, const std::string& path) {
  Registry& r = Files();
  const std::lock_guard<std::mutex> lock(r.mutex);
  std::erase_if(r.outputs, [&](const Claim& c) { return c.exists && c.file == file && !StillThere(c.path, file); });
  for (const Claim& c : r.outputs) {
    if (c.exists && c.file == file) return c.flag;
  }
  // a file read again (the API reloads a mechanism) is recorded once
  if (!HasInput(r, file)) r.inputs.push_back({file, path});
  return "";
}

bool IsInput(FileIdentity file) {
  Registry& r = Files();
  const std::lock_guard<std::mutex> lock(r.mutex);
  return HasInput(r, file);
}

std::string NoteOutput(const FileIdentity* existing, const std::string& absolute_path, const std::string& flag) {
  Registry& r = Files();
  const std::lock_guard<std::mutex> lock(r.mutex);
  if (existing) std::erase_if(r.outputs, [&](const Claim& c) { return c.exists && c.file == *existing && !StillThere(c.path, *existing); });
  for (const Claim& c : r.outputs) {
    if ((existing && c.exists && c.file == *existing) || c.path == absolute_path) return c.flag;
  }
  r.outputs.push_back(Claim{existing != nullptr, existing ? *existing : FileIdentity{}, absolute_path, flag});
  return "";
}

}  // namespace koppel::io::detail
