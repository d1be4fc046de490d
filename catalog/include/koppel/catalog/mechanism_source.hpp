// A mechanism file read once, evaluated with any parameter overrides without reading the file
// again: what a koppel::Model keeps to re-evaluate its parameters (Model::Set, a tolerance's
// samples) and shares between its copies. Each evaluation parses the kept text anew, so every
// problem keeps its line and column (a copied YAML tree loses them). The file is read for its
// mechanism: its catalog card is not read (CardReading::kSkipped, mechanism_file.hpp; the
// evaluations' MechanismFile::card is empty), and not parsed where its lines are plainly its own.
#pragma once

#include "koppel/catalog/mechanism_file.hpp"

#include <memory>
#include <string>

namespace koppel {

class MechanismSource {
 public:
  // The file `name`, or the catalog entry when it is no file but a catalog id (as
  // ReadMechanismFile). InputError when it does not read or is not YAML.
  static MechanismSource Read(const std::string& name);
  // The text of a mechanism file; `file_name` stands for the file in messages.
  static MechanismSource Parse(const std::string& text, const std::string& file_name);
  // Read (Parse) and then Evaluate(overrides) into `evaluated`, the YAML parsed once instead of
  // twice: a program that reads a file and evaluates it once (`koppel analyze`) spent a third of
  // its start-up in yaml-cpp parsing the same text twice (issue 25). Throws as both would.
  static MechanismSource Read(const std::string& name, const Overrides& overrides, MechanismFile* evaluated);
  static MechanismSource Parse(const std::string& text, const std::string& file_name, const Overrides& overrides,
                               MechanismFile* evaluated);

  // The mechanism with `overrides` (NAME -> formula) in place of the parameters' formulas: the
  // same as ReadMechanismFile(path(), overrides) but for the card, not read.
  // InputError for what does not evaluate or check.
  MechanismFile Evaluate(const Overrides& overrides = {}) const;
  const std::string& path() const { return path_; }
  const std::string& text() const { return *text_; }
  // The same without the file's `catalog` card (the card does not make the mechanism and is a
  // third to two thirds of a catalog entry: a tolerance analysis evaluates thousands of times).
  MechanismSource WithoutCard() const;

 private:
  MechanismSource(std::shared_ptr<const std::string> text, std::string path);
  std::shared_ptr<const std::string> text_;  // never changed once read: copies share it
  std::string path_;
};

}  // namespace koppel
