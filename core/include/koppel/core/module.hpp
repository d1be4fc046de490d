// Modules: the parts of koppel that need heavy libraries only a few commands use (Ceres with glog,
// SuiteSparse and LAPACK for the fits; cairo with X11 for `koppel animate`) are shared objects of
// their own, libkoppel_NAME.so, loaded when first called, so that a program linking koppel (the
// koppel executable first) starts without mapping them (issue 25). Each module exports one C
// function, koppel_NAME_module(), returning a table of its functions whose first member is the
// koppel version it was built with (ModuleTable); a module of another version is not used.
#pragma once

#include <string>
#include <vector>

namespace koppel {

// The head of every module's table.
struct ModuleTable {
  const char* version;  // KOPPEL_VERSION_STRING of the build that made the module
};

// Where an installed koppel's modules and data may be, nearest first: each folder from the one
// holding this code upwards (the koppel executable in PREFIX/bin, the Python module in
// PREFIX/lib/python3/dist-packages/koppel), so that an installed tree and a moved one find their
// own; then the prefix that koppel's CMake package compiles into a program linking the installed
// static libraries (koppel_installed_prefix, tools/cmake/koppelConfig.cmake.in).
std::vector<std::string> InstallRoots();

// The table of module NAME ("ceres" -> libkoppel_NAME.so, entry koppel_NAME_module), loaded
// once per process and kept (never unloaded). Looked for in LIBDIR/koppel (LIBDIR as installed,
// e.g. lib) under each of InstallRoots() (the build tree keeps its modules there too), then
// under the configured install prefix and in the build tree. Throws std::runtime_error naming
// the module, where it was looked for and why it could not be loaded.
const ModuleTable& LoadModule(const std::string& name);

// The file that holds the code at `address` (a function of the caller's), canonical: the koppel
// executable, a program linking koppel statically, the Python module, or a shared library of
// koppel. Empty when not known.
std::string FileHoldingCode(const void* address);

}  // namespace koppel
