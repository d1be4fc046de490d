// Crank-rocker dead-centre synthesis: the family of designs for given phi0, psi0 and rocker
// sense, its arc LE, the design at a given beta or lambda, and the one with the largest mu_min.
#include "koppel/synthesis/deadcentre_synthesis.hpp"

#include "bar_linkages.hpp"
#include "design_proof.hpp"
#include "maximise.hpp"
#include "koppel/synthesis/design_space.hpp"

#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <cmath>
#include <complex>
#include <optional>

namespace koppel {
namespace {

using Complex = std::complex<double>;

// A link shorter than this fraction of the longest counts as vanished: such a "design" is the
// degenerate limit of the family, never a linkage to build.
constexpr double kVanishing = 1e-6;
// The family is searched over x = -ln(lambda) in [0, kLambdaDecades]: lambda = 1 (coupler as long
// as the crank, the end L of the arc) down to e^-28 = 7e-13, far below kVanishing and far above
// the roundoff in cos(delta/2) on the line phi0 = 180 deg + s psi0 where the family has one beta.
constexpr double kLambdaDecades = 28;
constexpr int kSearchSamples = 4000;
// |det| of the 2x2 dead-centre system below which beta no longer fixes a design
// (phi0 = 180 deg + s psi0: every design has the same beta).
constexpr double kSingular = 1e-12;

double SenseSign(RockerSense sense) { return sense == RockerSense::kSame ? 1.0 : -1.0; }

// One member of the family, in the synthesis frame (crank counter-clockwise).
struct Geometry {
  double l1 = 0, l2 = 0, l3 = 0;
  double phi_a = 0;  // signed angle of A0B_a, the crank angle of the extended dead centre
  Complex b_a, b_i;
};

void CompleteGeometry(const CrankRockerRequest& r, Geometry* g) {
  g->phi_a = std::remainder(g->phi_a, 2 * kPi);
  g->b_a = (g->l2 + g->l1) * std::polar(1.0, g->phi_a);
  g->b_i = (g->l2 - g->l1) * std::polar(1.0, g->phi_a - r.phi0 + kPi);
  g->l3 = std::abs(g->b_a - Complex(r.frame_length, 0));
}

// lambda = l1/l2 in (0, 1): the ellipse l2^2 cos^2(delta/2) + l1^2 sin^2(delta/2) = d^2 sin^2(psi0/2)
// gives l2, the direction of rho_a + rho_i e^{i delta} against d (1 - e^{i s psi0}) gives phi_a.
// Written with half angles, rho_a + rho_i e^{i delta} = 2 l2 e^{i delta/2} (cos(delta/2) - i lambda
// sin(delta/2)), so that on the line cos(delta/2) = 0 every lambda gives the same phi_a exactly.
Geometry FromLambda(const CrankRockerRequest& r, double lambda) {
  const double d = r.frame_length, s = SenseSign(r.rocker_sense), delta = s * r.psi0 - r.phi0;
  double c = std::cos(delta / 2);
  if (std::abs(c) < kSingular) c = 0;
  const double sn = std::sin(delta / 2);
  Geometry g;
  g.l2 = d * std::sin(r.psi0 / 2) / std::hypot(lambda * sn, c);
  g.l1 = lambda * g.l2;
  const Complex rhs = d * (1.0 - std::polar(1.0, s * r.psi0));
  g.phi_a = std::arg(rhs) - delta / 2 - std::atan2(-lambda * sn, c);
  CompleteGeometry(r, &g);
  return g;
}

// The document's construction as algebra: B_a on the ray at phi_a, B_i on the ray at
// phi_a - phi0 + pi, B_a - B0 = R(s psi0) (B_i - B0): linear in rho_a, rho_i. nullopt where
// phi_a does not fix the design.
std::optional<Geometry> FromPhiA(const CrankRockerRequest& r, double phi_a) {
  const double d = r.frame_length;
  const Complex ua = std::polar(1.0, phi_a), ui = std::polar(1.0, phi_a - r.phi0 + kPi), rot = std::polar(1.0, SenseSign(r.rocker_sense) * r.psi0);
  const Complex b0(d, 0.0), rhs = b0 - rot * b0, c2 = -rot * ui;
  const double det = ua.real() * c2.imag() - ua.imag() * c2.real();
  if (std::abs(det) < kSingular) return std::nullopt;
  const double rho_a = (rhs.real() * c2.imag() - rhs.imag() * c2.real()) / det;
  const double rho_i = (ua.real() * rhs.imag() - ua.imag() * rhs.real()) / det;
  Geometry g;
  g.l1 = 0.5 * (rho_a - rho_i);
  g.l2 = 0.5 * (rho_a + rho_i);
  g.phi_a = phi_a;
  CompleteGeometry(r, &g);
  return g;
}

// Empty when the geometry is a crank-rocker with these dead centres; otherwise why not.
std::string Inadmissible(const Geometry& g, double d) {
  if (!(g.l1 > 0 && g.l2 > g.l1)) return "the coupler would not be longer than the crank";
  // both dead centres on one assembly branch: B_a, B_i strictly on one side of A0B0
  if (!(g.b_a.imag() * g.b_i.imag() > 0)) return "B_a and B_i lie on different sides of A0B0 (different assembly branches)";
  const double l1 = g.l1, l2 = g.l2, l3 = g.l3;
  if (!(l1 < l3 && l1 < d && d + l1 < l2 + l3 && d - l1 > std::abs(l2 - l3)))
    return fmt::format("l1 = {:.6g}, l2 = {:.6g}, l3 = {:.6g}, l4 = {:.6g} is no crank-rocker (Grashof, crank shortest)", l1, l2, l3, d);
  return "";
}

// The links shorter than kVanishing of the longest ("the crank", "the crank and the rocker"), or empty.
std::string VanishingLinks(const Geometry& g, double d) {
  const double longest = std::max({g.l2, g.l3, d});
  std::string names;
  for (const auto& [length, name] : {std::pair{g.l1, "the crank"}, std::pair{g.l3, "the rocker"}, std::pair{d, "the frame"}}) {
    if (length < kVanishing * longest) names += (names.empty() ? "" : " and ") + std::string(name);
  }
  return names;
}

const char* Verb(const std::string& names) { return names.find(" and ") == std::string::npos ? "vanishes" : "vanish"; }

// Transmission angle folded to [0, pi/2] from the law of cosines in triangle A B B0, ab0 = |AB0|.
double FoldedMu(double l2, double l3, double ab0) {
  const double mu = std::acos(std::clamp((l2 * l2 + l3 * l3 - ab0 * ab0) / (2 * l2 * l3), -1.0, 1.0));
  return std::min(mu, kPi - mu);
}

// mu is extreme where the crank lies along the frame line (|AB0| = d -+ l1, monotonic between).
double ClosedFormMuMin(const Geometry& g, double d) { return std::min(FoldedMu(g.l2, g.l3, d - g.l1), FoldedMu(g.l2, g.l3, d + g.l1)); }

DesignScore MuMinScore(const CrankRockerRequest& r) {
  return [r](double x) -> std::optional<double> {
    const Geometry g = FromLambda(r, std::exp(-x));
    if (!Inadmissible(g, r.frame_length).empty() || !VanishingLinks(g, r.frame_length).empty()) return std::nullopt;
    return ClosedFormMuMin(g, r.frame_length);
  };
}

double DocumentBeta(double phi_a) { return std::abs(phi_a); }

// The arc LE around x (= -ln lambda): the document's beta at its ends; false when the whole
// family is inadmissible.
bool ArcAround(const CrankRockerRequest& r, double x, double* beta_l, double* beta_e) {
  const DesignScore score = MuMinScore(r);
  const double h = kLambdaDecades / kSearchSamples;
  // walk the grid outwards from x to the first inadmissible samples
  double lo = std::clamp(x, 0.0, kLambdaDecades), hi = lo;
  if (!score(lo)) {
    const std::optional<GridMaximum> any = MaximiseOnGrid(score, 0, kLambdaDecades, kSearchSamples, h);
    if (!any) return false;
    lo = hi = any->x;
  }
  while (lo - h >= 0 && score(lo - h)) lo -= h;
  while (hi + h <= kLambdaDecades && score(hi + h)) hi += h;
  const double x_l = lo - h >= 0 ? AdmissibleEdge(score, lo, lo - h) : 0.0;
  const double x_e = hi + h <= kLambdaDecades ? AdmissibleEdge(score, hi, hi + h) : kLambdaDecades;
  *beta_l = DocumentBeta(FromLambda(r, std::exp(-x_l)).phi_a);
  *beta_e = DocumentBeta(FromLambda(r, std::exp(-x_e)).phi_a);
  return true;
}

CrankRockerDesign Failed(const CrankRockerRequest& r, DesignStatus status, std::string message) {
  CrankRockerDesign d;
  d.request = r;
  d.status = status;
  d.message = std::move(message);
  return d;
}

std::string Describe(const CrankRockerRequest& r) {
  return fmt::format("phi0 = {:.6g} deg, psi0 = {:.6g} deg, rocker sense {}", RadToDeg(r.phi0), RadToDeg(r.psi0), ToString(r.rocker_sense));
}

// Fills the design from an admissible geometry and proves it by re-analysis.
CrankRockerDesign Prove(const CrankRockerRequest& r, const Geometry& g) {
  CrankRockerDesign d;
  d.request = r;
  d.beta = DocumentBeta(g.phi_a);
  d.phi_a = g.phi_a;
  d.phi_i = std::remainder(g.phi_a - r.phi0, 2 * kPi);
  d.lambda = g.l1 / g.l2;
  d.l1 = g.l1;
  d.l2 = g.l2;
  d.l3 = g.l3;
  d.l4 = r.frame_length;
  if (!ArcAround(r, -std::log(d.lambda), &d.beta_l, &d.beta_e)) d.beta_l = d.beta_e = d.beta;
  const double closed_form_mu = ClosedFormMuMin(g, r.frame_length);
  // the turn starts half-way round the arc from the extended to the folded dead centre
  const CrankReanalysis check = ReanalyseCrank(CrankRockerMechanism(d), 0, 1, d.phi_a + (2 * kPi - r.phi0) / 2);
  if (!check.ok()) return Failed(r, DesignStatus::kReanalysisFailed, "re-analysis: " + check.message);
  d.reanalysed_phi0 = check.phi0;
  d.reanalysed_psi = check.turn;
  d.mu_min = check.mu_min;
  d.mu_min_at = check.mu_min_at;
  const double want_turn = SenseSign(r.rocker_sense) * r.psi0;
  if (std::abs(AngleDifference(check.phi0, r.phi0)) > kReanalysisTolerance || std::abs(check.turn - want_turn) > kReanalysisTolerance ||
      std::abs(check.mu_min - closed_form_mu) > kReanalysisTolerance) {
    return Failed(r, DesignStatus::kReanalysisFailed,
                  fmt::format("re-analysis disagrees: phi0 {:.12g} deg (want {:.12g}), rocker turn {:.12g} deg (want {:.12g}), "
                              "mu_min {:.12g} deg (closed form {:.12g})",
                              RadToDeg(check.phi0), RadToDeg(r.phi0), RadToDeg(check.turn), RadToDeg(want_turn), RadToDeg(check.mu_min),
                              RadToDeg(closed_form_mu)));
  }
  d.status = DesignStatus::kOk;
  return d;
}

std::string OutsideArc(const CrankRockerRequest& r, const std::string& why) {
  double beta_l = 0, beta_e = 0;
  if (!ArcAround(r, 1.0, &beta_l, &beta_e)) return "no crank-rocker has " + Describe(r);
  return fmt::format("{}: outside the arc LE, which spans beta = {:.6g} .. {:.6g} deg (L .. E) for {}", why, RadToDeg(beta_l),
                     RadToDeg(beta_e), Describe(r));
}

}  // namespace

const char* ToString(RockerSense sense) { return sense == RockerSense::kSame ? "same" : "opposite"; }

const char* ToString(DesignStatus status) {
  switch (status) {
    case DesignStatus::kNotRun: return "not run";
    case DesignStatus::kOk: return "ok";
    case DesignStatus::kInvalidRequest: return "invalid request";
    case DesignStatus::kNoDesign: return "no design";
    case DesignStatus::kBoundaryOptimum: return "optimum on the boundary";
    case DesignStatus::kReanalysisFailed: return "re-analysis failed";
  }
  return "not run";
}

bool CrankRockerRequest::IsValid(std::string* why) const {
  std::string problem;
  if (!(phi0 > 0 && phi0 < 2 * kPi)) problem = "phi0 must lie strictly between 0 and 360 deg";
  else if (!(psi0 > 0 && psi0 < kPi)) problem = "psi0 must lie strictly between 0 and 180 deg";
  else if (!(frame_length > 0 && std::isfinite(frame_length))) problem = "the frame length must be positive";
  if (why) *why = problem;
  return problem.empty();
}

std::string CrankRockerDesign::Brief() const {
  if (!ok()) return fmt::format("{}: {}", ToString(status), message);
  return fmt::format("ok: beta {:.4f} deg, l1 {:.6g}, l2 {:.6g}, l3 {:.6g}, l4 {:.6g}, mu_min {:.4f} deg", RadToDeg(beta), l1, l2, l3, l4,
                     RadToDeg(mu_min));
}

CrankRockerDesign CrankRockerFromBeta(const CrankRockerRequest& r, double beta) {
  std::string why;
  if (!r.IsValid(&why)) return Failed(r, DesignStatus::kInvalidRequest, why);
  if (!(beta > 0 && beta < kPi)) return Failed(r, DesignStatus::kInvalidRequest, "beta must lie strictly between 0 and 180 deg");
  // crank counter-clockwise: B_a below A0B0 in the same sense, above it in the opposite sense
  const double phi_a = r.rocker_sense == RockerSense::kSame ? -beta : beta;
  const std::optional<Geometry> g = FromPhiA(r, phi_a);
  if (!g) {
    const Geometry any = FromLambda(r, 0.5);
    return Failed(r, DesignStatus::kNoDesign,
                  fmt::format("for {} every design has beta = {:.6g} deg and l1 = d sin(psi0/2): choose it by lambda = l1/l2 instead",
                              Describe(r), RadToDeg(DocumentBeta(any.phi_a))));
  }
  if (const std::string why_not = Inadmissible(*g, r.frame_length); !why_not.empty())
    return Failed(r, DesignStatus::kNoDesign, OutsideArc(r, fmt::format("beta = {:.6g} deg gives no crank-rocker ({})", RadToDeg(beta), why_not)));
  if (const std::string gone = VanishingLinks(*g, r.frame_length); !gone.empty())
    return Failed(r, DesignStatus::kNoDesign, fmt::format("beta = {:.6g} deg is a degenerate end of the arc LE: {} {}", RadToDeg(beta), gone, Verb(gone)));
  return Prove(r, *g);
}

CrankRockerDesign CrankRockerFromLambda(const CrankRockerRequest& r, double lambda) {
  std::string why;
  if (!r.IsValid(&why)) return Failed(r, DesignStatus::kInvalidRequest, why);
  if (!(lambda > 0 && lambda < 1)) return Failed(r, DesignStatus::kInvalidRequest, "lambda = l1/l2 must lie strictly between 0 and 1");
  const Geometry g = FromLambda(r, lambda);
  if (const std::string why_not = Inadmissible(g, r.frame_length); !why_not.empty())
    return Failed(r, DesignStatus::kNoDesign, OutsideArc(r, fmt::format("lambda = {:.6g} gives no crank-rocker ({})", lambda, why_not)));
  if (const std::string gone = VanishingLinks(g, r.frame_length); !gone.empty())
    return Failed(r, DesignStatus::kNoDesign, fmt::format("lambda = {:.6g} is a degenerate end of the arc LE: {} {}", lambda, gone, Verb(gone)));
  return Prove(r, g);
}

CrankRockerDesign BestCrankRocker(const CrankRockerRequest& r) {
  std::string why;
  if (!r.IsValid(&why)) return Failed(r, DesignStatus::kInvalidRequest, why);
  const std::optional<GridMaximum> found = MaximiseOnGrid(MuMinScore(r), 0, kLambdaDecades, kSearchSamples, 1e-13);
  if (!found) return Failed(r, DesignStatus::kNoDesign, "no crank-rocker has " + Describe(r));
  // Where the admissible stretch ends because a link vanishes (rather than at mu = 0), mu_min
  // may still grow towards that end: when the end is as good as the maximum, there is no best
  // crank-rocker, only a degenerate limit (phi0 = 180 deg: crank and rocker shrink to nothing).
  const DesignScore score = MuMinScore(r);
  const GridMaximum& best = *found;
  for (const auto& [inside, outside] : {std::pair{best.run_first, best.before_run}, std::pair{best.run_last, best.after_run}}) {
    if (inside == outside) continue;
    const Geometry beyond = FromLambda(r, std::exp(-outside));
    const std::string gone = VanishingLinks(beyond, r.frame_length);
    if (gone.empty() || !Inadmissible(beyond, r.frame_length).empty()) continue;
    const double edge = AdmissibleEdge(score, inside, outside);
    const double edge_value = score(edge).value_or(0);
    if (edge_value < best.value - kReanalysisTolerance) continue;
    return Failed(r, DesignStatus::kBoundaryOptimum,
                  fmt::format("for {} mu_min grows towards the end E of the arc LE (beta -> {:.6g} deg), where {} {}: "
                              "it approaches {:.6g} deg there, but no crank-rocker attains it; choose beta instead",
                              Describe(r), RadToDeg(DocumentBeta(FromLambda(r, std::exp(-edge)).phi_a)), gone, Verb(gone),
                              RadToDeg(std::max(edge_value, best.value))));
  }
  const Geometry g = FromLambda(r, std::exp(-best.x));
  return Prove(r, g);
}

CrankRockerDesign BestCrankRockerInSpace(const CrankRockerRequest& r, const DesignSpace& space) {
  if (space.Empty()) return BestCrankRocker(r);
  std::string why;
  if (!r.IsValid(&why)) return Failed(r, DesignStatus::kInvalidRequest, why);
  if (!space.IsValid(&why)) return Failed(r, DesignStatus::kInvalidRequest, "design space: " + why);
  const auto sizes = [&r](const Geometry& g, double mu) {
    return FourBarSizes{{0, 0}, {r.frame_length, 0}, g.l1, g.l2, g.l3, std::nullopt, mu};
  };
  const DesignScore family = MuMinScore(r);
  const DesignScore inside = [&](double x) -> std::optional<double> {
    const std::optional<double> mu = family(x);
    if (!mu || !space.Violation(sizes(FromLambda(r, std::exp(-x)), *mu)).empty()) return std::nullopt;
    return mu;
  };
  const std::optional<GridMaximum> found = MaximiseOnGrid(inside, 0, kLambdaDecades, kSearchSamples, 1e-13);
  if (!found) {
    const std::optional<GridMaximum> any = MaximiseOnGrid(family, 0, kLambdaDecades, kSearchSamples, 1e-13);
    if (!any) return Failed(r, DesignStatus::kNoDesign, "no crank-rocker has " + Describe(r));
    return Failed(r, DesignStatus::kNoDesign,
                  "no crank-rocker of the family lies inside the design space; the best without it broke " +
                      space.Violation(sizes(FromLambda(r, std::exp(-any->x)), any->value)));
  }
  CrankRockerDesign d = Prove(r, FromLambda(r, std::exp(-found->x)));
  if (!d.ok()) return d;
  // the solver's mu_min and the lengths of the proved design, against the space once more
  if (const std::string v = space.Violation({{0, 0}, {r.frame_length, 0}, d.l1, d.l2, d.l3, std::nullopt, d.mu_min}); !v.empty())
    return Failed(r, DesignStatus::kNoDesign, "the re-analysed design lies outside the design space: " + v);
  return d;
}

Mechanism CrankRockerMechanism(const CrankRockerDesign& d) {
  Mechanism m = BarFourBar("crank-rocker", {0, 0}, {d.l4, 0}, d.l1, d.l2, d.l3);
  // assembled in the extended dead centre: B_a on the ray at phi_a
  HintInput(m, d.phi_a);
  const Eigen::Vector2d ba = (d.l1 + d.l2) * Eigen::Vector2d(std::cos(d.phi_a), std::sin(d.phi_a));
  HintPoint(m, "coupler", "B", ba);
  HintPoint(m, "rocker", "B", ba);
  return m;
}

}  // namespace koppel
