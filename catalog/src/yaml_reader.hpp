// Reading YAML nodes with diagnostics: every accessor reports what is wrong with file, line,
// column and key path, and returns nullopt instead of throwing, so a file's problems are all
// collected before one InputError is thrown. Private to the catalog (yaml-cpp stays in here).
#pragma once

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/expression.hpp"

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace koppel {

class YamlReader {
 public:
  YamlReader(std::string file, const ParameterSet* parameters) : file_(std::move(file)), parameters_(parameters) {}

  // Reports at the node's position; a missing node (no mark) falls back to `fallback`.
  void Error(const YAML::Node& node, const std::string& path, const std::string& message);
  void Error(const YAML::Mark& mark, const std::string& path, const std::string& message);

  bool ExpectMap(const YAML::Node& node, const std::string& path);
  bool ExpectSequence(const YAML::Node& node, const std::string& path);
  // Reports keys of `map` not in `allowed` (suggesting the nearest allowed key) and duplicates.
  void CheckKeys(const YAML::Node& map, const std::string& path, std::initializer_list<const char*> allowed);
  void CheckKeys(const YAML::Node& map, const std::string& path, const std::vector<std::string>& allowed);
  // A required key: reports it missing (at the map) and returns an invalid node.
  YAML::Node Require(const YAML::Node& map, const std::string& key, const std::string& path);

  std::optional<std::string> Text(const YAML::Node& node, const std::string& path);
  // The rule for a name the file gives (a link, point, joint, output, load, the drive's input, a
  // parameter; `what` says which): printable text (koppel/core/printable_text.hpp: valid UTF-8,
  // no control character) of at most kMaxNameBytes, so that every table, picture and page can
  // show it. Reports at `node` and returns false otherwise.
  bool CheckName(const YAML::Node& node, const std::string& path, const std::string& what, const std::string& name);
  // A number or a formula over the parameters.
  std::optional<double> Number(const YAML::Node& node, const std::string& path);
  std::optional<double> Number(const YAML::Node& node, const std::string& path, const ParameterSet& parameters);
  std::optional<int> Count(const YAML::Node& node, const std::string& path);  // whole number >= 0
  std::optional<Eigen::Vector2d> Vector(const YAML::Node& node, const std::string& path);
  // A point's place [x, y]: a Vector within kMaxCoordinate of the origin in each coordinate.
  std::optional<Eigen::Vector2d> Position(const YAML::Node& node, const std::string& path);
  std::optional<bool> Flag(const YAML::Node& node, const std::string& path);
  std::vector<std::string> TextList(const YAML::Node& node, const std::string& path);

  // The node's key order (yaml-cpp keeps document order) as (key text, key node, value node).
  struct Entry {
    std::string key;
    YAML::Node key_node;
    YAML::Node value;
  };
  std::vector<Entry> Entries(const YAML::Node& map, const std::string& path);

  const std::string& file() const { return file_; }
  std::vector<Diagnostic>& diagnostics() { return diagnostics_; }
  void set_parameters(const ParameterSet* parameters) { parameters_ = parameters; }

  // A parameter whose formula failed (reported once, at its line or its --set): a formula naming
  // it fails too, and Number reports no second error for it (no cascade).
  void MarkFailedParameter(const std::string& name) { failed_parameters_.push_back(name); }
  bool NamesFailedParameter(const std::string& formula) const;
  void set_fallback(const YAML::Mark& mark) { fallback_ = mark; }
  // Where Number records each formula it evaluates, with its key path (null: nowhere).
  void set_formula_log(std::vector<std::pair<std::string, std::string>>* log) { formula_log_ = log; }

 private:
  std::string file_;
  const ParameterSet* parameters_;
  std::vector<std::string> failed_parameters_;
  std::vector<Diagnostic> diagnostics_;
  YAML::Mark fallback_ = YAML::Mark::null_mark();
  std::vector<std::pair<std::string, std::string>>* formula_log_ = nullptr;
};

// Joins a key path: Child("joints", "A") = "joints.A"; Index("links", 1) = "links[1]".
std::string Child(const std::string& path, const std::string& key);
std::string Index(const std::string& path, int index);
// The candidate nearest to `word` (fewer than three edits), for "did you mean"; empty if none.
std::string Nearest(const std::string& word, const std::vector<std::string>& candidates);
// "unknown key 'x' (did you mean 'y'?)", or with the list of candidates when none is near.
std::string UnknownName(const std::string& what, const std::string& word, const std::vector<std::string>& candidates);

// Parses the `catalog` section of a mechanism file (card_reader.cpp).
std::optional<CatalogCard> ReadCard(YamlReader& reader, const YAML::Node& node, const MechanismFile& file);

// Reads the masses (links.*.mass, cg, inertia), units, gravity and loads into file.loads
// (loads_reader.cpp). Call once the links, joints, drive and outputs are read.
void ReadLoads(YamlReader& reader, const YAML::Node& root, MechanismFile& file);

}  // namespace koppel
