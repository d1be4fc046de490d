#include "koppel/core/module.hpp"

#include "koppel/core/version.hpp"

#include <dlfcn.h>

#include <cerrno>
#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

// Defined (weak) only in programs that link koppel's installed static libraries through its CMake
// package: that tree's prefix.
extern "C" __attribute__((weak)) const char koppel_installed_prefix[];

namespace koppel {

std::string FileHoldingCode(const void* address) {
  namespace fs = std::filesystem;
  Dl_info info{};
  if (dladdr(address, &info) == 0 || !info.dli_fname) return {};
  // glibc names the main program by argv[0] (a bare name when found on PATH): its real path is
  // /proc/self/exe
  std::string file = info.dli_fname;
  if (file.empty() || file == program_invocation_name || file.find('/') == std::string::npos) file = "/proc/self/exe";
  std::error_code ec;
  const fs::path canonical = fs::canonical(file, ec);
  return ec ? std::string() : canonical.string();
}

std::vector<std::string> InstallRoots() {
  namespace fs = std::filesystem;
  std::vector<std::string> roots;
  const std::string here = FileHoldingCode(reinterpret_cast<const void*>(&InstallRoots));
  if (!here.empty()) {
    fs::path up = fs::path(here).parent_path();
    for (int level = 0; level < 6 && !up.empty(); ++level, up = up.parent_path()) {
      roots.push_back(up.string());
      if (up == up.root_path()) break;
    }
  }
  if (&koppel_installed_prefix != nullptr && koppel_installed_prefix[0] != '\0') roots.emplace_back(koppel_installed_prefix);
  return roots;
}

namespace {

// The folders to look in, nearest first (see LoadModule).
std::vector<std::filesystem::path> ModuleFolders() {
  std::vector<std::filesystem::path> folders;
  for (const std::string& root : InstallRoots()) folders.push_back(std::filesystem::path(root) / KOPPEL_MODULE_LIBDIR);
  folders.push_back(KOPPEL_MODULE_INSTALL_DIR);
  folders.push_back(KOPPEL_MODULE_BUILD_DIR);
  return folders;
}

const ModuleTable* TryLoad(const std::filesystem::path& file, const std::string& entry, std::string* why) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return nullptr;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    *why += "\n  " + file.string() + ": " + dlerror();
    return nullptr;
  }
  using Entry = const ModuleTable* (*)();
  const auto function = reinterpret_cast<Entry>(dlsym(handle, entry.c_str()));
  const ModuleTable* table = function ? function() : nullptr;
  if (!table || std::string(table->version) != KOPPEL_VERSION_STRING) {
    *why += "\n  " + file.string() + (table ? ": of koppel " + std::string(table->version) : ": no " + entry);
    dlclose(handle);
    return nullptr;
  }
  return table;  // kept loaded for the rest of the process
}

}  // namespace

const ModuleTable& LoadModule(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, const ModuleTable*> loaded;
  const std::lock_guard<std::mutex> lock(mutex);
  if (const auto it = loaded.find(name); it != loaded.end()) return *it->second;
  const std::string file = "libkoppel_" + name + ".so", entry = "koppel_" + name + "_module";
  std::string why;
  for (const std::filesystem::path& folder : ModuleFolders()) {
    if (const ModuleTable* table = TryLoad(folder / file, entry, &why)) {
      loaded[name] = table;
      return *table;
    }
  }
  if (why.empty()) {
    why = "\n  not found in";
    for (const std::filesystem::path& folder : ModuleFolders()) why += " " + folder.string();
  }
  throw std::runtime_error("koppel's module " + file + " (koppel " KOPPEL_VERSION_STRING ") could not be loaded:" + why);
}

}  // namespace koppel
