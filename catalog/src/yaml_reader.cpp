#include "yaml_reader.hpp"

#include "koppel/core/limits.hpp"
#include "koppel/core/printable_text.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <unordered_set>

namespace koppel {
namespace {

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string NodeKind(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return "'" + node.Scalar() + "'";
    case YAML::NodeType::Null: return "nothing";
    default: return "nothing";
  }
}

}  // namespace

std::string Nearest(const std::string& word, const std::vector<std::string>& candidates) {
  int best = 3;
  std::string nearest;
  for (const std::string& c : candidates) {
    const int d = EditDistance(word, c);
    if (d < best) {
      best = d;
      nearest = c;
    }
  }
  return nearest;
}

std::string UnknownName(const std::string& what, const std::string& word, const std::vector<std::string>& candidates) {
  std::string message = "unknown " + what + " '" + word + "'";
  const std::string suggestion = Nearest(word, candidates);
  if (!suggestion.empty()) return message + " (did you mean '" + suggestion + "'?)";
  message += " (expected one of:";
  for (const std::string& c : candidates) message += " " + c;
  return message + ")";
}

std::string Child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string Index(const std::string& path, int index) { return path + "[" + std::to_string(index) + "]"; }

void YamlReader::Error(const YAML::Mark& mark, const std::string& path, const std::string& message) {
  const YAML::Mark& m = mark.is_null() ? fallback_ : mark;
  diagnostics_.push_back({file_, m.is_null() ? 0 : m.line + 1, m.is_null() ? 0 : m.column + 1, path, message});
}

void YamlReader::Error(const YAML::Node& node, const std::string& path, const std::string& message) {
  Error(node.IsDefined() ? node.Mark() : YAML::Mark::null_mark(), path, message);
}

bool YamlReader::ExpectMap(const YAML::Node& node, const std::string& path) {
  if (node.IsMap()) return true;
  Error(node, path, "expected a map (key: value lines), found " + NodeKind(node));
  return false;
}

bool YamlReader::ExpectSequence(const YAML::Node& node, const std::string& path) {
  if (node.IsSequence()) return true;
  Error(node, path, "expected a list, found " + NodeKind(node));
  return false;
}

std::vector<YamlReader::Entry> YamlReader::Entries(const YAML::Node& map, const std::string& path) {
  std::vector<Entry> entries;
  if (!ExpectMap(map, path)) return entries;
  std::unordered_set<std::string> seen;  // a map of many parameters must not cost its square
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (!it->first.IsScalar()) {
      Error(it->first, path, "a key must be a plain name");
      continue;
    }
    const std::string key = it->first.Scalar();
    if (!seen.insert(key).second) {
      Error(it->first, Child(path, key), "duplicate key '" + key + "'");
      continue;
    }
    entries.push_back({key, it->first, it->second});
  }
  return entries;
}

void YamlReader::CheckKeys(const YAML::Node& map, const std::string& path, std::initializer_list<const char*> allowed) {
  CheckKeys(map, path, std::vector<std::string>(allowed.begin(), allowed.end()));
}

void YamlReader::CheckKeys(const YAML::Node& map, const std::string& path, const std::vector<std::string>& allowed) {
  if (!map.IsMap()) return;
  for (const Entry& e : Entries(map, path)) {
    if (std::any_of(allowed.begin(), allowed.end(), [&](const std::string& a) { return e.key == a; })) continue;
    Error(e.key_node, Child(path, e.key), UnknownName("key", e.key, allowed));
  }
}

