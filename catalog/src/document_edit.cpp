#include "koppel/catalog/document_edit.hpp"

#include "input_file.hpp"  // ParseYamlText

#include <fmt/core.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace koppel {
namespace {

[[noreturn]] void Refuse(const std::string& file_name, const std::string& path, const std::string& message) {
  throw InputError({Diagnostic{file_name, 0, 0, path, message}});
}

// The node at path[pos..] below `node`. A key may itself hold '.' or '[' (a link named
// "arm.2"): every key that the path starts with is tried, the first that leads to a node wins.
std::optional<YAML::Node> Locate(const YAML::Node& node, const std::string& path, std::size_t pos) {
  if (pos == path.size()) return node;
  if (node.IsSequence() && path[pos] == '[') {
    const std::size_t close = path.find(']', pos);
    if (close == std::string::npos || close == pos + 1) return std::nullopt;
    std::size_t index = 0;
    for (std::size_t k = pos + 1; k < close; ++k) {
      if (path[k] < '0' || path[k] > '9' || index > node.size()) return std::nullopt;
      index = 10 * index + static_cast<std::size_t>(path[k] - '0');
    }
    if (index >= node.size()) return std::nullopt;
    std::size_t next = close + 1;
    if (next < path.size() && path[next] == '.') ++next;
    return Locate(node[index], path, next);
  }
  if (!node.IsMap()) return std::nullopt;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (!it->first.IsScalar()) continue;
    const std::string& key = it->first.Scalar();
    if (path.compare(pos, key.size(), key) != 0) continue;
    const std::size_t next = pos + key.size();
    std::optional<YAML::Node> found;
    if (next == path.size()) {
      found = it->second;
    } else if (path[next] == '.') {
      found = Locate(it->second, path, next + 1);
    } else if (path[next] == '[') {
      found = Locate(it->second, path, next);
    }
    if (found) return found;
  }
  return std::nullopt;
}

// A scalar's place in the text: its span and the quote that stays around it ('\0': none, the
// span is the whole scalar).
struct Place {
  TextSpan span;
  char quote = '\0';
};

// The end of a quoted scalar that opens at `open` (the closing quote's offset), or npos.
std::size_t ClosingQuote(const std::string& text, std::size_t open) {
  const char quote = text[open];
  for (std::size_t k = open + 1; k < text.size(); ++k) {
    if (quote == '"' && text[k] == '\\') {
      ++k;
    } else if (quote == '\'' && text[k] == '\'' && k + 1 < text.size() && text[k + 1] == '\'') {
      ++k;
    } else if (text[k] == quote) {
      return k;
    }
  }
  return std::string::npos;
}

Place FindPlace(const std::string& text, const std::string& file_name, const std::string& path, const YAML::Node& root) {
  const std::optional<YAML::Node> node = Locate(root, path, 0);
  if (!node || !node->IsScalar()) Refuse(file_name, path, "the file holds no single value at '" + path + "' to change");
  const std::string& value = node->Scalar();
  // yaml-cpp's mark is the scalar's first byte; an anchor or tag before it moves it along the line
  std::size_t begin = node->Mark().pos < 0 ? text.size() : static_cast<std::size_t>(node->Mark().pos);
  const std::size_t line_end = std::min(text.find('\n', std::min(begin, text.size())), text.size());
  for (; begin < line_end; ++begin) {
    if (text[begin] == '"' || text[begin] == '\'') {
      const std::size_t close = ClosingQuote(text, begin);
      if (close == std::string::npos || close > line_end) break;
      // the quotes stay where the text between them is the value itself (no escape, no folding)
      if (text.compare(begin + 1, close - begin - 1, value) == 0) return {{begin + 1, close}, text[begin]};
      return {{begin, close + 1}, '\0'};
    }
    if (!value.empty() && text.compare(begin, value.size(), value) == 0 && begin + value.size() <= line_end) {
      return {{begin, begin + value.size()}, '\0'};
    }
    if (text[begin] != '&' && text[begin] != '!') break;
    // skip the anchor or tag and the spaces after it
    while (begin < line_end && text[begin] != ' ') ++begin;
  }
  Refuse(file_name, path, "the value at '" + path + "' is not written on one line as it reads ('" + value +
                              "'): it cannot be changed in place");
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

TextSpan ScalarSpan(const std::string& text, const std::string& file_name, const std::string& key_path) {
  return FindPlace(text, file_name, key_path, ParseYamlText(text, file_name)).span;
}

std::string EditMechanismText(const std::string& text, const std::string& file_name, const DocumentChanges& changes) {
  if (changes.parameters.empty() && changes.numbers.empty()) return text;
  const YAML::Node root = ParseYamlText(text, file_name);
  struct Edit {
    Place place;
    std::string replacement, what;
  };
  std::vector<Edit> edits;
  for (const auto& [name, formula] : changes.parameters) {
    const YAML::Node parameters = root.IsMap() ? root["parameters"] : YAML::Node();
    if (!parameters.IsMap() || !parameters[name].IsDefined())
      Refuse(file_name, "parameters." + name, "'" + name + "' is not a parameter of this file");
    const Place place = FindPlace(text, file_name, "parameters." + name, root);
    edits.push_back({place, ScalarText(formula, place.quote), "parameter '" + name + "'"});
  }
  for (const auto& [path, value] : changes.numbers) {
    const Place place = FindPlace(text, file_name, path, root);
    edits.push_back({place, ScalarText(NumberText(value), place.quote), "'" + path + "'"});
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.place.span.begin < b.place.span.begin; });
  for (std::size_t k = 1; k < edits.size(); ++k) {
    if (edits[k].place.span.begin < edits[k - 1].place.span.end)
      Refuse(file_name, "", "two changes of the same value: " + edits[k - 1].what + " and " + edits[k].what);
  }
  std::string out;
  std::size_t from = 0;
  for (const Edit& e : edits) {
    out.append(text, from, e.place.span.begin - from);
    out += e.replacement;
    from = e.place.span.end;
  }
  out.append(text, from, std::string::npos);
  return out;
}

}  // namespace koppel
