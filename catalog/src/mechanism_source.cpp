#include "koppel/catalog/mechanism_source.hpp"

#include "koppel/catalog/parameter_builder.hpp"  // MechanismTextWithoutCard

#include "mechanism_node.hpp"
#include "yaml_reader.hpp"

#include <utility>

namespace koppel {
namespace {

// a source is read for its mechanism: the card's formulas are the catalog commands' (CardFormulas)
constexpr CardFormulas kCardFormulas = CardFormulas::kUnparsed;

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
  // what Evaluate parses from the kept text, parsed here once: the same tree, the same places
  *evaluated = ParseMechanismNode(ParseYamlText(text, file_name), file_name, overrides, kCardFormulas);
  return MechanismSource(std::make_shared<const std::string>(text), file_name);
}

MechanismFile MechanismSource::Evaluate(const Overrides& overrides) const {
  return ParseMechanismText(*text_, path_, overrides, kCardFormulas);
}

MechanismSource MechanismSource::WithoutCard() const {
  return MechanismSource(std::make_shared<const std::string>(MechanismTextWithoutCard(*text_, path_)), path_);
}

}  // namespace koppel
