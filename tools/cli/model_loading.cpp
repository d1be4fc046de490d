#include "model_loading.hpp"

namespace koppel::cli {

Model LoadModel(const std::string& path, const std::vector<std::string>& sets) {
  Model model = Checked([&] {
    return Model::Load(path, ParseParameterValues(sets));  // admitted: mobility 1 (tools/api/src/admission.hpp)
  });
  PrintNotes(path, model.notes());
  return model;
}

std::pair<std::string, double> NamedNumber(const std::string& flag, const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    Complain(flag + ": expected NAME=VALUE, not '" + text + "'");
    throw Exit{kExitBadInput};
  }
  return {text.substr(0, eq), ParseNumberFlag(flag + " " + text.substr(0, eq), text.substr(eq + 1))};
}

}  // namespace koppel::cli
