// Slider-crank dead-centre synthesis (seed 002, Totlagensynthese der Schubkurbel): the design
// from the offset or from beta, the ranges of both that give a crank, and the offset with the
// largest mu_min.
#include "koppel/synthesis/deadcentre_synthesis.hpp"

#include "bar_linkages.hpp"
#include "design_proof.hpp"
#include "maximise.hpp"

#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <cmath>
#include <optional>

namespace koppel {
namespace {

// Below this |phi0 - 180 deg| the rays to the dead centres are parallel: the centric case.
constexpr double kCentric = 1e-12;
// A coupler longer than the crank by less than this fraction of the stroke, or an offset below
// it, counts as degenerate (the coupler folds onto the crank).
constexpr double kVanishingLength = 1e-6;
constexpr int kOffsetSamples = 4000;

// theta = |phi0 - 180 deg|: the angle between the rays A0B_a and A0B_i.
double Theta(const SliderCrankRequest& r) { return std::abs(r.phi0 - kPi); }
// seed 000's offset sign: A0 below the slide line (e > 0) when the crank turns the short way
double OffsetSign(const SliderCrankRequest& r) { return r.phi0 < kPi ? 1.0 : -1.0; }
// The offset range that gives a crank: |e| < s0 cot theta (B_i at the foot point at the end).
double OffsetMax(const SliderCrankRequest& r) { return r.stroke / std::tan(Theta(r)); }

struct SliderCrankGeometry {
  double offset = 0;  // |e|
  double x = 0;       // B_i's distance from the foot point along the slide
  double l1 = 0, l2 = 0, beta = 0;
};

// B_i = (x, e), B_a = (x + s0, e) seen from A0 enclose theta: tan theta = e s0 / (x (x + s0) + e^2),
// x = (-s0 + sqrt(s0^2 - 4 e^2 + 4 e s0 cot theta)) / 2. nullopt outside the offset range.
std::optional<SliderCrankGeometry> FromOffset(const SliderCrankRequest& r, double offset) {
  const double s0 = r.stroke, theta = Theta(r);
  if (!(offset > 0 && theta > kCentric && offset < OffsetMax(r))) return std::nullopt;
  SliderCrankGeometry g;
  g.offset = offset;
  g.x = 0.5 * (-s0 + std::sqrt(s0 * s0 - 4 * offset * offset + 4 * offset * s0 / std::tan(theta)));
  if (!(g.x > 0)) return std::nullopt;
  const double rho_i = std::hypot(g.x, offset), rho_a = std::hypot(g.x + s0, offset);
  g.l1 = 0.5 * (rho_a - rho_i);
  g.l2 = 0.5 * (rho_a + rho_i);
  g.beta = std::atan2(offset, g.x + s0);
  return g;
}

// seed 000: mu = 90 deg - |psi|, sin|psi| = |lambda cos phi + eps|, smallest with the crank
// normal to the slide on the side away from it
double ClosedFormMuMin(const SliderCrankGeometry& g) { return kPi / 2 - std::asin((g.l1 + g.offset) / g.l2); }

bool Degenerate(const SliderCrankGeometry& g, double s0) { return g.offset < kVanishingLength * s0 || g.l2 - g.l1 - g.offset < kVanishingLength * s0; }

// A design not yet run, with the request and the ranges that give a crank.
SliderCrankDesign Blank(const SliderCrankRequest& r) {
  SliderCrankDesign d;
  d.request = r;
  if (Theta(r) > kCentric && Theta(r) < kPi / 2) {
    d.offset_max = OffsetMax(r);
    d.beta_max = kPi / 2 - Theta(r);
  }
  return d;
}

SliderCrankDesign Failed(const SliderCrankRequest& r, DesignStatus status, std::string message) {
  SliderCrankDesign d = Blank(r);
  d.status = status;
  d.message = std::move(message);
  return d;
}

std::string Ranges(const SliderCrankRequest& r) {
  return fmt::format("for phi0 = {:.6g} deg and s0 = {:.6g} a crank needs 0 < |e| < {:.6g} (0 < beta < {:.6g} deg)", RadToDeg(r.phi0), r.stroke,
                     OffsetMax(r), RadToDeg(kPi / 2 - Theta(r)));
}

// Request checks shared by every entry point: a slider-crank's dead centres lie within 90 deg of
// the slide direction, so phi0 in (90, 270) deg; 180 deg is the centric case.
std::optional<SliderCrankDesign> CheckRequest(const SliderCrankRequest& r) {
  std::string why;
  if (!r.IsValid(&why)) return Failed(r, DesignStatus::kInvalidRequest, why);
  if (!(Theta(r) < kPi / 2))
    return Failed(r, DesignStatus::kNoDesign, fmt::format("no slider-crank has phi0 = {:.6g} deg: it needs 90 < phi0 < 270 deg", RadToDeg(r.phi0)));
  if (Theta(r) <= kCentric)
    return Failed(r, DesignStatus::kBoundaryOptimum,
                  fmt::format("phi0 = 180 deg is the centric slider-crank: e = 0, l1 = s0/2 = {:.6g} and any coupler l2 > l1; "
                              "mu_min = acos(l1/l2) approaches 90 deg only as l2 grows without bound",
                              r.stroke / 2));
  return std::nullopt;
}

SliderCrankDesign Prove(const SliderCrankRequest& r, const SliderCrankGeometry& g) {
  SliderCrankDesign d = Blank(r);
  d.e = OffsetSign(r) * g.offset;
  d.l1 = g.l1;
  d.l2 = g.l2;
  d.beta = g.beta;
  // crank angles (seed 000: A = A0 + l1 (sin phi, -cos phi)) of the dead centres: the crank along
  // A0B_a, and against A0B_i; the turn starts half-way round the arc that holds neither
  const double x_a = g.x + r.stroke, y = d.e;  // B_a - A0 = (x_a, e)
  const double phi_a = std::atan2(x_a, -y);
  const double mu_closed_form = ClosedFormMuMin(g);
  const CrankReanalysis check = ReanalyseCrank(SliderCrankMechanism(d), 0, 1, phi_a + (2 * kPi - r.phi0) / 2);
  if (!check.ok()) return Failed(r, DesignStatus::kReanalysisFailed, "re-analysis: " + check.message);
  d.reanalysed_phi0 = check.phi0;
  d.reanalysed_stroke = check.turn;
  d.mu_min = check.mu_min;
  d.mu_min_at = check.mu_min_at;
  if (std::abs(AngleDifference(check.phi0, r.phi0)) > kReanalysisTolerance || std::abs(check.turn - r.stroke) > kReanalysisTolerance * r.stroke ||
      std::abs(check.mu_min - mu_closed_form) > kReanalysisTolerance) {
    return Failed(r, DesignStatus::kReanalysisFailed,
                  fmt::format("re-analysis disagrees: phi0 {:.12g} deg (want {:.12g}), stroke {:.12g} (want {:.12g}), mu_min {:.12g} deg "
                              "(closed form {:.12g})",
                              RadToDeg(check.phi0), RadToDeg(r.phi0), check.turn, r.stroke, RadToDeg(check.mu_min), RadToDeg(mu_closed_form)));
  }
  d.status = DesignStatus::kOk;
  return d;
}

}  // namespace

bool SliderCrankRequest::IsValid(std::string* why) const {
  std::string problem;
  if (!(phi0 > 0 && phi0 < 2 * kPi)) problem = "phi0 must lie strictly between 0 and 360 deg";
  else if (!(stroke > 0 && std::isfinite(stroke))) problem = "the stroke must be positive";
  if (why) *why = problem;
  return problem.empty();
}

std::string SliderCrankDesign::Brief() const {
  if (!ok()) return fmt::format("{}: {}", ToString(status), message);
  return fmt::format("ok: e {:.6g}, l1 {:.6g}, l2 {:.6g}, beta {:.4f} deg, mu_min {:.4f} deg", e, l1, l2, RadToDeg(beta), RadToDeg(mu_min));
}

SliderCrankDesign SliderCrankFromOffset(const SliderCrankRequest& r, double offset) {
  if (auto refused = CheckRequest(r)) return *refused;
  if (offset < 0 || !std::isfinite(offset))
    return Failed(r, DesignStatus::kInvalidRequest, "the offset is |e|, a distance (its side follows from phi0): give it positive");
  if (offset == 0) return Failed(r, DesignStatus::kNoDesign, "without offset phi0 is 180 deg: " + Ranges(r));
  const std::optional<SliderCrankGeometry> g = FromOffset(r, offset);
  if (!g) return Failed(r, DesignStatus::kNoDesign, fmt::format("|e| = {:.6g} gives no crank: {}", offset, Ranges(r)));
  if (Degenerate(*g, r.stroke)) return Failed(r, DesignStatus::kNoDesign, fmt::format("|e| = {:.6g} is at the end of the range: {}", offset, Ranges(r)));
  return Prove(r, *g);
}

SliderCrankDesign SliderCrankFromBeta(const SliderCrankRequest& r, double beta) {
  if (auto refused = CheckRequest(r)) return *refused;
  const double theta = Theta(r);
  if (!(beta > 0 && beta + theta < kPi / 2)) return Failed(r, DesignStatus::kNoDesign, fmt::format("beta = {:.6g} deg gives no crank: {}", RadToDeg(beta), Ranges(r)));
  // B_a = (e cot beta, e), B_i = (e cot(beta + theta), e): e = s0 / (cot beta - cot(beta + theta))
  return SliderCrankFromOffset(r, r.stroke / (1 / std::tan(beta) - 1 / std::tan(beta + theta)));
}

SliderCrankDesign BestSliderCrank(const SliderCrankRequest& r) {
  if (auto refused = CheckRequest(r)) return *refused;
  // |e| = t s0 cot theta, t in (0, 1): mu_min -> 0 at both ends, so the maximum is inside
  const double e_max = OffsetMax(r);
  const DesignScore score = [&](double t) -> std::optional<double> {
    const std::optional<SliderCrankGeometry> g = FromOffset(r, t * e_max);
    if (!g) return std::nullopt;
    return ClosedFormMuMin(*g);
  };
  const std::optional<GridMaximum> best = MaximiseOnGrid(score, 0, 1, kOffsetSamples, 1e-13);
  if (!best) return Failed(r, DesignStatus::kNoDesign, "no offset gives a slider-crank: " + Ranges(r));
  const std::optional<SliderCrankGeometry> g = FromOffset(r, best->x * e_max);
  if (!g || Degenerate(*g, r.stroke))
    return Failed(r, DesignStatus::kBoundaryOptimum, "mu_min grows towards the end of the offset range: " + Ranges(r));
  return Prove(r, *g);
}

Mechanism SliderCrankMechanism(const SliderCrankDesign& d) {
  Mechanism m = BarSliderCrank("slider-crank", {0, -d.e}, {0, 0}, {0, -d.l1}, d.l2);
  HintInput(m, 0);
  HintPoint(m, "slider", "B", {std::sqrt(std::max(d.l2 * d.l2 - std::pow(d.e + d.l1, 2), 0.0)), 0.0});
  return m;
}

}  // namespace koppel
