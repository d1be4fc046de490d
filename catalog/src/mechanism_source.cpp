#include "koppel/catalog/mechanism_source.hpp"

#include "koppel/catalog/parameter_builder.hpp"  // MechanismTextWithoutCard

#include "card_text.hpp"
#include "input_file.hpp"  // ParseYamlText
#include "mechanism_node.hpp"
#include "yaml_reader.hpp"

#include <utility>

namespace koppel {
namespace {

// yaml-cpp found the blanked card where BlankCard (card_text.hpp) says it is: `catalog` a
// top-level key at its line, and another at the card's next line (if any), each at column 1.
bool SourceCardInPlace(const YAML::Node& root, const BlankedCard& blanked) {
  if (!root.IsMap()) return false;
  bool key = false, next = blanked.next_line == 0;
  for (auto it = root.begin(); it != root.end(); ++it) {
    const YAML::Mark mark = it->first.Mark();
    if (mark.column != 0) continue;
    key = key || (mark.line + 1 == blanked.key_line && it->first.IsScalar() && it->first.Scalar() == "catalog");
    next = next || mark.line + 1 == blanked.next_line;
  }
  return key && next;
}

// The mechanism of `text`, its card not read (CardReading::kSkipped) and, where BlankCard can
// blank it, not parsed either. Whatever goes wrong with the blanked text (a YAML error, an
// alias of an anchor in the card, a problem of the mechanism) is left to the whole text's
// reading: its messages are the file's as it is, every line in its place.
MechanismFile ReadMechanismAlone(const std::string& text, const std::string& file_name, const Overrides& overrides) {
  if (const std::optional<BlankedCard> blanked = BlankCard(text)) {
    try {
      const YAML::Node root = ParseYamlText(blanked->text, file_name);
      if (SourceCardInPlace(root, *blanked)) return ParseMechanismNode(root, file_name, overrides, CardReading::kSkipped);
    } catch (const InputError&) {
      // read again below, card and all
    }
  }
  return ParseMechanismNode(ParseYamlText(text, file_name), file_name, overrides, CardReading::kSkipped);
}

}  // namespace

MechanismSource::MechanismSource(std::shared_ptr<const std::string> text, std::string path)
    : text_(std::move(text)), path_(std::move(path)) {}

MechanismSource MechanismSource::Read(const std::string& name) {
  std::string path;
  std::string text = ReadMechanismFileText(name, &path);
  return Parse(text, path);
}

MechanismSource MechanismSource::Parse(const std::string& text, const std::string& file_name) {
  ParseYamlText(text, file_name);  // text that is no YAML is refused here, not at every evaluation
  return MechanismSource(std::make_shared<const std::string>(text), file_name);
}

MechanismSource MechanismSource::Read(const std::string& name, const Overrides& overrides, MechanismFile* evaluated) {
  std::string path;
  std::string text = ReadMechanismFileText(name, &path);
  return Parse(text, path, overrides, evaluated);
}

MechanismSource MechanismSource::Parse(const std::string& text, const std::string& file_name, const Overrides& overrides,
                                       MechanismFile* evaluated) {
  // what Evaluate reads from the kept text, read here once
  *evaluated = ReadMechanismAlone(text, file_name, overrides);
  return MechanismSource(std::make_shared<const std::string>(text), file_name);
}

MechanismFile MechanismSource::Evaluate(const Overrides& overrides) const { return ReadMechanismAlone(*text_, path_, overrides); }

MechanismSource MechanismSource::WithoutCard() const {
  return MechanismSource(std::make_shared<const std::string>(MechanismTextWithoutCard(*text_, path_)), path_);
}

}  // namespace koppel