YAML::Node YamlReader::Require(const YAML::Node& map, const std::string& key, const std::string& path) {
  if (!map.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const YAML::Node node = map[key];
  if (!node.IsDefined() || node.IsNull()) Error(map, Child(path, key), "missing required key '" + key + "'");
  return node;
}

std::optional<std::string> YamlReader::Text(const YAML::Node& node, const std::string& path) {
  if (node.IsScalar()) return node.Scalar();
  Error(node, path, "expected text, found " + NodeKind(node));
  return std::nullopt;
}

bool YamlReader::CheckName(const YAML::Node& node, const std::string& path, const std::string& what, const std::string& name) {
  if (name.size() > kMaxNameBytes) {
    Error(node, path, "the " + what + " name is " + std::to_string(name.size()) + " bytes long, more than the limit of " +
                          std::to_string(kMaxNameBytes) + " (kMaxNameBytes)");
    return false;
  }
  if (const std::optional<Unprintable> u = FirstUnprintable(name)) {
    // the name is shown escaped (Diagnostic::ToString), so the message says what to look for
    Error(node, path, "the " + what + " name '" + name + "' holds " + u->Describe() + " at byte " + std::to_string(u->offset + 1) +
                          ": a name must be printable UTF-8 text, without control characters");
    return false;
  }
  return true;
}

std::optional<double> YamlReader::Number(const YAML::Node& node, const std::string& path) {
  static const ParameterSet kNone;
  return Number(node, path, parameters_ ? *parameters_ : kNone);
}

std::optional<double> YamlReader::Number(const YAML::Node& node, const std::string& path, const ParameterSet& parameters) {
  if (!node.IsScalar()) {
    Error(node, path, "expected a number or formula, found " + NodeKind(node));
    return std::nullopt;
  }
  if (formula_log_) formula_log_->emplace_back(path, node.Scalar());
  const Expected<double> value = parameters.Evaluate(node.Scalar());
  if (!value) {
    if (!NamesFailedParameter(node.Scalar())) Error(node, path, value.error());
    return std::nullopt;
  }
  return *value;
}

bool YamlReader::NamesFailedParameter(const std::string& formula) const {
  if (failed_parameters_.empty()) return false;
  // the formula's names: a letter or '_' then letters, digits, '_' (ParameterSet::ValidName)
  for (size_t i = 0; i < formula.size();) {
    const auto word = [&](size_t k) { return k < formula.size() && (std::isalnum(static_cast<unsigned char>(formula[k])) || formula[k] == '_'); };
    if (!word(i)) {
      ++i;
      continue;
    }
    size_t end = i;
    while (word(end)) ++end;
    const std::string name = formula.substr(i, end - i);
    if (std::find(failed_parameters_.begin(), failed_parameters_.end(), name) != failed_parameters_.end()) return true;
    i = end;
  }
  return false;
}

std::optional<int> YamlReader::Count(const YAML::Node& node, const std::string& path) {
  const std::optional<double> v = Number(node, path);
  if (!v) return std::nullopt;
  if (*v < 0 || *v > 1e6 || std::floor(*v) != *v) {
    Error(node, path, "expected a whole number >= 0");
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

std::optional<Eigen::Vector2d> YamlReader::Vector(const YAML::Node& node, const std::string& path) {
  if (!node.IsSequence() || node.size() != 2) {
    Error(node, path, "expected a point [x, y], found " + NodeKind(node));
    return std::nullopt;
  }
  const std::optional<double> x = Number(node[0], Index(path, 0));
  const std::optional<double> y = Number(node[1], Index(path, 1));
  if (!x || !y) return std::nullopt;
  return Eigen::Vector2d(*x, *y);
}

std::optional<Eigen::Vector2d> YamlReader::Position(const YAML::Node& node, const std::string& path) {
  const std::optional<Eigen::Vector2d> v = Vector(node, path);
  if (!v || v->cwiseAbs().maxCoeff() <= kMaxCoordinate) return v;
  Error(node, path, fmt::format("a coordinate of {:.3g} lies beyond {:g} of the file's length unit (kMaxCoordinate): no mechanism is "
                                "that size in its own unit; choose a larger unit (units: {{length: ...}})", v->cwiseAbs().maxCoeff(),
                                kMaxCoordinate));
  return std::nullopt;
}

std::optional<bool> YamlReader::Flag(const YAML::Node& node, const std::string& path) {
  if (node.IsScalar()) {
    const std::string& s = node.Scalar();
    if (s == "true" || s == "yes") return true;
    if (s == "false" || s == "no") return false;
  }
  Error(node, path, "expected true or false, found " + NodeKind(node));
  return std::nullopt;
}

std::vector<std::string> YamlReader::TextList(const YAML::Node& node, const std::string& path) {
  std::vector<std::string> out;
  if (!ExpectSequence(node, path)) return out;
  for (size_t i = 0; i < node.size(); ++i) {
    if (auto t = Text(node[i], Index(path, static_cast<int>(i)))) out.push_back(*t);
  }
  return out;
}

}  // namespace koppel
