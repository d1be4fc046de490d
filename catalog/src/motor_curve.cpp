#include "koppel/catalog/motor_curve.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/expression.hpp"
#include "koppel/core/limits.hpp"
#include "input_file.hpp"
#include "text_lines.hpp"

#include <cctype>

namespace koppel {
namespace {


}  // namespace

MotorCurveFile ReadMotorCurve(const std::string& path) { return ParseMotorCurveText(ReadInputText(path), path); }

MotorCurveFile ParseMotorCurveText(const std::string& text, const std::string& path) {
  MotorCurveFile curve;
  std::vector<Diagnostic> problems;
  auto problem = [&](int line, int column, const std::string& message) { problems.push_back(Diagnostic{path, line, column, "", message}); };
  const ParameterSet no_parameters;
  bool first = true;
  for (const TextLine& line : SplitLines(text)) {
    if (problems.size() > kMaxReportedProblems) break;
    const std::vector<TextField> fields = SplitFields(line.text, ',');
    const bool blank = fields.size() == 1 && fields[0].text.empty();
    if (blank || fields[0].text.rfind('#', 0) == 0) continue;
    // a header names the columns: its first field starts with a letter
    const bool header = first && std::isalpha(static_cast<unsigned char>(fields[0].text[0]));
    first = false;
    if (header) continue;
    if (fields.size() != 2) {
      problem(line.number, 1, "expected 'speed,torque', found " + std::to_string(fields.size()) + " fields in '" + line.text +
                                  "' (a decimal comma? write 2.6)");
      continue;
    }
    const Expected<double> speed = no_parameters.Evaluate(fields[0].text), torque = no_parameters.Evaluate(fields[1].text);
    if (!speed) problem(line.number, fields[0].column, "speed: " + speed.error());
    if (!torque) problem(line.number, fields[1].column, "torque: " + torque.error());
    if (!speed || !torque) continue;
    if (curve.speeds.size() == kMaxMotorCurvePoints) {
      problem(line.number, 1, "more than " + std::to_string(kMaxMotorCurvePoints) + " points (kMaxMotorCurvePoints)");
      break;
    }
    curve.speeds.push_back(*speed);
    curve.torques.push_back(*torque);
  }
  if (problems.empty() && curve.speeds.empty()) problem(0, 0, "no 'speed,torque' line: the motor curve is empty");
  if (!problems.empty()) throw InputError(problems);
  return curve;
}

}  // namespace koppel
