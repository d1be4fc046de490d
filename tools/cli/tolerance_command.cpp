// koppel tolerance: how far an output moves when the parts are made to tolerance and the pins have
// play: exact sensitivities, linear worst case and rss, shares, clearance, and a Monte Carlo run
// through the exact solver on every core.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include <fmt/core.h>

#include <cmath>
#include <iostream>
#include <unistd.h>

namespace koppel::cli {
namespace tolerance_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, output, at, from, to, step = "1", distribution = "uniform";
  std::vector<std::string> tols, clearances, sets;
  std::string samples = "0", seed = "1", threads = "0";
  bool quiet = false;
  std::string format = "csv", out;
};

// Monte Carlo work below this many solves finishes in a blink: no progress bar
constexpr double kProgressSolves = 2e5;

std::string Csv(const std::vector<std::string>& columns, const std::vector<std::vector<std::optional<double>>>& rows) {
  std::string csv = CsvLine(columns);
  for (const auto& row : rows) {
    for (size_t c = 0; c < row.size(); ++c) csv += (c ? "," : "") + (row[c] ? FormatNumber(*row[c]) : std::string());
    csv += "\n";
  }
  return csv;
}

std::string Json(const Model& model, const ToleranceResult& r, const std::vector<std::string>& columns,
                 const std::vector<std::vector<std::optional<double>>>& rows) {
  nlohmann::json tolerances = nlohmann::json::object(), clearances = nlohmann::json::object(), table = nlohmann::json::array();
  for (size_t j = 0; j < r.parameters.size(); ++j) tolerances[r.parameters[j]] = r.tolerances[j];
  for (size_t j = 0; j < r.joints.size(); ++j) clearances[r.joints[j]] = r.clearances[j];
  for (size_t i = 0; i < rows.size(); ++i) {
    nlohmann::json row = nlohmann::json::object();
    for (size_t c = 0; c < columns.size(); ++c) {
      if (rows[i][c]) FormatNumber(*rows[i][c]);  // the CSV's refusal of non-finite numbers
      const bool count = columns[c] == "mc_samples" || columns[c] == "mc_failed";
      if (!rows[i][c]) row[columns[c]] = nullptr;
      else if (count) row[columns[c]] = static_cast<long>(*rows[i][c]);
      else row[columns[c]] = *rows[i][c];
    }
    if (!r.rows[i].ok) row["message"] = r.rows[i].message;
    table.push_back(row);
  }
  nlohmann::json j = {{"mechanism", model.name()}, {"output", r.output}, {"unit", r.unit},
                      {"input_unit", r.input_unit}, {"tolerances", tolerances},
                      {"clearances", clearances}, {"distribution", r.distribution}, {"samples", r.samples},
                      {"seed", r.seed}, {"quantile_levels", r.quantile_levels}, {"status", ToString(r.status)}, {"rows", table}};
  if (!r.message.empty()) j["message"] = r.message;
  return JsonText(j);
}

std::vector<double> Inputs(const Args& args) {
  const bool range = !args.from.empty() || !args.to.empty();
  if (range == !args.at.empty()) {
    Complain("give either --at X or --from A --to B [--step S]");
    throw Exit{kExitBadInput};
  }
  if (!range) return {ParseNumberFlag("--at", args.at)};
  if (args.from.empty() || args.to.empty()) {
    Complain("--from and --to go together");
    throw Exit{kExitBadInput};
  }
  const double from = ParseNumberFlag("--from", args.from), to = ParseNumberFlag("--to", args.to), step = ParseNumberFlag("--step", args.step);
  CheckSampleCount(from, to, step, "--from/--to/--step");
  std::vector<double> inputs;
  const long n = static_cast<long>(std::floor(std::abs(to - from) / std::abs(step) + 1e-9)) + 1;
  for (long i = 0; i < n; ++i) inputs.push_back(from + i * (to >= from ? std::abs(step) : -std::abs(step)));
  return inputs;
}

