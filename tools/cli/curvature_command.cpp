// koppel curvature: the instantaneous geometry of the motion at one input (pole, pole tangent,
// inflection circle, Ball point) and the radius and centre of curvature of a point's path.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include <optional>

namespace koppel::cli {
namespace curvature_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, point, at;
  std::vector<std::string> sets;
  std::string format = "csv", out;
};

std::string Csv(const std::vector<NamedValue>& q) {
  std::string csv = "quantity,value,unit\n";
  for (const NamedValue& v : q) csv += CsvField(v.name) + "," + (v.value ? FormatNumber(*v.value) : "") + "," + CsvField(v.unit) + "\n";
  return csv;
}

std::string Json(const Model& model, const CurvatureReport& r, const std::vector<NamedValue>& q) {
  nlohmann::json j = {{"mechanism", model.name()}, {"point", r.point}, {"link", r.link}, {"status", ToString(r.status)}};
  nlohmann::json units = nlohmann::json::object();
  for (const NamedValue& v : q) {
    if (v.value) FormatNumber(*v.value);  // refuses a non-finite number, as the CSV does
    j[v.name] = v.value ? nlohmann::json(*v.value) : nlohmann::json(nullptr);
    units[v.name] = v.unit;
  }
  j["rho_infinite"] = r.curvature.has_value() && *r.curvature == 0.0;
  j["units"] = units;
  if (!r.message.empty()) j["message"] = r.message;
  return JsonText(j);
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const double at = ParseNumberFlag("--at", args.at);
  const Model model = LoadModel(args.file, args.sets);
  const CurvatureReport r = Checked([&] { return model.Curvature(args.point, at); });
  const std::vector<NamedValue> q = r.Quantities();
  WriteOutput(args.out, args.format == "json" ? Json(model, r, q) : Csv(q));
  if (!r.message.empty()) Complain(args.file + ": " + r.message);
  if (r.status != AnalysisStatus::kComplete) throw Exit{kExitFailed};
}

}  // namespace
}  // namespace curvature_command

void AddCurvatureCommand(CLI::App& app) {
  using namespace curvature_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "curvature",
      "The motion's geometry to second and third order at one input, for the link that carries --point,\n"
      "against the frame: the instant centre (pole_x, pole_y), the direction the pole moves along the fixed\n"
      "centrode (pole_direction_x/_y, the pole tangent), the inflection circle (Wendekreis: centre\n"
      "inflection_x/_y, inflection_diameter; inflection_pole_x/_y the Wendepol W opposite the pole), the\n"
      "Ball point (ball_x/_y, where it exists: a point of the inflection circle with stationary curvature),\n"
      "and for the point (POINT_x, POINT_y) its path's signed curvature (positive: turning counter-clockwise),\n"
      "radius rho and centre of curvature (centre_x/_y). All from the exact transfer functions to 3rd order.\n"
      "A point on the inflection circle has an inflection: curvature 0, rho and centre empty (JSON null,\n"
      "rho_infinite true). Quantities that do not exist here are empty and the exit code is 1 with the\n"
      "reason on stderr: a link that translates (its pole is at infinity), a point at the pole (a cusp).\n"
      "Columns: quantity,value,unit; --format json: one object with the same names.\n"
      "Example: koppel curvature catalog/entries/mzc-crank-rocker.yaml --point K --at 180");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--point", args->point, "The point: a point output (K), link.point, or a point name one link has")->required();
  cmd->add_option("--at", args->at, "The input (deg for an R drive)")->required();
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
