// koppel synth: dead-centre synthesis, design charts, Meyer zur Capellen straight-line linkages
// and least-squares fitting (synth fit, in fit_command.cpp).
#include "commands.hpp"
#include "koppel/api/design_file.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/api/design_chart.hpp"
#include "koppel/api/synthesis.hpp"

#include <fmt/core.h>

#include <iostream>
#include <optional>

namespace koppel::cli {
namespace synth_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string type;
  std::string phi0, psi0, beta, lambda_cr, stroke, offset, frame = "1";
  std::string rocker_sense = "same";
  std::string lambda, kappa, diameter = "1";
  std::string out, yaml, cognates_dir;
  std::string format = "csv";
  std::string sense = "ccw";
  std::string units, design;
  bool quiet = false;
};

// "a:b:d" [deg] -> the chart's range; empty: `fallback` (the chart's default)
ChartRange Range(const std::string& flag, const std::string& text, const ChartRange& fallback) {
  if (text.empty()) return fallback;
  const auto c1 = text.find(':'), c2 = text.rfind(':');
  if (c1 == std::string::npos || c1 == c2) {
    Complain(flag + ": expected FROM:TO:STEP, found '" + text + "'");
    throw Exit{kExitBadInput};
  }
  const double a = ParseNumberFlag(flag, text.substr(0, c1)), b = ParseNumberFlag(flag, text.substr(c1 + 1, c2 - c1 - 1)),
               d = ParseNumberFlag(flag, text.substr(c2 + 1));
  if (d <= 0 || b < a) {
    Complain(flag + ": needs FROM <= TO and STEP > 0");
    throw Exit{kExitBadInput};
  }
  CheckSampleCount(a, b, d, flag + " FROM:TO:STEP", kChartCells);
  return {a, b, d};
}

double Required(const std::string& flag, const std::string& text) {
  if (text.empty()) {
    Complain(flag + " is required");
    throw Exit{kExitBadInput};
  }
  return ParseNumberFlag(flag, text);
}

// --rocker-sense: same | opposite (| both for the chart)
void CheckRockerSense(const std::string& text, bool allow_both) {
  if (text == "same" || text == "opposite" || (allow_both && text == "both")) return;
  Complain(std::string("--rocker-sense must be same") + (allow_both ? ", opposite or both" : " or opposite") + ", not '" + text + "'");
  throw Exit{kExitBadInput};
}

// A design's figures as the summary table; its mechanism file with -o.
void Emit(const Args& args, const Design& d) {
  if (!args.yaml.empty()) WriteOutput(args.yaml, d.yaml);
  Summary s;
  for (const DesignFigure& f : d.figures) s.Add(f.name, f.value, f.unit);
  WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
}

// A request the API refuses as malformed (InputError: a value out of its range): its reason on
// stderr as the command's other flag errors are said, exit 2.
template <class F>
auto Requested(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) Complain(d.message);
    throw Exit{kExitBadInput};
  }
}

// A refused design: the reason on stderr, exit 1 (a malformed request is InputError: exit 2).
void Refuse(const Design& d) {
  Complain(d.message);
  throw Exit{kExitFailed};
}

void RunCrankRocker(const Args& args, double phi0) {
  CrankRockerSpec spec;
  spec.phi0 = phi0;
  spec.psi0 = Required("--psi0", args.psi0);
  CheckRockerSense(args.rocker_sense, false);
  spec.same_sense = args.rocker_sense == "same";
  spec.frame = ParseNumberFlag("--frame", args.frame);
  if (args.sense != "ccw" && args.sense != "cw") {
    Complain("--sense must be ccw or cw");
    throw Exit{kExitBadInput};
  }
  spec.clockwise = args.sense == "cw";  // the written mechanism is the mirror image
  if (!args.beta.empty() && !args.lambda_cr.empty()) {
    Complain("give --beta or --lambda, not both");
    throw Exit{kExitBadInput};
  }
  spec.beta = OptionalNumberFlag("--beta", args.beta);
  spec.lambda = OptionalNumberFlag("--lambda", args.lambda_cr);
  spec.units = args.units;
  if (!args.design.empty()) spec.space = Checked([&] { return ReadDesignFile(args.design); });  // file:line, exit 2
  const Design d = Requested([&] { return SynthesiseCrankRocker(spec); });
  if (!d.ok()) Refuse(d);
  Emit(args, d);
}

