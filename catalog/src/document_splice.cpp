// New values written into the scalar spans of a user's text (koppel/catalog/document_splice.hpp).
// No YAML reader here: the editor page's WebAssembly module compiles this file too.
#include "koppel/catalog/document_splice.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

[[noreturn]] void Refuse(const std::string& file_name, const std::string& message) {
  throw InputError({Diagnostic{file_name, 0, 0, "", message}});
}

// Whether `formula` reads back as the same text when written bare, in a block or a flow
// collection alike: no indicator first, no ",[]{}" (they end a flow scalar), no ": " or " #".
bool PlainSafe(const std::string& formula) {
  if (formula.empty() || formula.front() == ' ' || formula.back() == ' ' || formula.back() == ':') return false;
  if (formula == "~" || formula == "null" || formula == "Null" || formula == "NULL") return false;
  if (std::string("?:,[]{}#&*!|>'\"%@`").find(formula.front()) != std::string::npos) return false;
  if (formula.front() == '-' && (formula.size() == 1 || formula[1] == ' ')) return false;
  for (std::size_t k = 0; k < formula.size(); ++k) {
    const unsigned char c = static_cast<unsigned char>(formula[k]);
    if (c < 0x20 || c == 0x7f || std::string(",[]{}").find(formula[k]) != std::string::npos) return false;
    if (formula[k] == ':' && k + 1 < formula.size() && formula[k + 1] == ' ') return false;
    if (formula[k] == '#' && k > 0 && formula[k - 1] == ' ') return false;
  }
  return true;
}

// `formula` as the text of a scalar inside `quote` ('\0': written bare, or double-quoted when it
// cannot be).
std::string ScalarText(const std::string& formula, char quote) {
  if (quote == '\0' && PlainSafe(formula)) return formula;
  std::string out;
  for (char c : formula) {
    if (quote == '\'' && c == '\'') out += '\'';
    if (quote != '\'' && (c == '"' || c == '\\')) out += '\\';
    out += c;
  }
  return quote == '\0' ? "\"" + out + "\"" : out;
}

}  // namespace

std::string NumberText(double value) {
  if (!std::isfinite(value)) throw InputError({Diagnostic{"", 0, 0, "", "a file cannot hold the value " + fmt::format("{}", value)}});
  return fmt::format("{}", value);  // the shortest text that reads back to the same double
}

std::string SpliceScalars(const std::string& text, const std::string& file_name, std::vector<ScalarEdit> edits) {
  std::sort(edits.begin(), edits.end(), [](const ScalarEdit& a, const ScalarEdit& b) { return a.place.span.begin < b.place.span.begin; });
  for (std::size_t k = 0; k < edits.size(); ++k) {
    const TextSpan& s = edits[k].place.span;
    if (s.begin > s.end || s.end > text.size()) Refuse(file_name, edits[k].what + ": its place is not in the text");
    if (k > 0 && s.begin < edits[k - 1].place.span.end)
      Refuse(file_name, "two changes of the same value: " + edits[k - 1].what + " and " + edits[k].what);
  }
  std::string out;
  std::size_t from = 0;
  for (const ScalarEdit& e : edits) {
    out.append(text, from, e.place.span.begin - from);
    out += ScalarText(e.formula, e.place.quote);
    from = e.place.span.end;
  }
  out.append(text, from, std::string::npos);
  return out;
}

}  // namespace koppel
