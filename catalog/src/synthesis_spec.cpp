#include "koppel/catalog/synthesis_spec.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/angles.hpp"
#include "input_file.hpp"
#include "yaml_reader.hpp"

#include <fmt/core.h>


namespace koppel {
namespace {

// [from, to] with from != to.
bool Range(YamlReader& r, const YAML::Node& node, const std::string& key, double* from, double* to) {
  if (!node.IsDefined()) return false;
  if (!node.IsSequence() || node.size() != 2) {
    r.Error(node, key, "expected [from, to]");
    return false;
  }
  const auto a = r.Number(node[0], Index(key, 0)), b = r.Number(node[1], Index(key, 1));
  if (!a || !b) return false;
  if (*a == *b) {
    r.Error(node, key, "from and to must differ");
    return false;
  }
  *from = *a;
  *to = *b;
  return true;
}

// The precision points: `points: n` (spaced by the synthesis) or `at: [x, ...]` (inside the x
// range when that was read), not both.
void ReadFunctionPrecisionPoints(YamlReader& r, const YAML::Node& root, bool ranges, FunctionRequest* q) {
  const YAML::Node points = root["points"], at = root["at"];
  if (points.IsDefined() && at.IsDefined()) r.Error(at, "at", "give points or at, not both");
  if (points.IsDefined()) {
    if (const auto n = r.Count(points, "points")) {
      if (*n < 3 || *n > 1000) r.Error(points, "points", "expected 3 to 1000 precision points");
      q->points = *n;
    }
  }
  if (at.IsDefined() && r.ExpectSequence(at, "at")) {
    if (at.size() < 3 || at.size() > 1000) r.Error(at, "at", "expected 3 to 1000 precision points");
    for (size_t i = 0; i < at.size(); ++i) {
      const auto x = r.Number(at[i], Index("at", static_cast<int>(i)));
      if (!x) continue;
      if (ranges && (*x < std::min(q->x_from, q->x_to) || *x > std::max(q->x_from, q->x_to)))
        r.Error(at[i], Index("at", static_cast<int>(i)), fmt::format("x = {} lies outside x: [{}, {}]", *x, q->x_from, q->x_to));
      q->at.push_back(*x);
    }
  }
}

// The formula must evaluate (x defined) at both ends of the x range and at the precision points:
// the first x where it does not is reported at the function's line.
void CheckFunctionFormulaEvaluates(YamlReader& r, const YAML::Node& function, const std::string& formula, const FunctionRequest& q) {
  std::vector<double> xs = {q.x_from, q.x_to};
  xs.insert(xs.end(), q.at.begin(), q.at.end());
  for (double x : xs) {
    ParameterSet p;
    p.DefineValue("x", x);
    if (const Expected<double> v = p.Evaluate(formula); !v) {
      r.Error(function, "function", fmt::format("cannot evaluate at x = {}: {}", x, v.error()));
      break;
    }
  }
}

}  // namespace

MotionSpecFile ReadMotionSpec(const std::string& path) { return ParseMotionSpecText(ReadInputText(path), path); }

MotionSpecFile ParseMotionSpecText(const std::string& text, const std::string& path) {
  const YAML::Node root = ParseYamlText(text, path);
  MotionSpecFile spec;
  spec.path = path;
  YamlReader r(path, nullptr);
  r.set_fallback(YAML::Mark());
  if (!r.ExpectMap(root, "")) throw InputError(r.diagnostics());
  r.CheckKeys(root, "", {"poses"});
  const YAML::Node poses = r.Require(root, "poses", "");
  if (poses.IsDefined() && r.ExpectSequence(poses, "poses")) {
    if (poses.size() < 2 || poses.size() > 5) r.Error(poses, "poses", fmt::format("expected 2 to 5 poses, found {}", poses.size()));
    std::vector<int> node_of;  // the list entry of each pose read (a malformed entry is skipped)
    for (size_t i = 0; i < poses.size(); ++i) {
      const std::string p = Index("poses", static_cast<int>(i));
      if (!poses[i].IsSequence() || poses[i].size() != 3) {
        r.Error(poses[i], p, "expected [x, y, angle_deg]");
        continue;
      }
      const auto x = r.Number(poses[i][0], Index(p, 0)), y = r.Number(poses[i][1], Index(p, 1)), a = r.Number(poses[i][2], Index(p, 2));
      if (x && y && a) {
        spec.poses.push_back({{*x, *y}, DegToRad(*a)});
        node_of.push_back(static_cast<int>(i));
      }
    }
    // two equal poses give no condition
    for (size_t i = 0; i < spec.poses.size(); ++i) {
      for (size_t j = i + 1; j < spec.poses.size(); ++j) {
        if ((spec.poses[i].point - spec.poses[j].point).norm() == 0 && AngleDifference(spec.poses[i].angle, spec.poses[j].angle) == 0)
          r.Error(poses[node_of[j]], Index("poses", node_of[j]), fmt::format("repeats pose {}", node_of[i] + 1));
      }
    }
  }
  if (!r.diagnostics().empty()) throw InputError(r.diagnostics());
  return spec;
}

FunctionSpecFile ReadFunctionSpec(const std::string& path) { return ParseFunctionSpecText(ReadInputText(path), path); }

FunctionSpecFile ParseFunctionSpecText(const std::string& text, const std::string& path) {
  const YAML::Node root = ParseYamlText(text, path);
  FunctionSpecFile spec;
  spec.path = path;
  YamlReader r(path, nullptr);
  r.set_fallback(YAML::Mark());
  if (!r.ExpectMap(root, "")) throw InputError(r.diagnostics());
  r.CheckKeys(root, "", {"type", "function", "x", "input", "output", "points", "at", "frame"});
  FunctionRequest& q = spec.request;
  if (const YAML::Node type = root["type"]; type.IsDefined()) {
    const std::string t = r.Text(type, "type").value_or("");
    if (t == "four-bar") q.type = FunctionGenerator::kFourBar;
    else if (t == "slider-crank") q.type = FunctionGenerator::kSliderCrank;
    else r.Error(type, "type", "expected four-bar or slider-crank, found '" + t + "'");
  }
  const YAML::Node function = r.Require(root, "function", "");
  if (function.IsDefined()) spec.formula = r.Text(function, "function").value_or("");
  // an empty formula ('' or "  ") is reported here, at its line, not later without one
  if (function.IsDefined() && function.IsScalar() && spec.formula.find_first_not_of(" \t") == std::string::npos)
    r.Error(function, "function", "expected a formula of x, e.g. 'log10(x)', found an empty text");
  const bool ranges = Range(r, r.Require(root, "x", ""), "x", &q.x_from, &q.x_to) &
                      Range(r, r.Require(root, "input", ""), "input", &q.input_from, &q.input_to) &
                      Range(r, r.Require(root, "output", ""), "output", &q.output_from, &q.output_to);
  q.input_from = DegToRad(q.input_from);
  q.input_to = DegToRad(q.input_to);
  if (q.type == FunctionGenerator::kFourBar) {
    q.output_from = DegToRad(q.output_from);
    q.output_to = DegToRad(q.output_to);
  }
  ReadFunctionPrecisionPoints(r, root, ranges, &q);
  if (const YAML::Node frame = root["frame"]; frame.IsDefined()) {
    if (q.type == FunctionGenerator::kSliderCrank) r.Error(frame, "frame", "a slider-crank has no frame length (its slide is the frame)");
    if (const auto f = r.Number(frame, "frame")) {
      if (!(*f > 0)) r.Error(frame, "frame", "expected a positive length");
      q.frame = *f;
    }
  }
  // the formula: evaluated with x defined, at both ends and at the precision points
  const std::string formula = spec.formula;
  q.function = [formula](double x, double* y) {
    ParameterSet p;
    p.DefineValue("x", x);
    const Expected<double> v = p.Evaluate(formula);
    if (!v) return false;
    *y = *v;
    return true;
  };
  // an empty formula is reported above
  if (function.IsDefined() && ranges && formula.find_first_not_of(" \t") != std::string::npos) CheckFunctionFormulaEvaluates(r, function, formula, q);
  if (!r.diagnostics().empty()) throw InputError(r.diagnostics());
  return spec;
}

}  // namespace koppel
