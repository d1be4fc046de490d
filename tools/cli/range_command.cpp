// koppel range: the intervals of the drive input over which the mechanism assembles, per branch.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/model.hpp"

namespace koppel::cli {
namespace range_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, at_branch_point, format = "csv", out;
  std::vector<std::string> sets;
  bool all_branches = false;
};

std::string Json(const Model& model, const Ranges& ranges) {
  nlohmann::json branches = nlohmann::json::array();
  for (const BranchInterval& b : ranges.branches) {
    nlohmann::json entry = {{"branch", b.branch},       {"from", b.from},       {"to", b.to},
                            {"from_kind", b.from_kind}, {"to_kind", b.to_kind}, {"singular_points", SingularPointsJson(b.singular_points)}};
    if (b.period > 0) entry["period"] = b.period;
    if (!b.message.empty()) entry["message"] = b.message;
    branches.push_back(entry);
  }
  const nlohmann::json j = {{"mechanism", model.mechanism().name}, {"input", model.input_name()},
                            {"unit", model.input_is_angle() ? "deg" : model.length_unit()}, {"branches", branches},
                            {"notes", ranges.notes}};
  return JsonText(j);
}

std::string Csv(const Ranges& ranges) {
  std::string csv = "branch,from,to,from_kind,to_kind\n";
  for (const BranchInterval& b : ranges.branches) {
    csv += std::to_string(b.branch) + "," + FormatNumber(b.from) + "," + FormatNumber(b.to) + "," + b.from_kind + "," + b.to_kind + "\n";
  }
  return csv;
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  const AtBranchPoint action = ParseBranchPointFlag(args.at_branch_point);
  const Ranges ranges = Checked([&] { return model.DrivableRanges(args.all_branches, action); });
  for (const std::string& note : ranges.notes) Complain(args.file + ": " + note);
  if (!ranges.walked) {
    Complain(args.file + ": " + ranges.message);
    throw Exit{kExitFailed};
  }
  WriteOutput(args.out, args.format == "json" ? Json(model, ranges) : Csv(ranges));
  for (const BranchInterval& b : ranges.branches) {
    ReportSingularPoints(args.file + " (branch " + std::to_string(b.branch) + ")", model, b.singular_points);
    if (!b.message.empty()) Complain(args.file + " (branch " + std::to_string(b.branch) + "): " + b.message);
  }
  if (ranges.status != AnalysisStatus::kComplete) throw Exit{kExitFailed};
}

}  // namespace
}  // namespace range_command

void AddRangeCommand(CLI::App& app) {
  using namespace range_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "range",
      "Drivable ranges: for the assembly branch the file's hint chooses (and with --all-branches for every branch\n"
      "koppel finds from seeded random starting guesses), the interval of the input over which the mechanism\n"
      "assembles. CSV columns: branch,from,to,from_kind,to_kind (inputs in degrees for an R drive, length for a P\n"
      "drive). Kinds: limit (a limit point: dead centre of the drive), branch-point (only with --at-branch-point\n"
      "stop), full-turn (the drive turns fully; from 0 to the period after which the pose repeats, 360 or a\n"
      "multiple), bound (the search bound: 4 turns, or 100 length scales for a P drive), failed (exit 1).\n"
      "Singular points met are listed on stderr.\n"
      "Example: koppel range catalog/entries/mzc-crank-rocker.yaml --all-branches");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_flag("--all-branches", args->all_branches, "Every assembly branch koppel can find, not only the hint's");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
