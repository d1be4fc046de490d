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

#include <atomic>
#include <functional>
#include <iostream>
#include <optional>
#include <thread>

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

// --rocker-sense: same | opposite (| both for the chart)
std::vector<RockerSense> RockerSenses(const std::string& text, bool allow_both) {
  if (text == "same") return {RockerSense::kSame};
  if (text == "opposite") return {RockerSense::kOpposite};
  if (allow_both && text == "both") return {RockerSense::kSame, RockerSense::kOpposite};
  Complain(std::string("--rocker-sense must be same") + (allow_both ? ", opposite or both" : " or opposite") + ", not '" + text + "'");
  throw Exit{kExitBadInput};
}

void Emit(const Args& args, const Summary& s) { WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv()); }

// A refused design: the reason on stderr, exit 2 for a malformed request, else 1.
void Refuse(DesignStatus status, const std::string& message) {
  Complain(message);
  throw Exit{status == DesignStatus::kInvalidRequest ? kExitBadInput : kExitFailed};
}

void RunCrankRocker(const Args& args, double phi0) {
  CrankRockerRequest request;
  request.phi0 = phi0;
  request.psi0 = DegToRad(Required("--psi0", args.psi0));
  request.rocker_sense = RockerSenses(args.rocker_sense, false).front();
  request.frame_length = ParseNumberFlag("--frame", args.frame);
  if (args.sense != "ccw" && args.sense != "cw") {
    Complain("--sense must be ccw or cw");
    throw Exit{kExitBadInput};
  }
  if (!args.beta.empty() && !args.lambda_cr.empty()) {
    Complain("give --beta or --lambda, not both");
    throw Exit{kExitBadInput};
  }
  const CrankRockerDesign d = !args.beta.empty()        ? CrankRockerFromBeta(request, DegToRad(ParseNumberFlag("--beta", args.beta)))
                              : !args.lambda_cr.empty() ? CrankRockerFromLambda(request, ParseNumberFlag("--lambda", args.lambda_cr))
                                                        : BestCrankRocker(request);
  if (!d.ok()) Refuse(d.status, d.message);
  // the written mechanism turns its crank in --sense: clockwise is the mirror image
  const double turn = args.sense == "cw" ? -1 : 1;
  Summary s;
  s.Add("phi0", RadToDeg(request.phi0), "deg");
  s.Add("psi0", RadToDeg(request.psi0), "deg");
  s.Add("rocker_sense", request.rocker_sense == RockerSense::kSame ? 1 : -1, "same=1");
  s.Add("beta", RadToDeg(d.beta), "deg");
  s.Add("lambda", d.lambda, "1");
  s.Add("l1", d.l1, "length");
  s.Add("l2", d.l2, "length");
  s.Add("l3", d.l3, "length");
  s.Add("l4", d.l4, "length");
  s.Add("mu_min", RadToDeg(d.mu_min), "deg");
  s.Add("mu_min_at", RadToDeg(turn * d.mu_min_at), "deg");
  s.Add("phi_a", RadToDeg(turn * d.phi_a), "deg");
  s.Add("phi_i", RadToDeg(turn * d.phi_i), "deg");
  s.Add("beta_L", RadToDeg(d.beta_l), "deg");
  s.Add("beta_E", RadToDeg(d.beta_e), "deg");
  s.Add("reanalysed_phi0", RadToDeg(d.reanalysed_phi0), "deg");
  s.Add("reanalysed_psi0", RadToDeg(std::abs(d.reanalysed_psi)), "deg");
  s.Add("sense", turn, "ccw=1");
  if (!args.yaml.empty()) {
    const Mechanism designed = args.sense == "cw" ? MirrorMechanism(CrankRockerMechanism(d)) : CrankRockerMechanism(d);
    WriteOutput(args.yaml,
                WriteMechanismYaml(designed,
                                   fmt::format("Crank-rocker from dead-centre synthesis (koppel synth): phi0 = {:.10g} deg, psi0 = {:.10g} deg, beta = {:.10g} deg,\n"
                                               "rocker sense {}. Input phi: crank angle against A0B0, counter-clockwise; the crank runs {}.\n"
                                               "From the folded dead centre (phi = {:.10g} deg) to the extended one (phi = {:.10g} deg) the crank turns\n"
                                               "by phi0 and the rocker by psi0, {}.",
                                               RadToDeg(request.phi0), RadToDeg(request.psi0), RadToDeg(d.beta), ToString(request.rocker_sense),
                                               args.sense == "cw" ? "clockwise" : "counter-clockwise", RadToDeg(turn * d.phi_i),
                                               RadToDeg(turn * d.phi_a),
                                               request.rocker_sense == RockerSense::kSame ? "both the same way" : "in opposite senses"),
                                   {0, 360, 1}));
  }
  Emit(args, s);
}