void RunSliderCrank(const Args& args, double phi0) {
  SliderCrankSpec spec;
  spec.phi0 = phi0;
  spec.stroke = Required("--stroke", args.stroke);
  if (!args.offset.empty() && !args.beta.empty()) {
    Complain("give --offset or --beta, not both");
    throw Exit{kExitBadInput};
  }
  spec.offset = OptionalNumberFlag("--offset", args.offset);
  spec.beta = OptionalNumberFlag("--beta", args.beta);
  spec.units = args.units;
  if (!args.design.empty()) {
    Complain("--design: the design space is for four-bars (crank-rocker); a slider-crank's offset or beta chooses its design");
    throw Exit{kExitBadInput};
  }
  const Design d = Requested([&] { return SynthesiseSliderCrank(spec); });
  if (!d.ok()) Refuse(d);
  Emit(args, d);
}

void RunDeadCentre(const Args& args) {
  CheckFormat(args.format);
  const double phi0 = Required("--phi0", args.phi0);
  if (args.type == "crank-rocker") {
    RunCrankRocker(args, phi0);
  } else if (args.type == "slider-crank") {
    RunSliderCrank(args, phi0);
  } else {
    Complain("synth deadcentre: TYPE must be crank-rocker or slider-crank");
    throw Exit{kExitBadInput};
  }
}

std::string ChartCsv(const DesignChart& chart) {
  std::string out = CsvLine(chart.columns);
  for (const auto& row : chart.rows) {
    for (size_t i = 0; i < row.size(); ++i) out += (i ? "," : "") + (row[i].number ? FormatNumber(*row[i].number) : CsvField(row[i].word));
    out += "\n";
  }
  return out;
}

// {"columns", "rows"}: a number, a word, or null where no design exists
nlohmann::json ChartJson(const DesignChart& chart) {
  nlohmann::json rows_json = nlohmann::json::array();
  for (const auto& row : chart.rows) {
    nlohmann::json r = nlohmann::json::array();
    for (const ChartCell& c : row) {
      if (c.number) r.push_back(std::stod(FormatNumber(*c.number)));
      else if (!c.word.empty()) r.push_back(c.word);
      else r.push_back(nullptr);
    }
    rows_json.push_back(r);
  }
  return {{"columns", chart.columns}, {"rows", rows_json}};
}

void RunChart(const Args& args) {
  CheckFormat(args.format);
  if (args.type != "crank-rocker" && args.type != "slider-crank") {
    Complain("synth chart: TYPE must be crank-rocker or slider-crank");
    throw Exit{kExitBadInput};
  }
  ChartSpec spec = Checked([&] { return DefaultChart(args.type); });
  spec.phi0 = Range("--phi0", args.phi0, spec.phi0);
  if (args.type == "crank-rocker") {
    spec.psi0 = Range("--psi0", args.psi0, spec.psi0);
    CheckCount(Checked([&] { return spec.phi0.Count("phi0") * spec.psi0.Count("psi0"); }), "--phi0/--psi0 steps", kChartCells);
    CheckRockerSense(args.rocker_sense, true);
    spec.rocker_sense = args.rocker_sense;
  }
  if (!args.design.empty()) spec.space = Checked([&] { return ReadDesignFile(args.design); });  // file:line, exit 2
  const DesignChart chart = Requested([&] { return SynthesiseChart(spec); });
  if (!args.quiet) std::cerr << fmt::format("koppel synth chart: {} designs\n", chart.designs);
  WriteOutput(args.out, args.format == "json" ? JsonText(ChartJson(chart)) : ChartCsv(chart));
}

void RunMzc(const Args& args) {
  CheckFormat(args.format);
  MzcSpec spec;
  if (!args.kappa.empty()) spec.kappa = ParseNumberFlag("--kappa", args.kappa);
  else spec.lambda = Required("--lambda", args.lambda);
  spec.diameter = ParseNumberFlag("--D", args.diameter);
  spec.units = args.units;
  const Design d = Requested([&] { return SynthesiseMzc(spec); });
  if (!d.ok()) {
    Complain(d.message);
    throw Exit{kExitBadInput};
  }
  if (!args.cognates_dir.empty()) {
    const Design crank_rocker = MzcCrankRocker(d, args.units);
    if (crank_rocker.ok()) {
      MakeOutputDirectory(args.cognates_dir);
      WriteOutput(args.cognates_dir + "/" + crank_rocker.model->name() + ".yaml", crank_rocker.yaml);
    }
  }
  Emit(args, d);
}

}  // namespace
}  // namespace synth_command