void Run(const Args& args) {
  CheckFormat(args.format);
  ToleranceRequest request;
  request.output = args.output;
  request.inputs = Inputs(args);
  for (const std::string& t : args.tols) request.tolerances.push_back(NamedNumber("--tol", t));
  for (const std::string& c : args.clearances) request.clearances.push_back(NamedNumber("--clearance", c));
  request.samples = ParseCountFlag("--samples", args.samples, 0, kMaxToleranceSamples);
  CheckCount(static_cast<double>(request.samples) * static_cast<double>(request.inputs.size()), "--samples and the inputs",
             kToleranceValues);
  request.seed = static_cast<std::uint64_t>(ParseCountFlag("--seed", args.seed, 0, kMaxSeed));
  request.distribution = args.distribution;
  request.threads = static_cast<int>(ParseCountFlag("--threads", args.threads, 0, kMaxThreads));
  // a progress bar on a terminal when the run is long
  const bool bar = !args.quiet && isatty(STDERR_FILENO) && static_cast<double>(request.samples) * request.inputs.size() > kProgressSolves;
  if (bar) {
    request.progress = [](long done, long total) {
      const int width = 40, filled = static_cast<int>(width * done / std::max(1L, total));
      std::cerr << fmt::format("\rkoppel tolerance [{}{}] {}/{} samples", std::string(filled, '#'), std::string(width - filled, ' '), done, total)
                << std::flush;
    };
  }
  const Model model = LoadModel(args.file, args.sets);
  const ToleranceResult r = Checked([&] { return model.Tolerances(request); });
  if (bar) std::cerr << "\n";
  const std::vector<std::string> columns = r.Columns();
  std::vector<std::vector<std::optional<double>>> rows;
  for (size_t i = 0; i < r.rows.size(); ++i) rows.push_back(r.Row(i));
  WriteOutput(args.out, args.format == "json" ? Json(model, r, columns, rows) : Csv(columns, rows));
  for (const ToleranceRowReport& row : r.rows) {
    if (!row.ok) Complain(args.file + ": at " + FormatNumber(row.input) + ": " + row.message);
  }
  if (!r.message.empty()) Complain(args.file + ": " + r.message);
  if (r.status != AnalysisStatus::kComplete) throw Exit{kExitFailed};
}

}  // namespace
}  // namespace tolerance_command

void AddToleranceCommand(CLI::App& app) {
  using namespace tolerance_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "tolerance",
      "How far an output moves when the parameters are made to tolerance and the pins have play, per input:\n"
      "nominal; sens_NAME = d output / d NAME, exact (implicit-function theorem through the solver);\n"
      "worst_case = sum |sens| T; rss = sqrt(sum (sens T)^2); clearance_worst_case = sum c |d output / d pin\n"
      "offset| for revolute joints whose pin is free in a circle of radius c (sens_clearance_JOINT is that\n"
      "gradient's length); linear_std = the standard deviation the linear model predicts for the distribution\n"
      "(T/sqrt(3) uniform, T/3 normal, c/2 a pin); share_NAME / share_clearance_JOINT = each one's part of\n"
      "linear_std^2 (sum 1): tighten the largest first. With --samples N: a Monte Carlo run through the exact solver on every core (each\n"
      "parameter uniform in +-T, or normal with T = 3 sigma; each pin uniform in its circle), seeded: mc_min,\n"
      "mc_max, mc_mean, mc_std and the quantiles mc_q0.001 ... mc_q0.999; mc_failed counts samples that do\n"
      "not assemble at that input (then exit 1). Angles in degrees (an angle output's sensitivities in degrees\n"
      "per unit of the parameter). A progress bar on stderr when a long run writes to a terminal.\n"
      "Example: koppel tolerance catalog/entries/slider-crank-offset.yaml --output s --at 60 --tol l1=0.01\n"
      "         --tol l2=0.02 --tol e=0.005 --clearance A=0.003 --samples 20000 --seed 1");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--output", args->output, "The output: a scalar output (s) or a point's component (K_x, K_y)")->required();
  cmd->add_option("--at", args->at, "One input (deg for an R drive)");
  cmd->add_option("--from", args->from, "A range of inputs from this");
  cmd->add_option("--to", args->to, "... to this");
  cmd->add_option("--step", args->step, "... by this step (default 1)");
  cmd->add_option("--tol", args->tols, "A parameter's tolerance: NAME=T (+-T, the parameter's unit); repeat for several");
  cmd->add_option("--clearance", args->clearances, "A revolute joint's play: JOINT=c (the pin free in a circle of radius c); repeat");
  cmd->add_option("--samples", args->samples, "Monte Carlo samples (default 0: the linear analysis only; at most 1 000 000, and samples x inputs at most 10^8)");
  cmd->add_option("--seed", args->seed, "Monte Carlo seed, 0 to 2^53 (default 1); the result does not depend on the number of threads");
  cmd->add_option("--distribution", args->distribution, "uniform (default: +-T) or normal (T = 3 sigma)");
  cmd->add_option("--threads", args->threads, "Threads for the Monte Carlo run (default 0: every core; at most 256, kMaxThreads)");
  cmd->add_flag("--quiet", args->quiet, "No progress bar");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json (one object per input, with the same names)");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
