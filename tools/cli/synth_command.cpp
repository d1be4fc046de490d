// koppel synth: dead-centre synthesis, design charts, Meyer zur Capellen straight-line linkages
// and least-squares fitting (synth fit, in fit_command.cpp).
#include "commands.hpp"
#include "common.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/cognates.hpp"
#include "koppel/synthesis/deadcentre_synthesis.hpp"
#include "koppel/synthesis/mzc_synthesis.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace {

struct Args {
  std::string type;
  std::string phi0, psi0, beta, stroke, offset, frame = "1";
  std::string lambda, kappa, diameter = "1";
  std::string out, yaml, cognates_dir;
  std::string format = "csv";
  std::string sense = "ccw";
  bool quiet = false;
};

// "a:b:d" -> values a, a + d, ..., <= b (degrees)
std::vector<double> Range(const std::string& flag, const std::string& text) {
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
  std::vector<double> values;
  for (int i = 0; a + i * d <= b + 1e-9 * d; ++i) values.push_back(a + i * d);
  return values;
}

double Required(const std::string& flag, const std::string& text) {
  if (text.empty()) {
    Complain(flag + " is required");
    throw Exit{kExitBadInput};
  }
  return ParseNumberFlag(flag, text);
}

void Emit(const Args& args, const Summary& s) { WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv()); }

void RunDeadCentre(const Args& args) {
  CheckFormat(args.format);
  const double phi0 = DegToRad(Required("--phi0", args.phi0));
  Summary s;
  if (args.type == "crank-rocker") {
    const double psi0 = DegToRad(Required("--psi0", args.psi0)), frame = ParseNumberFlag("--frame", args.frame);
    const CrankRockerDesign d = args.beta.empty() ? BestCrankRocker(phi0, psi0, frame)
                                                  : CrankRockerFromDeadCentres(phi0, psi0, DegToRad(ParseNumberFlag("--beta", args.beta)), frame);
    if (!d.ok) {
      Complain(d.message);
      throw Exit{kExitFailed};
    }
    s.Add("phi0", RadToDeg(d.phi0), "deg");
    s.Add("psi0", RadToDeg(d.psi0), "deg");
    s.Add("beta", RadToDeg(d.beta), "deg");
    s.Add("l1", d.l1, "length");
    s.Add("l2", d.l2, "length");
    s.Add("l3", d.l3, "length");
    s.Add("l4", d.l4, "length");
    s.Add("mu_min", RadToDeg(d.mu_min), "deg");
    s.Add("mu_min_at", RadToDeg(d.mu_min_at), "deg");
    if (args.sense != "ccw" && args.sense != "cw") {
      Complain("--sense must be ccw or cw");
      throw Exit{kExitBadInput};
    }
    s.Add("sense", args.sense == "cw" ? -1 : 1, "ccw=1");
    const Mechanism designed = args.sense == "cw" ? MirrorMechanism(CrankRockerMechanism(d)) : CrankRockerMechanism(d);
    if (!args.yaml.empty())
      WriteOutput(args.yaml, WriteMechanismYaml(designed,
                                                fmt::format("Crank-rocker from dead-centre synthesis (koppel synth): phi0 = {} deg, psi0 = {} deg, beta = {} deg.\n"
                                                            "Input phi: crank angle against A0B0, counter-clockwise; extended dead centre at phi = {}beta.\n"
                                                            "The crank turns {} by phi0 from the folded to the extended dead centre, the rocker the other way by psi0.",
                                                            RadToDeg(d.phi0), RadToDeg(d.psi0), RadToDeg(d.beta), args.sense == "cw" ? "-" : "",
                                                            args.sense == "cw" ? "clockwise" : "counter-clockwise"),
                                                {0, 360, 1}));
  } else if (args.type == "slider-crank") {
    const double stroke = Required("--stroke", args.stroke);
    if (!args.offset.empty() && !args.beta.empty()) {
      Complain("give --offset or --beta, not both");
      throw Exit{kExitBadInput};
    }
    const SliderCrankDesign d = !args.offset.empty() ? SliderCrankFromDeadCentres(phi0, stroke, ParseNumberFlag("--offset", args.offset))
                                : !args.beta.empty() ? SliderCrankFromBeta(phi0, stroke, DegToRad(ParseNumberFlag("--beta", args.beta)))
                                                     : BestSliderCrank(phi0, stroke);
    if (!d.ok) {
      Complain(d.message);
      throw Exit{kExitFailed};
    }
    s.Add("phi0", RadToDeg(d.phi0), "deg");
    s.Add("stroke", d.stroke, "length");
    s.Add("e", d.e, "length");
    s.Add("l1", d.l1, "length");
    s.Add("l2", d.l2, "length");
    s.Add("e_s0", d.e / d.stroke, "1");
    s.Add("beta", RadToDeg(d.beta), "deg");
    s.Add("mu_min", RadToDeg(d.mu_min), "deg");
    s.Add("mu_min_at", RadToDeg(d.mu_min_at), "deg");
    if (!args.yaml.empty())
      WriteOutput(args.yaml, WriteMechanismYaml(SliderCrankMechanism(d),
                                                fmt::format("Slider-crank from dead-centre synthesis (koppel synth): phi0 = {} deg, stroke = {}, e = {}.\n"
                                                            "Conventions of seed 000: A0 = (0, -e), phi from -y counter-clockwise, s from the foot point.",
                                                            RadToDeg(d.phi0), d.stroke, d.e),
                                                {0, 360, 1}));
  } else {
    Complain("synth deadcentre: TYPE must be crank-rocker or slider-crank");
    throw Exit{kExitBadInput};
  }
  Emit(args, s);
}

