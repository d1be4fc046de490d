#include "koppel/catalog/parameter_use.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace koppel {
namespace {

// The names a formula holds: a letter or '_' then letters, digits, '_' (ParameterSet::ValidName);
// a run that starts with a digit is a number ("1e5"), not a name.
std::vector<std::string> NamesIn(const std::string& formula) {
  std::vector<std::string> names;
  const auto word = [&](std::size_t k) {
    return k < formula.size() && (std::isalnum(static_cast<unsigned char>(formula[k])) || formula[k] == '_');
  };
  for (std::size_t i = 0; i < formula.size();) {
    if (!word(i)) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (word(end)) ++end;
    if (!std::isdigit(static_cast<unsigned char>(formula[i]))) names.push_back(formula.substr(i, end - i));
    i = end;
  }
  return names;
}

// How a formula names `name`: not at all, only as a term or factor (ParameterMeasure), or
// otherwise (inside a function's brackets, a divisor, a power).
enum class Mention { kNone, kLinear, kOther };

Mention MentionOf(const std::string& formula, const std::string& name) {
  Mention mention = Mention::kNone;
  const auto word = [&](std::size_t k) {
    return k < formula.size() && (std::isalnum(static_cast<unsigned char>(formula[k])) || formula[k] == '_');
  };
  const auto neighbour = [&](std::size_t k, int step) {  // the next character that is no space
    for (long j = static_cast<long>(k) + step; j >= 0 && j < static_cast<long>(formula.size()); j += step)
      if (formula[j] != ' ') return formula[j];
    return '\0';
  };
  std::vector<bool> function_brackets;  // per open bracket: whether a function's name opened it
  for (std::size_t i = 0; i < formula.size();) {
    if (formula[i] == '(') {
      function_brackets.push_back(i > 0 && word(i - 1));
      ++i;
    } else if (formula[i] == ')') {
      if (!function_brackets.empty()) function_brackets.pop_back();
      ++i;
    } else if (!word(i)) {
      ++i;
    } else {
      std::size_t end = i;
      while (word(end)) ++end;
      if (formula.compare(i, end - i, name) == 0 && end - i == name.size() && !std::isdigit(static_cast<unsigned char>(formula[i]))) {
        const bool in_function = std::find(function_brackets.begin(), function_brackets.end(), true) != function_brackets.end();
        const char before = i == 0 ? '\0' : neighbour(i, -1), after = neighbour(end - 1, 1);
        const bool linear = !in_function && before != '/' && before != '^' && after != '^' && after != '(';
        mention = linear && mention != Mention::kOther ? Mention::kLinear : Mention::kOther;
      }
      i = end;
    }
  }
  return mention;
}

// What the number at a key path of the model part measures (MechanismFile::formulas' paths).
ParameterMeasure MeasureAt(const MechanismFile& file, const std::string& path) {
  const auto starts = [&](const char* prefix) { return path.rfind(prefix, 0) == 0; };
  const auto ends = [&](const std::string& suffix) {
    return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  const bool angle_input = file.mechanism.InputIsAngle();
  const ParameterMeasure input = angle_input ? ParameterMeasure::kAngle : ParameterMeasure::kLength;
  if (starts("links.") && (path.find(".points.") != std::string::npos || path.find(".cg[") != std::string::npos) && ends("]"))
    return ParameterMeasure::kLength;
  if (starts("assembly.points.")) return ParameterMeasure::kLength;
  if (starts("joints.") && ends(".angle")) return ParameterMeasure::kAngle;
  if (starts("outputs.") && ends(".zero")) return ParameterMeasure::kAngle;
  if (path == "drive.zero" || path == "assembly.input" || starts("sweep.")) return input;
  return ParameterMeasure::kUnknown;
}

}  // namespace

ParameterMeasure MeasureOf(const MechanismFile& file, const std::string& name) {
  static const std::string kParameterPath = "parameters.";
  // the parameters that carry `name`'s value as a term or factor; any other use: no one measure
  std::vector<std::string> carriers{name};
  for (const auto& [path, formula] : file.formulas) {
    if (path.compare(0, kParameterPath.size(), kParameterPath) != 0) continue;
    Mention worst = Mention::kNone;
    for (const std::string& c : carriers) worst = std::max(worst, MentionOf(formula, c));
    if (worst == Mention::kOther) return ParameterMeasure::kUnknown;
    if (worst == Mention::kLinear) carriers.push_back(path.substr(kParameterPath.size()));
  }
  std::optional<ParameterMeasure> measure;
  for (const auto& [path, formula] : file.formulas) {
    if (path.compare(0, kParameterPath.size(), kParameterPath) == 0) continue;
    Mention worst = Mention::kNone;
    for (const std::string& c : carriers) worst = std::max(worst, MentionOf(formula, c));
    if (worst == Mention::kNone) continue;
    const ParameterMeasure here = MeasureAt(file, path);
    if (worst == Mention::kOther || here == ParameterMeasure::kUnknown || (measure && *measure != here)) return ParameterMeasure::kUnknown;
    measure = here;
  }
  for (const PointForce& f : file.loads.forces)
    for (const std::string& c : carriers)
      if (MentionOf(f.magnitude, c) != Mention::kNone) return ParameterMeasure::kUnknown;
  for (const LinkTorque& t : file.loads.torques)
    for (const std::string& c : carriers)
      if (MentionOf(t.magnitude, c) != Mention::kNone) return ParameterMeasure::kUnknown;
  return measure.value_or(ParameterMeasure::kUnknown);
}

std::vector<std::string> ParametersRead(const MechanismFile& file) {
  static const std::string kParameterPath = "parameters.";
  std::unordered_map<std::string, std::string> parameter_formula;
  std::vector<std::string> pending;  // names read, their own formulas not yet followed
  for (const auto& [path, formula] : file.formulas) {
    if (path.compare(0, kParameterPath.size(), kParameterPath) == 0) {
      parameter_formula[path.substr(kParameterPath.size())] = formula;
    } else {
      for (std::string& n : NamesIn(formula)) pending.push_back(std::move(n));
    }
  }
  for (const PointForce& f : file.loads.forces)
    for (std::string& n : NamesIn(f.magnitude)) pending.push_back(std::move(n));
  for (const LinkTorque& t : file.loads.torques)
    for (std::string& n : NamesIn(t.magnitude)) pending.push_back(std::move(n));
  // follow the parameters' formulas: a parameter read by a parameter that is read is read
  std::unordered_set<std::string> read;
  while (!pending.empty()) {
    const std::string name = std::move(pending.back());
    pending.pop_back();
    const auto formula = parameter_formula.find(name);
    if (formula == parameter_formula.end() || !read.insert(name).second) continue;
    for (std::string& n : NamesIn(formula->second)) pending.push_back(std::move(n));
  }
  std::vector<std::string> in_order;
  for (const auto& [name, value] : file.parameters.Values())
    if (read.count(name)) in_order.push_back(name);
  return in_order;
}

std::string UnreadParameterMessage(const std::string& name, const std::vector<std::string>& read) {
  std::string message = "no formula of this file reads the parameter '" + name + "', so setting it would change nothing";
  if (read.empty()) return message + " (no formula reads any parameter)";
  message += " (the parameters read:";
  for (const std::string& r : read) message += " " + r;
  return message + ")";
}

}  // namespace koppel