void RunSliderCrank(const Args& args, double phi0) {
  SliderCrankRequest request;
  request.phi0 = phi0;
  request.stroke = Required("--stroke", args.stroke);
  if (!args.offset.empty() && !args.beta.empty()) {
    Complain("give --offset or --beta, not both");
    throw Exit{kExitBadInput};
  }
  const SliderCrankDesign d = !args.offset.empty() ? SliderCrankFromOffset(request, ParseNumberFlag("--offset", args.offset))
                              : !args.beta.empty() ? SliderCrankFromBeta(request, DegToRad(ParseNumberFlag("--beta", args.beta)))
                                                   : BestSliderCrank(request);
  if (!d.ok()) Refuse(d.status, d.message);
  Summary s;
  s.Add("phi0", RadToDeg(request.phi0), "deg");
  s.Add("stroke", request.stroke, "length");
  s.Add("e", d.e, "length");
  s.Add("l1", d.l1, "length");
  s.Add("l2", d.l2, "length");
  s.Add("e_s0", d.e / request.stroke, "1");
  s.Add("beta", RadToDeg(d.beta), "deg");
  s.Add("mu_min", RadToDeg(d.mu_min), "deg");
  s.Add("mu_min_at", RadToDeg(d.mu_min_at), "deg");
  s.Add("offset_max", d.offset_max, "length");
  s.Add("beta_max", RadToDeg(d.beta_max), "deg");
  s.Add("reanalysed_phi0", RadToDeg(d.reanalysed_phi0), "deg");
  s.Add("reanalysed_stroke", d.reanalysed_stroke, "length");
  if (!args.yaml.empty())
    WriteOutput(args.yaml, WriteMechanismYaml(SliderCrankMechanism(d),
                                              fmt::format("Slider-crank from dead-centre synthesis (koppel synth): phi0 = {:.10g} deg, stroke = {:.10g}, e = {:.10g}.\n"
                                                          "Conventions of seed 000: A0 = (0, -e), phi from -y counter-clockwise, s from the foot point.",
                                                          RadToDeg(request.phi0), request.stroke, d.e),
                                              {0, 360, 1}));
  Emit(args, s);
}

void RunDeadCentre(const Args& args) {
  CheckFormat(args.format);
  const double phi0 = DegToRad(Required("--phi0", args.phi0));
  if (args.type == "crank-rocker") {
    RunCrankRocker(args, phi0);
  } else if (args.type == "slider-crank") {
    RunSliderCrank(args, phi0);
  } else {
    Complain("synth deadcentre: TYPE must be crank-rocker or slider-crank");
    throw Exit{kExitBadInput};
  }
}

// A chart: numbers, words (sense, status) and empty cells where no design exists.
struct Chart {
  struct Cell {
    std::optional<double> number;
    std::string word;
  };
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;

  std::string ToCsv() const {
    std::string out;
    for (size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i];
    out += "\n";
    for (const auto& row : rows) {
      for (size_t i = 0; i < row.size(); ++i) out += (i ? "," : "") + (row[i].number ? FormatNumber(*row[i].number) : row[i].word);
      out += "\n";
    }
    return out;
  }
  nlohmann::json ToJson() const {
    nlohmann::json rows_json = nlohmann::json::array();
    for (const auto& row : rows) {
      nlohmann::json r = nlohmann::json::array();
      for (const Cell& c : row) {
        if (c.number) r.push_back(std::stod(FormatNumber(*c.number)));
        else if (!c.word.empty()) r.push_back(c.word);
        else r.push_back(nullptr);
      }
      rows_json.push_back(r);
    }
    return {{"columns", columns}, {"rows", rows_json}};
  }
};

// ok; none: no design exists; boundary: the best design degenerates; failed: re-analysis refused it
std::string ChartStatus(DesignStatus status) {
  switch (status) {
    case DesignStatus::kOk: return "ok";
    case DesignStatus::kBoundaryOptimum: return "boundary";
    case DesignStatus::kReanalysisFailed: return "failed";
    default: return "none";
  }
}

