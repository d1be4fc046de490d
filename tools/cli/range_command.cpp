// koppel range: the intervals of the drive input over which the mechanism assembles, per branch.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/analysis/ranges.hpp"
#include "koppel/core/angles.hpp"

namespace koppel::cli {
namespace range_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, at_branch_point, format = "csv", out;
  std::vector<std::string> sets;
  bool all_branches = false;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  RangeOptions options;
  options.all_branches = args.all_branches;
  options.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  const RangeReport report = DrivableRanges(m, options);
  for (const std::string& note : report.notes) Complain(args.file + ": " + note);
  if (report.status != RangeStatus::kDone) {
    Complain(args.file + ": " + report.message);
    throw Exit{kExitFailed};
  }
  auto shown = [&](double v) { return m.InputIsAngle() ? RadToDeg(v) : v; };
  if (args.format == "json") {
    nlohmann::json branches = nlohmann::json::array();
    for (const BranchRange& b : report.branches) {
      nlohmann::json entry = {{"branch", b.branch},         {"from", shown(b.from)},         {"to", shown(b.to)},
                              {"from_kind", ToString(b.from_kind)}, {"to_kind", ToString(b.to_kind)},
                              {"singular_points", SingularPointsJson(m, b.singular_points)}};
      if (b.period > 0) entry["period"] = shown(b.period);
      if (!b.message.empty()) entry["message"] = b.message;
      branches.push_back(entry);
    }
    const nlohmann::json j = {{"mechanism", m.name}, {"input", m.drive.input_name}, {"unit", m.InputIsAngle() ? "deg" : file.loads.LengthUnit()},
                              {"branches", branches}, {"notes", report.notes}};
    WriteOutput(args.out, JsonText(j));
  } else {
    std::string csv = "branch,from,to,from_kind,to_kind\n";
    for (const BranchRange& b : report.branches) {
      csv += std::to_string(b.branch) + "," + FormatNumber(shown(b.from)) + "," + FormatNumber(shown(b.to)) + "," +
             ToString(b.from_kind) + "," + ToString(b.to_kind) + "\n";
    }
    WriteOutput(args.out, csv);
  }
  for (const BranchRange& b : report.branches) {
    ReportSingularPoints(args.file + " (branch " + std::to_string(b.branch) + ")", m, b.singular_points);
    if (!b.message.empty()) Complain(args.file + " (branch " + std::to_string(b.branch) + "): " + b.message);
  }
  if (report.HasFailure()) throw Exit{kExitFailed};
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
