// koppel analyze: a sweep of the drive with every declared output and its transfer functions.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/model.hpp"
#include "koppel/core/number_text.hpp"

#include <fmt/core.h>

#include <cmath>
#include <optional>

namespace koppel::cli {
namespace analyze_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct AnalyzeArgs {
  std::string file;
  std::string from, to, step, at, at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv";
  std::string out;
  int order = 2;
};

// The table of a sweep (koppel/api/model.hpp, SweepTable), written row by row as the API makes
// the rows: the input, every output's derivatives 0..order, and the singular flag. A transfer
// function that cannot be computed at a row (above the row's valid order, or not defined there:
// an output that is not differentiable) is NaN in the table: empty in CSV, null in JSON, never a number.
void AppendCsvHeader(std::string& out, const SweepTable& t) { out += CsvLine(t.columns); }

// The row is written in place at the end of `out` (room for every cell, then cut to length):
// one resize a row instead of an append a cell, for analyze's millions of cells.
void AppendCsvRow(std::string& out, const SweepTable& t, const double* row) {
  const size_t width = t.columns.size(), start = out.size();
  out.resize(start + width * (kG12Chars + 1) + 1);
  char* end = WriteNumber(out.data() + start, row[0]);
  for (size_t c = 1; c + 1 < width; ++c) {
    *end++ = ',';
    if (!std::isnan(row[c])) end = WriteNumber(end, row[c]);
  }
  *end++ = ',';
  *end++ = row[width - 1] != 0 ? '1' : '0';
  *end++ = '\n';
  out.resize(static_cast<size_t>(end - out.data()));
}

nlohmann::json JsonRow(const SweepTable& t, const double* values) {
  const size_t width = t.columns.size();
  nlohmann::json row = nlohmann::json::array();
  row.push_back(values[0]);
  for (size_t c = 1; c + 1 < width; ++c) {
    if (std::isnan(values[c])) {
      row.push_back(nullptr);
    } else {
      FormatNumber(values[c]);  // the same refusal of non-finite numbers as CSV
      row.push_back(values[c]);
    }
  }
  row.push_back(values[width - 1] != 0 ? 1 : 0);
  return row;
}

// The range from the flags, the file's sweep for what is not given (Model::Span), checked with
// the flags' names before anything is allocated.
SweepSpan SpanOf(const AnalyzeArgs& args, const Model& model) {
  // --at X: the one row at X, walked from the assembly as every sweep is (the same branch)
  const std::optional<double> at = OptionalNumberFlag("--at", args.at);
  const SweepSpan span = at ? model.Span(at, at, std::nullopt)
                            : model.Span(OptionalNumberFlag("--from", args.from), OptionalNumberFlag("--to", args.to),
                                         OptionalNumberFlag("--step", args.step));
  CheckSampleCount(span.from, span.to, span.step, "--from/--to/--step");
  if (args.order < 0 || args.order > kMaxTransferOrder) {
    Complain("--from/--to/--step/--order: the order must lie between 0 and " + std::to_string(kMaxTransferOrder));
    throw Exit{kExitBadInput};
  }
  return span;
}

void RunAnalyze(const AnalyzeArgs& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  const SweepSpan span = SpanOf(args, model);
  const AtBranchPoint action = ParseBranchPointFlag(args.at_branch_point);
  const bool csv = args.format == "csv";
  std::optional<StreamedOutput> csv_out;  // CSV goes out as it is made (the file appears whole at Finish)
  if (csv) csv_out.emplace(args.out);
  nlohmann::json rows = nlohmann::json::array();
  const SweepTable table = Checked([&] {
    return model.Sweep(span.from, span.to, span.step, args.order, action, [&](const SweepTable& t, int i, const double* row) {
      if (csv) {
        if (i == 0) AppendCsvHeader(csv_out->text(), t);
        AppendCsvRow(csv_out->text(), t, row);
        csv_out->Flush();
      } else {
        rows.push_back(JsonRow(t, row));
      }
    });
  });
  if (csv) {
    if (table.rows == 0) AppendCsvHeader(csv_out->text(), table);  // no row reached: the header alone
    csv_out->Finish();
  } else {
    nlohmann::json j = {{"columns", table.columns}, {"units", table.units}, {"rows", rows}};
    j["mechanism"] = model.mechanism().name;
    j["file"] = model.path();
    j["input"] = {{"name", model.input_name()}, {"unit", model.input_is_angle() ? "deg" : model.length_unit()},
                  {"from", span.from}, {"to", span.to}, {"step", span.step}};
    j["order"] = args.order;
    j["complete"] = table.status == AnalysisStatus::kComplete;
    j["status"] = table.sweep_status;
    j.update(SweepEventsJson(table.record));
    if (!table.message.empty()) j["message"] = table.message;
    WriteOutput(args.out, JsonText(j));
  }
  ReportSweep(args.file, model, table.record);
  if (!table.record.complete()) throw Exit{kExitFailed};
  // every sample there, but an output has no number in some cells (not differentiable there)
  if (table.status != AnalysisStatus::kComplete) {
    Complain(args.file + ": " + table.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace analyze_command

void AddAnalyzeCommand(CLI::App& app) {
  using namespace analyze_command;
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Sweep the drive and tabulate every output of the mechanism with its transfer functions.\n"
      "Columns: the input (degrees for an R drive, length for a P drive), then for each output NAME:\n"
      "NAME, NAME_d1, NAME_d2 ... (d_k = k-th derivative with respect to the input in radians, or in\n"
      "length units for a P drive); a point output K gives K_x, K_y and their derivatives. Angle\n"
      "outputs (R joints, links, directions, transmission angles) are printed in degrees; their\n"
      "derivatives in radians. Derivatives are exact (Taylor series through the constraint equations),\n"
      "not differences of positions. The last column, singular, is 1 where the pose is a singular\n"
      "position (reciprocal condition of the Jacobian below 1e-6): there the transfer functions up to 3rd\n"
      "order are the branch's limits and higher orders are left empty.\n"
      "The sweep starts at the file's `assembly` hint and follows that branch outward to both ends of the\n"
      "range: through branch points (see --at-branch-point), up to limit points (dead centres of the\n"
      "drive). It prints every row it reaches; when part of the range cannot be driven, it names the gaps\n"
      "and the singular points that bound them on stderr and exits 1.\n"
      "Example: koppel analyze catalog/entries/slider-crank-offset.yaml --set e=0 --step 5");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--from", args->from, "First input value [deg or length] (default: the file's sweep.from, else 0)");
  cmd->add_option("--to", args->to, "Last input value [deg or length] (default: the file's sweep.to, else 360)");
  CLI::Option* step = cmd->add_option("--step", args->step, "Input step [deg or length] (default: the file's sweep.step, else 1)");
  cmd->add_option("--at", args->at, "One row at this input [deg or length], on the branch the sweep follows (instead of\n"
                                    "--from/--to/--step)")
      ->excludes("--from")
      ->excludes("--to")
      ->excludes(step);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE (a formula; repeatable)");
  cmd->add_option("--order", args->order, fmt::format("Highest transfer-function order in the table, 0..{} (default 2)", kMaxTransferOrder));
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { RunAnalyze(*args); });
}

}  // namespace koppel::cli
