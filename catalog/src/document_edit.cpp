#include "koppel/catalog/document_edit.hpp"

#include "input_file.hpp"  // ParseYamlText

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

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

// The place of the scalar `node` (read at `path`) in the text.
ScalarPlace PlaceOf(const std::string& text, const std::string& file_name, const std::string& path, const YAML::Node& node) {
  const std::string& value = node.Scalar();
  // yaml-cpp's mark is the scalar's first byte; an anchor or tag before it moves it along the line
  std::size_t begin = node.Mark().pos < 0 ? text.size() : static_cast<std::size_t>(node.Mark().pos);
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

ScalarPlace FindPlace(const std::string& text, const std::string& file_name, const std::string& path, const YAML::Node& root) {
  const std::optional<YAML::Node> node = Locate(root, path, 0);
  if (!node || !node->IsScalar()) Refuse(file_name, path, "the file holds no single value at '" + path + "' to change");
  return PlaceOf(text, file_name, path, *node);
}

}  // namespace

TextSpan ScalarSpan(const std::string& text, const std::string& file_name, const std::string& key_path) {
  return ScalarPlaceAt(text, file_name, key_path).span;
}

ScalarPlace ScalarPlaceAt(const std::string& text, const std::string& file_name, const std::string& key_path) {
  return FindPlace(text, file_name, key_path, ParseYamlText(text, file_name));
}

std::unordered_map<std::string, ScalarPlace> ScalarPlaces(const std::string& text, const std::string& file_name) {
  std::unordered_map<std::string, ScalarPlace> places;
  // one walk of the tree (a stack, not recursion: a hostile file may nest deeply), each scalar's
  // key path as MechanismFile::formulas names it
  std::vector<std::pair<YAML::Node, std::string>> stack{{ParseYamlText(text, file_name), ""}};
  while (!stack.empty()) {
    const auto [node, path] = std::move(stack.back());
    stack.pop_back();
    if (node.IsScalar()) {
      try {
        places.emplace(path, PlaceOf(text, file_name, path, node));
      } catch (const InputError&) {
        // written over several lines: no place
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) stack.emplace_back(node[i], path + "[" + std::to_string(i) + "]");
    } else if (node.IsMap()) {
      for (auto it = node.begin(); it != node.end(); ++it)
        if (it->first.IsScalar()) stack.emplace_back(it->second, path.empty() ? it->first.Scalar() : path + "." + it->first.Scalar());
    }
  }
  return places;
}

std::string EditMechanismText(const std::string& text, const std::string& file_name, const DocumentChanges& changes) {
  if (changes.parameters.empty() && changes.numbers.empty()) return text;
  const YAML::Node root = ParseYamlText(text, file_name);
  std::vector<ScalarEdit> edits;
  for (const auto& [name, formula] : changes.parameters) {
    const YAML::Node parameters = root.IsMap() ? root["parameters"] : YAML::Node();
    if (!parameters.IsMap() || !parameters[name].IsDefined())
      Refuse(file_name, "parameters." + name, "'" + name + "' is not a parameter of this file");
    edits.push_back({FindPlace(text, file_name, "parameters." + name, root), formula, "parameter '" + name + "'"});
  }
  for (const auto& [path, value] : changes.numbers) edits.push_back({FindPlace(text, file_name, path, root), NumberText(value), "'" + path + "'"});
  return SpliceScalars(text, file_name, std::move(edits));
}

}  // namespace koppel
