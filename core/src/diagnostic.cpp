#include "koppel/core/diagnostic.hpp"

#include "koppel/core/printable_text.hpp"

#include <utility>

namespace koppel {

// A message goes to a terminal: a name from a file or a caller that holds a control character
// (ESC, BEL, CR) is shown escaped ("\x1B"), never sent raw; a message may span lines.
std::string Diagnostic::ToString() const {
  std::string s = PrintableText(file, Replacement::kEscape);
  if (line > 0) s += ":" + std::to_string(line) + (column > 0 ? ":" + std::to_string(column) : "");
  s += ": " + PrintableText(message, Replacement::kEscape, "\n");
  if (!path.empty()) s += " (" + PrintableText(path, Replacement::kEscape) + ")";
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
