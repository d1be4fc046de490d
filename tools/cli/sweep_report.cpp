#include "sweep_report.hpp"

#include "common.hpp"

#include <fmt/core.h>

namespace koppel::cli {
namespace sweep_report {  // this file's own names, apart from the other commands' in a unity build
namespace {

std::string Describe(const Model& model, const SingularPosition& p) {
  std::string names;
  for (const std::string& j : p.joints) names += (names.empty() ? "" : ", ") + j;
  const bool limit = p.kind == "limit";
  const char* what = limit ? "singular position: limit point (dead centre of the drive)"
                           : "singular position: branch point (two branches cross)";
  std::string text = std::string(what) + " at " + FormatInput(model, p.input) + " (joints " + names +
                     fmt::format("; reciprocal condition of the Jacobian {:.3g})", p.rcond);
  if (limit) return text + ": the drive cannot pass it on this branch";
  if (p.action == "stop") return text + ": the sweep stops there";
  if (p.action == "switch") return text + ": switched to the other branch (--at-branch-point switch)";
  return text + ": continued on the branch that continues the incoming one";
}

// "N rows at singular poses (phi = a, b, ... deg), flagged ...": at most eight inputs named.
std::string FlaggedRows(const std::string& input_name, bool angle, const std::vector<double>& shown_inputs) {
  std::string flagged;
  int count = 0;
  for (double input : shown_inputs) {
    if (++count <= 8) flagged += (flagged.empty() ? "" : ", ") + FormatNumber(input);
  }
  return std::to_string(count) + " row" + (count > 1 ? "s" : "") + " at singular poses (" + input_name + " = " + flagged +
         (count > 8 ? ", ..." : "") + (angle ? " deg" : "") +
         "), flagged in the 'singular' column: their transfer functions up to 3rd order are the branch's limits "
         "there, higher orders are left empty";
}

}  // namespace
}  // namespace sweep_report

void AddBranchPointOption(CLI::App* command, std::string& value) {
  command->add_option("--at-branch-point", value,
                      "Where two branches cross (change point of a Grashof-neutral linkage, a loop folding flat):\n"
                      "continue (default) on the branch that continues the incoming one analytically, stop there, or\n"
                      "switch to the other branch");
}

AtBranchPoint ParseBranchPointFlag(const std::string& text) {
  try {
    return ParseAtBranchPoint(text);  // the words are the library's (koppel/api/model.hpp)
  } catch (const InputError&) {
    Complain("--at-branch-point must be continue, stop or switch, not '" + text + "'");
    throw Exit{kExitBadInput};
  }
}

std::string FormatInput(const Model& model, double shown) {
  return model.input_name() + " = " + FormatNumber(shown) + (model.input_is_angle() ? " deg" : "");
}

void ReportSingularPoints(const std::string& file, const Model& model, const std::vector<SingularPosition>& points) {
  using namespace sweep_report;
  for (const SingularPosition& p : points) Complain(file + ": " + Describe(model, p));
}

void ReportSweep(const std::string& file, const Model& model, const SweepRecord& sweep) {
  using namespace sweep_report;
  for (const std::string& note : sweep.notes) Complain(file + ": " + note);
  ReportSingularPoints(file, model, sweep.singular_points);
  if (!sweep.singular_inputs.empty()) {
    Complain(file + ": " + FlaggedRows(model.input_name(), model.input_is_angle(), sweep.singular_inputs));
  }
  if (!sweep.complete() && !sweep.message.empty()) Complain(file + ": " + sweep.message);
}

nlohmann::json SingularPointsJson(const std::vector<SingularPosition>& points) {
  nlohmann::json list = nlohmann::json::array();
  for (const SingularPosition& p : points) {
    nlohmann::json entry = {{"input", p.input}, {"kind", p.kind}, {"joints", p.joints}, {"rcond", p.rcond}};
    if (p.kind == "branch-point") entry["action"] = p.action;
    list.push_back(entry);
  }
  return list;
}

nlohmann::json SweepEventsJson(const SweepRecord& sweep) {
  nlohmann::json gaps = nlohmann::json::array();
  for (const InputGap& g : sweep.gaps) gaps.push_back({{"from", g.from}, {"to", g.to}});
  return {{"singular_points", SingularPointsJson(sweep.singular_points)},
          {"gaps", gaps},
          {"notes", sweep.notes},
          {"reached", {{"from", sweep.reached.from}, {"to", sweep.reached.to}}}};
}

}  // namespace koppel::cli