std::vector<Chart::Cell> ChartRow(std::vector<Chart::Cell> keys, DesignStatus status, const std::vector<double>& values) {
  keys.push_back({std::nullopt, ChartStatus(status)});
  for (double v : values) keys.push_back(status == DesignStatus::kOk ? Chart::Cell{v, ""} : Chart::Cell{});
  return keys;
}

// Runs design(i) for i < n on every core (each design is independent and proved by its own
// re-analysis), with progress on stderr unless quiet.
template <class Design>
std::vector<Design> DesignAll(size_t n, const std::function<Design(size_t)>& design, bool quiet) {
  std::vector<Design> designs(n);
  std::atomic<size_t> next{0}, done{0};
  auto work = [&] {
    for (size_t i = next++; i < n; i = next++) {
      designs[i] = design(i);
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::max(1u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (!quiet) std::cerr << fmt::format("koppel synth chart: {} designs\n", done.load());
  return designs;
}

void RunChart(const Args& args) {
  CheckFormat(args.format);
  Chart chart;
  if (args.type == "crank-rocker") {
    const auto phis = Range("--phi0", args.phi0.empty() ? "150:210:2" : args.phi0);
    const auto psis = Range("--psi0", args.psi0.empty() ? "20:100:2" : args.psi0);
    CheckCount(static_cast<double>(phis.size()) * static_cast<double>(psis.size()), "--phi0/--psi0 steps", kChartCells);
    const auto senses = RockerSenses(args.rocker_sense, true);
    chart.columns = {"phi0", "psi0", "rocker_sense", "status", "beta", "mu_min", "l1", "l2", "l3", "l4", "beta_L", "beta_E"};
    std::vector<CrankRockerRequest> requests;
    for (double phi : phis) {
      for (RockerSense sense : senses) {
        for (double psi : psis) {
          CrankRockerRequest request;
          request.phi0 = DegToRad(phi);
          request.psi0 = DegToRad(psi);
          request.rocker_sense = sense;
          if (std::string why; !request.IsValid(&why)) Refuse(DesignStatus::kInvalidRequest, why);
          requests.push_back(request);
        }
      }
    }
    const auto designs = DesignAll<CrankRockerDesign>(requests.size(), [&](size_t i) { return BestCrankRocker(requests[i]); }, args.quiet);
    for (const CrankRockerDesign& d : designs) {
      const CrankRockerRequest& r = d.request;
      chart.rows.push_back(ChartRow({{RadToDeg(r.phi0), ""}, {RadToDeg(r.psi0), ""}, {std::nullopt, ToString(r.rocker_sense)}}, d.status,
                                    {RadToDeg(d.beta), RadToDeg(d.mu_min), d.l1, d.l2, d.l3, d.l4, RadToDeg(d.beta_l), RadToDeg(d.beta_e)}));
    }
  } else if (args.type == "slider-crank") {
    const auto phis = Range("--phi0", args.phi0.empty() ? "90:180:2" : args.phi0);
    chart.columns = {"phi0", "status", "e_s0", "l1_s0", "l2_s0", "mu_min", "beta"};
    std::vector<SliderCrankRequest> requests;
    for (double phi : phis) {
      SliderCrankRequest request;
      request.phi0 = DegToRad(phi);
      request.stroke = 1.0;
      if (std::string why; !request.IsValid(&why)) Refuse(DesignStatus::kInvalidRequest, why);
      requests.push_back(request);
    }
    const auto designs = DesignAll<SliderCrankDesign>(requests.size(), [&](size_t i) { return BestSliderCrank(requests[i]); }, args.quiet);
    for (const SliderCrankDesign& d : designs)
      chart.rows.push_back(ChartRow({{RadToDeg(d.request.phi0), ""}}, d.status, {d.e, d.l1, d.l2, RadToDeg(d.mu_min), RadToDeg(d.beta)}));
  } else {
    Complain("synth chart: TYPE must be crank-rocker or slider-crank");
    throw Exit{kExitBadInput};
  }
  WriteOutput(args.out, args.format == "json" ? JsonText(chart.ToJson()) : chart.ToCsv());
}

void RunMzc(const Args& args) {
  CheckFormat(args.format);
  double lambda = 0;
  if (!args.kappa.empty()) {
    const Expected<double> from_kappa = LambdaFromKappa(DegToRad(ParseNumberFlag("--kappa", args.kappa)));
    if (!from_kappa) {
      Complain("--kappa: " + from_kappa.error());
      throw Exit{kExitBadInput};
    }
    lambda = *from_kappa;
  } else {
    lambda = Required("--lambda", args.lambda);
  }
  const MzcDesign d = MzcFromLambda(lambda, ParseNumberFlag("--D", args.diameter));
  if (!d.ok()) {
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
  if (c.ok()) {
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
  if (!args.cognates_dir.empty() && c.ok()) {
    MakeOutputDirectory(args.cognates_dir);
    WriteOutput(args.cognates_dir + "/" + c.first.name + ".yaml",
                WriteMechanismYaml(c.first, "Crank-rocker cognate of a Meyer zur Capellen linkage (koppel synth mzc).", {0, 360, 1}));
  }
  Emit(args, s);
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
      "Dead-centre synthesis (Totlagensynthese, seed 002); every design is re-analysed by the solver before it is printed.\n"
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
      "slider-crank: seed 000's conventions (A0 = (0, -e), slide along x). phi0 from the folded to the extended dead centre\n"
      "  (90 < phi0 < 270 deg; phi0 > 180 puts A0 above the slide line, e < 0), the stroke s0 between them, and the offset\n"
      "  |e| (--offset) or beta (angle between the slide line and A0B_a), each within the range that gives a crank; by\n"
      "  default the offset that maximises mu_min. phi0 = 180 deg (centric) has no best design.\n"
      "Example: koppel synth deadcentre crank-rocker --phi0 164 --psi0 60 -o mech.yaml");
  dc->add_option("type", args->type, "crank-rocker or slider-crank")->required();
  dc->add_option("--phi0", args->phi0, "Crank angle from the folded to the extended dead centre [deg]")->required();
  dc->add_option("--psi0", args->psi0, "Rocker swing angle [deg] (crank-rocker)");
  dc->add_option("--rocker-sense", args->rocker_sense, "same (default: the document's) or opposite: the rocker's sense against the crank's\n"
                                                       "from the folded to the extended dead centre (crank-rocker)");
  dc->add_option("--beta", args->beta, "crank-rocker: angle B0 A0 B_a; slider-crank: angle between the slide line and A0B_a\n"
                                       "[deg] (default: best mu_min)");
  dc->add_option("--lambda", args->lambda_cr, "crank-rocker: l1/l2 in (0, 1) instead of beta (default: best mu_min)");
  dc->add_option("--frame", args->frame, "Frame length A0B0 (crank-rocker, default 1)");
  dc->add_option("--sense", args->sense, "ccw (default) or cw: the sense the crank runs in the written mechanism\n"
                                         "(cw is the mirror image, the document's 'mathematisch negativ')");
  dc->add_option("--stroke", args->stroke, "Stroke s0 (slider-crank)");
  dc->add_option("--offset", args->offset, "Offset |e| (slider-crank; default: best mu_min)");
  OutputFile(dc->add_option("-o,--yaml", args->yaml, "Write the mechanism as a YAML file"));
  common(dc);
  dc->callback([args] { RunDeadCentre(*args); });

  CLI::App* chart = cmd->add_subcommand(
      "chart",
      "Design charts (Kurventafeln), every design re-analysed: crank-rocker: for each phi0, psi0 (and rocker sense) the\n"
      "best beta and max mu_min, the lengths (frame 1) and the arc LE; slider-crank: for each phi0 the best e/s0, l1/s0,\n"
      "l2/s0 and mu_min. The status column says ok, none (no such mechanism exists), boundary (mu_min grows towards a\n"
      "degenerate end, no best design) or failed (the re-analysis refused it); the numbers are empty unless ok.\n"
      "Ranges FROM:TO:STEP in degrees.\n"
      "Example: koppel synth chart crank-rocker --phi0 160:170:2 --psi0 50:70:5 --rocker-sense both -o chart.csv");
  chart->add_option("type", args->type, "crank-rocker or slider-crank")->required();
  chart->add_option("--phi0", args->phi0, "phi0 range FROM:TO:STEP [deg]");
  chart->add_option("--psi0", args->psi0, "psi0 range FROM:TO:STEP [deg] (crank-rocker)");
  chart->add_option("--rocker-sense", args->rocker_sense, "same (default), opposite or both (crank-rocker)");
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
  common(mzc);
  mzc->callback([args] { RunMzc(*args); });

  AddFitSubcommand(*cmd);
  AddMotionSubcommand(*cmd);
  AddFunctionSubcommand(*cmd);
  AddPathSubcommand(*cmd);
}

}  // namespace koppel::cli
