#include "koppel/core/diagnostic.hpp"

#include <utility>

namespace koppel {

std::string Diagnostic::ToString() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line) + (column > 0 ? ":" + std::to_string(column) : "");
  s += ": " + message;
  if (!path.empty()) s += " (" + path + ")";
  return s;
}

static std::string JoinDiagnostics(const std::vector<Diagnostic>& diagnostics) {
  std::string s;
  // appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "" + temporary here
  for (const Diagnostic& d : diagnostics) {
    if (!s.empty()) s += '\n';
    s += d.ToString();
  }
  return s;
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(JoinDiagnostics(diagnostics)), diagnostics_(std::move(diagnostics)) {}

}  // namespace koppel