// long: one flat list of the synth command's flags and subcommands in the order --help shows them
void AddSynthCommand(CLI::App& app) {
  using namespace synth_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("synth", "Synthesis: dead-centre synthesis, design charts, Meyer zur Capellen linkages, least-squares fitting.");
  cmd->require_subcommand(1);
  auto common = [&](CLI::App* sub) {
    sub->add_option("--format", args->format, "csv (default) or json");
    OutputFile(sub->add_option("--output-file", args->out, "Write the table to this file instead of stdout"));
  };

  CLI::App* dc = cmd->add_subcommand(
      "deadcentre",
      "Dead-centre synthesis (Totlagensynthese, as in 'Totlagensynthese der Kurbelschwinge'); every design is re-analysed by the solver before it is printed.\n"
      "crank-rocker: frame A0 = (0,0), B0 = (--frame, 0), crank A0A = l1, coupler AB = l2, rocker B0B = l3.\n"
      "  In the folded dead centre (innere Totlage, Decklage) the crank points away from B along the coupler; in the\n"
      "  extended one (aeussere Totlage, Strecklage) it points along the coupler towards B. phi0 is the angle the crank\n"
      "  turns, in its running sense, from the folded to the extended dead centre; psi0 the rocker's swing meanwhile.\n"
      "  --rocker-sense same (default, the document's definition): the rocker turns the same way as the crank from the\n"
      "  folded to the extended dead centre; opposite: the other way. phi0 may be any angle in (0, 360) deg for which a\n"
      "  crank-rocker exists. beta = angle B0 A0 B_a (B_a: B in the extended dead centre) must lie in the arc LE (printed as\n"
      "  beta_L .. beta_E); without --beta (or --lambda = l1/l2) beta maximises the smallest transmission angle mu_min.\n"
      "  The crank runs counter-clockwise (--sense ccw: B_a below A0B0 for the same sense, above for the opposite sense);\n"
      "  --sense cw writes the mirror image, the document's drawing (\"Drehrichtung mathematisch negativ\").\n"
      "  Exit 1, with the reason, when no crank-rocker exists, when beta lies outside the arc LE, or when mu_min keeps\n"
      "  growing towards a degenerate end of the arc (phi0 = 180 deg: crank and rocker shrink to nothing).\n"
      "  --design FILE.yaml (lengths, ratio, pivots, mu_min; A0 = (0,0), B0 = (--frame, 0)): the best mu_min inside that\n"
      "  design space (with --beta or --lambda: that design, refused when outside); exit 1 naming the constraint when none is.\n"
      "slider-crank: the conventions of 'Ebene Schubkurbel' (A0 = (0, -e), slide along x). phi0 from the folded to the extended dead centre\n"
      "  (90 < phi0 < 270 deg; phi0 > 180 puts A0 above the slide line, e < 0), the stroke s0 between them, and the offset\n"
      "  |e| (--offset) or beta (angle between the slide line and A0B_a), each within the range that gives a crank; by\n"
      "  default the offset that maximises mu_min. phi0 = 180 deg (centric) has no best design.\n"
      "Examples: koppel synth deadcentre crank-rocker --phi0 164 --psi0 60 -o mech.yaml\n"
      "          koppel synth deadcentre slider-crank --phi0 200 --stroke 100 --units mm -o slider.yaml");
  dc->add_option("type", args->type, "crank-rocker or slider-crank")->required();
  dc->add_option("--phi0", args->phi0, "Crank angle from the folded to the extended dead centre [deg]")->required();
  dc->add_option("--psi0", args->psi0, "Rocker swing angle [deg] (crank-rocker)");
  dc->add_option("--rocker-sense", args->rocker_sense, "same (default: the document's) or opposite: the rocker's sense against the crank's\n"
                                                       "from the folded to the extended dead centre (crank-rocker)");
  dc->add_option("--beta", args->beta, "crank-rocker: angle B0 A0 B_a; slider-crank: angle between the slide line and A0B_a\n"
                                       "[deg] (default: best mu_min)");
  dc->add_option("--lambda", args->lambda_cr, "crank-rocker: l1/l2 in (0, 1) instead of beta (default: best mu_min)");
  dc->add_option("--frame", args->frame, "Frame length A0B0 (crank-rocker, default 1)");
  dc->add_option("--design", args->design, "crank-rocker: the design space, a YAML file (lengths, ratio, pivots, mu_min)");
  dc->add_option("--sense", args->sense, "ccw (default) or cw: the sense the crank runs in the written mechanism\n"
                                         "(cw is the mirror image, the document's 'mathematisch negativ')");
  dc->add_option("--stroke", args->stroke, "Stroke s0 (slider-crank)");
  dc->add_option("--offset", args->offset, "Offset |e| (slider-crank; default: best mu_min)");
  OutputFile(dc->add_option("-o,--yaml", args->yaml, "Write the mechanism as a YAML file"));
  dc->add_option("--units", args->units, "The designed mechanism's length unit: its file says `units: {length: UNIT}` and the\n"
                                         "table labels its lengths with it (m, dm, cm, mm, um, km, in, ft; default: none)");
  common(dc);
  dc->callback([args] { RunDeadCentre(*args); });

  CLI::App* chart = cmd->add_subcommand(
      "chart",
      "Design charts (Kurventafeln), every design re-analysed: crank-rocker: for each phi0, psi0 (and rocker sense) the\n"
      "best beta and max mu_min, the lengths (frame 1) and the arc LE; slider-crank: for each phi0 the best e/s0, l1/s0,\n"
      "l2/s0 and mu_min. The status column says ok, none (no such mechanism exists), boundary (mu_min grows towards a\n"
      "degenerate end, no best design) or failed (the re-analysis refused it); the numbers are empty unless ok.\n"
      "Ranges FROM:TO:STEP in degrees. crank-rocker --design FILE.yaml: each cell the best inside that design space (as\n"
      "synth deadcentre --design; none where no member of the family lies inside).\n"
      "Example: koppel synth chart crank-rocker --phi0 160:170:2 --psi0 50:70:5 --rocker-sense both -o chart.csv");
  chart->add_option("type", args->type, "crank-rocker or slider-crank")->required();
  chart->add_option("--phi0", args->phi0, "phi0 range FROM:TO:STEP [deg]");
  chart->add_option("--psi0", args->psi0, "psi0 range FROM:TO:STEP [deg] (crank-rocker)");
  chart->add_option("--rocker-sense", args->rocker_sense, "same (default), opposite or both (crank-rocker)");
  chart->add_option("--design", args->design, "crank-rocker: the design space, a YAML file (lengths, ratio, pivots, mu_min)");
  OutputFile(chart->add_option("-o,--output-file", args->out, "Write the chart to this file instead of stdout"));
  chart->add_option("--format", args->format, "csv (default) or json");
  chart->add_flag("--quiet", args->quiet, "No count of designs on stderr");
  chart->callback([args] { RunChart(*args); });

  CLI::App* mzc = cmd->add_subcommand(
      "mzc",
      "Meyer zur Capellen straight-line linkage: the symmetric double rocker with a six-point tangent from lambda and\n"
      "the inflection-circle diameter D (sin^2 phi0 = (1 + 2 lambda)/4), or lambda from the coupler angle --kappa.\n"
      "Prints the dimensions, the contact order of K's curve with its tangent (6 = six-point), and the crank-rocker\n"
      "cognate. Example: koppel synth mzc --lambda 5/6 --D 1 -o mzc.yaml");
  mzc->add_option("--lambda", args->lambda, "lambda, 0.5 < lambda <= 1.5 (a formula: 5/6)");
  mzc->add_option("--kappa", args->kappa, "Coupler angle kappa [deg] instead of lambda");
  mzc->add_option("--D", args->diameter, "Inflection-circle diameter D (default 1)");
  OutputFile(mzc->add_option("-o,--yaml", args->yaml, "Write the double rocker as a YAML file"));
  OutputDirectory(mzc->add_option("--cognate-dir", args->cognates_dir, "Also write the crank-rocker cognate into this directory"));
  mzc->add_option("--units", args->units, "The designed mechanisms' length unit, as synth deadcentre --units");
  common(mzc);
  mzc->callback([args] { RunMzc(*args); });

  AddFitSubcommand(*cmd);
  AddMotionSubcommand(*cmd);
  AddFunctionSubcommand(*cmd);
  AddPathSubcommand(*cmd);
}

}  // namespace koppel::cli
