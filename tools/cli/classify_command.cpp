// koppel classify: mobility, drive rotation and the Grashof type of four-bars and slider-cranks.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/api/classification.hpp"

#include <array>

namespace koppel::cli {
namespace classify_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, format = "csv", out;
  std::vector<std::string> sets;
};

// A quantity,value,unit table whose values may be words.
struct Rows {
  std::vector<std::array<std::string, 3>> rows;
  void Add(const std::string& quantity, const std::string& value, const std::string& unit) { rows.push_back({quantity, value, unit}); }
  std::string ToCsv() const {
    std::string csv = "quantity,value,unit\n";
    for (const auto& r : rows) csv += CsvLine({r[0], r[1], r[2]});
    return csv;
  }
};

void Run(const Args& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  const ModelClassification c = ClassifyModel(model);
  Rows rows;
  nlohmann::json j = nlohmann::json::object();
  auto add_number = [&](const std::string& q, double v, const std::string& unit) {
    rows.Add(q, FormatNumber(v), unit);
    j[q] = {{"value", v}, {"unit", unit}};
  };
  auto add_word = [&](const std::string& q, const std::string& v) {
    rows.Add(q, v, "");
    j[q] = {{"value", v}, {"unit", ""}};
  };
  add_number("mobility", c.mobility, "1");
  if (c.assembled) add_number("rank_mobility", c.rank_mobility, "1");
  add_word("drive_rotation", c.drive_rotation);
  if (!c.grashof.empty()) {
    add_word("grashof", c.grashof);
    for (const auto& [name, value] : c.lengths) add_number(name, value, model.length_unit());
    add_word("grashof_rule", c.rule);
  }
  WriteOutput(args.out, args.format == "json" ? JsonText(j) : rows.ToCsv());
  for (const std::string& note : c.notes) Complain(args.file + ": " + note);
  if (!c.assembled) {
    Complain(args.file + ": the mechanism cannot be assembled at its hint: no rank mobility or drive rotation");
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace classify_command

void AddClassifyCommand(CLI::App& app) {
  using namespace classify_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "classify",
      "Classification as quantity,value,unit rows: mobility (Grübler–Kutzbach count 3(n-1) - 2j), rank_mobility\n"
      "(n - rank of the joint equations at the assembly pose), drive_rotation (full: the drive comes round to the\n"
      "same pose; limited), and for four-bars and slider-cranks grashof with the lengths and the inequality it rests\n"
      "on: four-bar s + l < p + q: crank-rocker (shortest link adjacent to the frame), double-crank (shortest is the\n"
      "frame), double-rocker (shortest is the coupler); s + l > p + q: triple-rocker; s + l = p + q: change-point.\n"
      "Slider-crank (slide on the frame), crank a, coupler b, offset e: a + |e| < b crank-slider, > rocker-slider,\n"
      "= change-point. Equality to 1e-9 of the mechanism's size.\n"
      "A mechanism whose mobility is not 1 (one drive) is bad input (exit 2) for every command.\n"
      "Example: koppel classify catalog/entries/mzc-crank-rocker.yaml");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