void RunChart(const Args& args) {
  CheckFormat(args.format);
  Table t;
  if (args.type == "crank-rocker") {
    const auto phis = Range("--phi0", args.phi0.empty() ? "150:210:2" : args.phi0);
    const auto psis = Range("--psi0", args.psi0.empty() ? "20:100:2" : args.psi0);
    CheckCount(static_cast<double>(phis.size()) * static_cast<double>(psis.size()), "--phi0/--psi0 steps", kChartCells);
    t.columns = {"phi0", "psi0", "beta", "mu_min", "l1", "l2", "l3", "l4"};
    int done = 0;
    for (double phi : phis) {
      for (double psi : psis) {
        const CrankRockerDesign d = BestCrankRocker(DegToRad(phi), DegToRad(psi));
        if (d.ok) t.rows.push_back({phi, psi, RadToDeg(d.beta), RadToDeg(d.mu_min), d.l1, d.l2, d.l3, d.l4});
      }
      if (!args.quiet) std::cerr << fmt::format("\rkoppel synth chart: {}/{} phi0 values", ++done, phis.size()) << std::flush;
    }
  } else if (args.type == "slider-crank") {
    const auto phis = Range("--phi0", args.phi0.empty() ? "90:180:2" : args.phi0);
    t.columns = {"phi0", "e_s0", "l1_s0", "l2_s0", "mu_min", "beta"};
    int done = 0;
    for (double phi : phis) {
      const SliderCrankDesign d = BestSliderCrank(DegToRad(phi), 1.0);
      if (d.ok) t.rows.push_back({phi, d.e, d.l1, d.l2, RadToDeg(d.mu_min), RadToDeg(d.beta)});
      if (!args.quiet) std::cerr << fmt::format("\rkoppel synth chart: {}/{} phi0 values", ++done, phis.size()) << std::flush;
    }
  } else {
    Complain("synth chart: TYPE must be crank-rocker or slider-crank");
    throw Exit{kExitBadInput};
  }
  if (!args.quiet) std::cerr << "\n";
  WriteOutput(args.out, args.format == "json" ? JsonText(t.ToJson()) : t.ToCsv());
}

void RunMzc(const Args& args) {
  CheckFormat(args.format);
  double lambda = 0;
  if (!args.kappa.empty()) {
    std::string error;
    if (!LambdaFromKappa(DegToRad(ParseNumberFlag("--kappa", args.kappa)), &lambda, &error)) {
      Complain("--kappa: " + error);
      throw Exit{kExitBadInput};
    }
  } else {
    lambda = Required("--lambda", args.lambda);
  }
  const MzcDesign d = MzcFromLambda(lambda, ParseNumberFlag("--D", args.diameter));
  if (!d.ok) {
    Complain(d.message);
    throw Exit{kExitBadInput};
  }
  const Mechanism m = MzcMechanism(d);
  const int contact = TangentContactOrder(m, {2, 2}, m.hint.input, 1e-9);
  Summary s;
  s.Add("lambda", d.lambda, "1");
  s.Add("D", d.D, "length");
  s.Add("phi0", RadToDeg(d.phi0), "deg");
  s.Add("kappa", RadToDeg(d.kappa), "deg");
  s.Add("l1", d.l1, "length");
  s.Add("l2", d.l2, "length");
  s.Add("l3", d.l3, "length");
  s.Add("l4", d.l4, "length");
  s.Add("k", d.k, "length");
  s.Add("contact_points", contact, "1");
  const Cognates c = RobertsCognates(m, {2, 2});
  if (c.ok) {
    // the cognate whose crank turns with the double rocker's coupler is the crank-rocker
    s.Add("crank_rocker_l1", c.crank_first, "length");
    s.Add("crank_rocker_l2", c.coupler_first, "length");
    s.Add("crank_rocker_l3", c.rocker_first, "length");
    s.Add("crank_rocker_l4", c.frame_first, "length");
    s.Add("crank_rocker_AK", c.k_first, "length");
  }
  if (!args.yaml.empty()) {
    // the double rocker's own input range, a hundredth of a degree inside its limit positions
    const InputRange range = DrivableRange(m, kPi, DegToRad(1));
    const double lo = RadToDeg(range.low) + 0.01, hi = RadToDeg(range.high) - 0.01;
    WriteOutput(args.yaml, WriteMechanismYaml(m, fmt::format("Meyer zur Capellen straight-line linkage (koppel synth mzc): lambda = {}, D = {}.\n"
                                                             "Assembled in the crossed symmetric position; K is the inflection pole there.",
                                                             d.lambda, d.D),
                                              {lo, hi, (hi - lo) / 200}));
  }
  if (!args.cognates_dir.empty() && c.ok) {
    WriteOutput(args.cognates_dir + "/" + c.first.name + ".yaml",
                WriteMechanismYaml(c.first, "Crank-rocker cognate of a Meyer zur Capellen linkage (koppel synth mzc).", {0, 360, 1}));
  }
  Emit(args, s);
}

}  // namespace

