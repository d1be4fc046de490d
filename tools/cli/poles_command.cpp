// koppel poles: the instant centres of every pair of links at one input (Aronhold–Kennedy), or
// with --centrode LINK the fixed and moving centrodes of a link over a range.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

namespace koppel::cli {
namespace poles_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, at, centrode, reference, from, to, step = "1";
  std::vector<std::string> sets;
  std::string format = "csv", out;
};

std::string Number(const std::optional<double>& v) { return v ? FormatNumber(*v) : ""; }

const char* Kind(const InstantCentreEntry& c) {
  if (!c.defined) return "undefined";
  if (c.at_infinity) return "infinity";
  return c.from_acceleration ? "acceleration" : "finite";
}

void RunPoles(const Args& args, const Model& model, double at) {
  const PolesReport r = Checked([&] { return model.Poles(at); });
  if (args.format == "json") {
    nlohmann::json centres = nlohmann::json::array();
    for (const InstantCentreEntry& c : r.centres) {
      nlohmann::json e = {{"link_a", c.link_a}, {"link_b", c.link_b}, {"kind", Kind(c)}};
      const bool finite = c.defined && !c.at_infinity;
      e["pole_x"] = finite ? nlohmann::json(c.position.x) : nlohmann::json(nullptr);
      e["pole_y"] = finite ? nlohmann::json(c.position.y) : nlohmann::json(nullptr);
      e["direction_x"] = c.at_infinity ? nlohmann::json(c.direction.x) : nlohmann::json(nullptr);
      e["direction_y"] = c.at_infinity ? nlohmann::json(c.direction.y) : nlohmann::json(nullptr);
      centres.push_back(e);
    }
    nlohmann::json j = {{"mechanism", model.name()}, {model.input_name(), r.input}, {"status", ToString(r.status)}, {"poles", centres}};
    if (!r.message.empty()) j["message"] = r.message;
    WriteOutput(args.out, JsonText(j));
  } else {
    std::string csv = "link_a,link_b,kind,pole_x,pole_y,direction_x,direction_y\n";
    for (const InstantCentreEntry& c : r.centres) {
      const bool finite = c.defined && !c.at_infinity;
      csv += CsvField(c.link_a) + "," + CsvField(c.link_b) + "," + Kind(c) + "," + (finite ? FormatNumber(c.position.x) + "," + FormatNumber(c.position.y) : ",") +
             "," + (c.at_infinity ? FormatNumber(c.direction.x) + "," + FormatNumber(c.direction.y) : ",") + "\n";
    }
    WriteOutput(args.out, csv);
  }
  if (!r.message.empty()) Complain(args.file + ": " + r.message);
  if (r.status != AnalysisStatus::kComplete) throw Exit{kExitFailed};
}

void RunCentrodes(const Args& args, const Model& model, double at) {
  const double from = args.from.empty() ? model.sweep_from() : ParseNumberFlag("--from", args.from);
  const double to = args.to.empty() ? model.sweep_to() : ParseNumberFlag("--to", args.to);
  const double step = ParseNumberFlag("--step", args.step);
  CheckSampleCount(from, to, step, "--from/--to/--step");
  const CentrodesReport r = Checked([&] { return model.Centrodes(args.centrode, args.reference, from, to, step, at); });
  const std::vector<std::string> columns = {model.input_name(), "fixed_x", "fixed_y", "moving_x", "moving_y", "moving_at_x", "moving_at_y"};
  auto cells = [&](size_t i) {
    std::vector<std::optional<double>> row = {r.inputs[i]};
    for (const auto* curve : {&r.fixed, &r.moving, &r.moving_at}) {
      const auto& p = (*curve)[i];
      row.push_back(p ? std::optional<double>(p->x) : std::nullopt);
      row.push_back(p ? std::optional<double>(p->y) : std::nullopt);
    }
    return row;
  };
  if (args.format == "json") {
    nlohmann::json rows = nlohmann::json::array();
    for (size_t i = 0; i < r.inputs.size(); ++i) {
      nlohmann::json row = nlohmann::json::array();
      for (const auto& v : cells(i)) row.push_back(v ? nlohmann::json(*v) : nlohmann::json(nullptr));
      rows.push_back(row);
    }
    nlohmann::json j = {{"mechanism", model.name()}, {"link", r.link}, {"reference", r.reference}, {"at", at},
                        {"status", ToString(r.status)}, {"columns", columns}, {"rows", rows}};
    if (!r.message.empty()) j["message"] = r.message;
    WriteOutput(args.out, JsonText(j));
  } else {
    std::string csv = CsvLine(columns);
    for (size_t i = 0; i < r.inputs.size(); ++i) {
      const auto row = cells(i);
      for (size_t c = 0; c < row.size(); ++c) csv += (c ? "," : "") + Number(row[c]);
      csv += "\n";
    }
    WriteOutput(args.out, csv);
  }
  if (!r.message.empty()) Complain(args.file + ": " + r.message);
  if (r.status != AnalysisStatus::kComplete) throw Exit{kExitFailed};
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const double at = ParseNumberFlag("--at", args.at);
  const Model model = LoadModel(args.file, args.sets);
  if (args.centrode.empty()) {
    if (!args.reference.empty() || !args.from.empty() || !args.to.empty()) {
      Complain("--reference, --from and --to belong to --centrode");
      throw Exit{kExitBadInput};
    }
    RunPoles(args, model, at);
  } else {
    RunCentrodes(args, model, at);
  }
}

}  // namespace
}  // namespace poles_command

void AddPolesCommand(CLI::App& app) {
  using namespace poles_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "poles",
      "Instant centres (Momentanpole) of every pair of links at one input: the point where the two links\n"
      "have the same velocity, from the exact first-order transfer functions. Any three lie on one line\n"
      "(Aronhold-Kennedy). Columns: link_a, link_b, kind (finite; infinity: the links translate relative to\n"
      "each other, the pole lies at infinity in direction_x/_y; acceleration: their relative motion stands\n"
      "still, e.g. a rocker at its dead centre, and the pole is that of the accelerations; undefined), pole_x,\n"
      "pole_y. With --centrode LINK: the centrodes (Polbahnen) of LINK against --reference (default: the\n"
      "frame) over --from/--to/--step: the fixed centrode (fixed_x/_y, in the reference link's frame), the\n"
      "moving centrode (moving_x/_y, in LINK's own frame) and the moving centrode carried to the pose at\n"
      "--at (moving_at_x/_y), where it touches the fixed one at the pole; empty cells where the pole is at\n"
      "infinity. Exit 1 where a pole is undefined or part of the range is not reached.\n"
      "Example: koppel poles catalog/entries/mzc-crank-rocker.yaml --at 180\n"
      "Example: koppel poles catalog/entries/mzc-crank-rocker.yaml --at 180 --centrode coupler --step 2");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--at", args->at, "The input (deg for an R drive)")->required();
  cmd->add_option("--centrode", args->centrode, "Print the centrodes of this link instead");
  cmd->add_option("--reference", args->reference, "The centrodes against this link (default: the frame)");
  cmd->add_option("--from", args->from, "Centrodes from this input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Centrodes up to this input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Centrode step (default 1)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
