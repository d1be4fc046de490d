#include "koppel/catalog/parameter_builder.hpp"

#include "input_file.hpp"  // ParseYamlText
#include "mechanism_node.hpp"
#include "yaml_reader.hpp"

#include <fmt/core.h>

#include <memory>

namespace koppel {

std::string MechanismTextWithoutCard(const std::string& text, const std::string& file_name) {
  YAML::Node document = ParseYamlText(text, file_name);
  document.remove("catalog");
  YAML::Emitter out;
  out << document;
  return out.c_str();
}

MechanismBuilder ParameterBuilder(const std::string& text, const std::string& file_name, const Overrides& overrides,
                                  const std::vector<std::string>& names) {
  const auto parsed = std::make_shared<const YAML::Node>(ParseYamlText(text, file_name));
  return [file_name, parsed, overrides, names](const std::vector<double>& values) -> Expected<Mechanism> {
    Overrides with = overrides;
    for (size_t j = 0; j < names.size() && j < values.size(); ++j) {
      std::erase_if(with, [&](const auto& o) { return o.first == names[j]; });
      with.emplace_back(names[j], fmt::format("{:.17g}", values[j]));
    }
    try {
      return ParseMechanismNode(YAML::Clone(*parsed), file_name, with).mechanism;
    } catch (const InputError& e) {
      return Expected<Mechanism>::Error(e.what());
    }
  };
}

MechanismBuilder ParameterBuilder(const MechanismSource& source, const Overrides& overrides, const std::vector<std::string>& names) {
  return ParameterBuilder(source.text(), source.path(), overrides, names);
}

}  // namespace koppel