void AddSynthCommand(CLI::App& app) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("synth", "Synthesis: dead-centre synthesis, design charts, Meyer zur Capellen linkages, least-squares fitting.");
  cmd->require_subcommand(1);
  auto common = [&](CLI::App* sub) {
    sub->add_option("--format", args->format, "csv (default) or json");
    sub->add_option("--output-file", args->out, "Write the table to this file instead of stdout");
  };

  CLI::App* dc = cmd->add_subcommand(
      "deadcentre",
      "Dead-centre synthesis (Totlagensynthese).\n"
      "crank-rocker: frame A0 = (0,0), B0 = (--frame, 0). phi0 = crank angle from the folded to the extended dead centre,\n"
      "counter-clockwise; psi0 = the rocker's swing between them (it turns clockwise while the crank turns\n"
      "counter-clockwise; mirror the mechanism for the opposite senses, as the document's negative rotation);\n"
      "beta = angle B0 A0 B_a. Without --beta, beta maximises the smallest transmission angle mu_min.\n"
      "slider-crank: phi0 as above, the stroke s0 between the dead centres, the offset e (default: maximise mu_min).\n"
      "Example: koppel synth deadcentre crank-rocker --phi0 164 --psi0 60 -o mech.yaml");
  dc->add_option("type", args->type, "crank-rocker or slider-crank")->required();
  dc->add_option("--phi0", args->phi0, "Crank angle between the dead centres [deg]")->required();
  dc->add_option("--psi0", args->psi0, "Rocker swing angle [deg] (crank-rocker)");
  dc->add_option("--beta", args->beta, "crank-rocker: angle B0 A0 B_a; slider-crank: angle between the slide line and A0B_a\n"
                                       "[deg] (default: best mu_min)");
  dc->add_option("--frame", args->frame, "Frame length A0B0 (crank-rocker, default 1)");
  dc->add_option("--sense", args->sense, "ccw (default) or cw: the crank's sense from the folded to the extended dead centre\n"
                                         "(cw is the mirror image, the document's 'mathematisch negativ')");
  dc->add_option("--stroke", args->stroke, "Stroke s0 (slider-crank)");
  dc->add_option("--offset", args->offset, "Offset e (slider-crank; default: best mu_min)");
  dc->add_option("-o,--yaml", args->yaml, "Write the mechanism as a YAML file");
  common(dc);
  dc->callback([args] { RunDeadCentre(*args); });

  CLI::App* chart = cmd->add_subcommand(
      "chart",
      "Design charts (Kurventafeln): crank-rocker: for each phi0, psi0 the best beta and max mu_min;\n"
      "slider-crank: for each phi0 the best e/s0, l1/s0, l2/s0 and mu_min. Ranges FROM:TO:STEP in degrees.\n"
      "Example: koppel synth chart crank-rocker --phi0 160:170:2 --psi0 50:70:5 -o chart.csv");
  chart->add_option("type", args->type, "crank-rocker or slider-crank")->required();
  chart->add_option("--phi0", args->phi0, "phi0 range FROM:TO:STEP [deg]");
  chart->add_option("--psi0", args->psi0, "psi0 range FROM:TO:STEP [deg] (crank-rocker)");
  chart->add_option("-o,--output-file", args->out, "Write the chart to this file instead of stdout");
  chart->add_option("--format", args->format, "csv (default) or json");
  chart->add_flag("--quiet", args->quiet, "No progress on stderr");
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
  mzc->add_option("-o,--yaml", args->yaml, "Write the double rocker as a YAML file");
  mzc->add_option("--cognate-dir", args->cognates_dir, "Also write the crank-rocker cognate into this directory");
  common(mzc);
  mzc->callback([args] { RunMzc(*args); });

  AddFitSubcommand(*cmd);
}

}  // namespace koppel::cli
