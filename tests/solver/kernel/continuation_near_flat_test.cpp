// Linkages a hair from their change point (Grashof-neutral within a relative defect eps): the
// branch passes the other one at about sqrt(eps) and turns sharply there, but it is one smooth
// branch without a singular position, so every row must lie on the branch the mechanism was
// assembled on, whatever the step, and a branch point is reported only where the dimensions reach
// a flat pose (LocateBranchPoint's defect at most kBranchPointDefect). With eps < 0 the linkage
// cannot be assembled in a narrow stretch of the input: the sweep ends at the two limit points
// around it, lists the gap, and is partial.
//
// The reference: the circle intersection in long double (64-bit mantissa), with the square root's
// argument b^2 - x^2 written as (b - x)(b + x), exact to about 1e-19 / sqrt(eps) — three decades
// below what the rows are held to.
#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/constraints.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace koppel::continuation_near_flat_test {
namespace {

using Real = long double;

// Rows against the reference [rad, or units of L]: the kernel solves J dq = -F in double near a
// pose whose J S has sigma_min ~ sqrt(eps) (>= 3e-6 here), so a row may be off by roundoff / 3e-6
// (Newton polishes such poses below its tolerance: PositionSolver::Correct).
constexpr double kRow = 1e-9;
// Limit points: a gap's ends move by (their residual) / sin(phi_limit) with sin(phi_limit) ~
// sqrt(|eps|), and the augmented system's Newton stops at residuals of about 1e-13 L.
double LimitTolerance(double eps) { return std::max(1e-10, 1e-13 / std::sqrt(std::abs(eps))); }

enum class Kind { kFourBarExtended, kFourBarFolded, kSliderCrank };

// One linkage of the family: dimensions, and the output's reference on a branch (side = +-1).
struct Linkage {
  Kind kind;
  Real a = 1, b = 0, c = 0, d = 4, e = 0;  // four-bar a b c d; slider-crank l1 = a, l2 = b, offset e

  // the rocker's angle psi (four-bar) or the slider's s (slider-crank) at crank angle phi
  std::optional<Real> Output(Real phi, int side) const {
    if (kind == Kind::kSliderCrank) {
      const Real ax = a * std::sin(phi), ay = -e - a * std::cos(phi);
      const Real root2 = (b - ay) * (b + ay);
      if (root2 < 0) return std::nullopt;
      return ax + side * std::sqrt(root2);
    }
    const Real ax = a * std::cos(phi), ay = a * std::sin(phi);
    const Real rx = d - ax, ry = -ay, rho = std::sqrt(rx * rx + ry * ry);
    const Real x = (b * b - c * c + rho * rho) / (2 * rho);  // along A -> B0
    const Real h2 = (b - x) * (b + x);
    if (h2 < 0) return std::nullopt;
    const Real h = side * std::sqrt(h2);
    const Real bx = ax + (x * rx - h * ry) / rho, by = ay + (x * ry + h * rx) / rho;
    return std::atan2(by, bx - d);
  }
  // the crank angle where the linkage comes nearest to flat
  double NearFlatInput() const { return kind == Kind::kFourBarExtended ? kPi : 0.0; }
  // the crank angles in [0, 2 pi) where the linkage is flat (the gap's ends when eps < 0)
  std::vector<Real> FlatInputs() const {
    Real cosine;
    if (kind == Kind::kSliderCrank) {
      cosine = e >= 0 ? (b - e) / a : (-b - e) / a;  // |ay| = l2 with ay = -e - a cos phi
    } else {
      const Real reach = kind == Kind::kFourBarExtended ? b + c : b - c;
      cosine = (a * a + d * d - reach * reach) / (2 * a * d);
    }
    if (!(std::abs(cosine) <= 1)) return {};
    const Real phi = std::acos(cosine);
    return {phi, 2 * static_cast<Real>(kPi) - phi};
  }
};

// eps > 0: turns fully on one branch; eps < 0: a gap of width ~ sqrt(|eps|) around the flat input.
Linkage Make(Kind kind, Real eps) {
  Linkage l{kind};
  if (kind == Kind::kFourBarExtended) {
    l.c = 3;
    l.b = (l.a + l.d) * (1 + eps) - l.c;  // b + c = (a + d)(1 + eps): flat at phi = pi
  } else if (kind == Kind::kFourBarFolded) {
    l.c = 2;
    l.b = l.c + (l.d - l.a) * (1 - eps);  // b - c = (d - a)(1 - eps): folded at phi = 0
  } else {
    l.e = 0.4;
    l.b = (l.a + l.e) * (1 + eps);  // l2 = l1 + e: the coupler perpendicular to the slide at phi = 0
  }
  return l;
}

Mechanism Build(const Linkage& l, double assembly_input, int side, double scale) {
  const double a = static_cast<double>(l.a), b = static_cast<double>(l.b), c = static_cast<double>(l.c),
               d = static_cast<double>(l.d), e = static_cast<double>(l.e);
  Mechanism m;
  if (l.kind == Kind::kSliderCrank) {
    m = test::SliderCrank(a, b, e);
    m.hint.input = assembly_input;
    m.hint.points[0].global = {static_cast<double>(*l.Output(assembly_input, side)), 0.0};
  } else {
    const double psi = static_cast<double>(*l.Output(assembly_input, side));
    m = test::PlainFourBar(a, b, c, d, assembly_input, {d + c * std::cos(psi), c * std::sin(psi)});
  }
  return test::Scaled(m, scale);
}

const char* Name(Kind kind) {
  return kind == Kind::kFourBarExtended ? "four-bar b + c = (a + d)(1 + eps)"
         : kind == Kind::kFourBarFolded ? "four-bar b - c = (d - a)(1 - eps)"
                                        : "slider-crank l2 = (l1 + e)(1 + eps)";
}

struct Counts {
  int sweeps = 0, rows = 0, gaps = 0;
};

// One sweep: every row on the assembly branch; full turns close (eps > 0); gaps only between the
// two closed-form limit points around the flat input (eps < 0); no branch point at all.
void CheckSweep(const Linkage& l, Real eps, int side, double scale, double from, double to, double step, Counts* counts) {
  const double assembly = DegToRad(90.0);
  const Mechanism m = Build(l, assembly, side, scale);
  SweepOptions o;
  o.from = from;
  o.to = to;
  o.step = step;
  o.order = 1;
  const SweepResult r = Sweep(m, o);
  INFO(Name(l.kind) << ", eps = " << static_cast<double>(eps) << ", side " << side << ", scale " << scale << ", from "
                    << RadToDeg(from) << " to " << RadToDeg(to) << " step " << RadToDeg(step) << " deg: " << r.Brief());
  REQUIRE(r.status != SweepStatus::kNotAssemblable);
  const int column = OutputColumn(m, 0, 0, o.order);
  const double unit = l.kind == Kind::kSliderCrank ? scale : 1.0;  // s scales with the mechanism, psi does not
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    const std::optional<Real> expected = l.Output(r.inputs[i], side);
    INFO("row phi = " << RadToDeg(r.inputs[i]) << " deg");
    REQUIRE(expected);
    const double got = r.outputs(i, column) / unit, want = static_cast<double>(*expected);
    REQUIRE(std::abs(l.kind == Kind::kSliderCrank ? got - want : AngleDifference(got, want)) < kRow);
    ++counts->rows;
  }
  for (const SingularPoint& p : r.singular_points) REQUIRE(p.kind == SingularKind::kLimitPoint);
  const std::vector<Real> flat = l.FlatInputs();
  if (eps > 0) {
    CHECK(r.complete());
    CHECK(r.singular_points.empty());
  } else {
    REQUIRE(flat.size() == 2);
    for (const SingularPoint& p : r.singular_points) {
      const double near = std::min(std::abs(std::remainder(p.input - static_cast<double>(flat[0]), 2 * kPi)),
                                   std::abs(std::remainder(p.input - static_cast<double>(flat[1]), 2 * kPi)));
      CHECK(near < LimitTolerance(static_cast<double>(eps)));
    }
    // every range here holds the gap: the sweep says so, and has met the limit point before it
    CHECK(!r.complete());
    CHECK(!r.gaps.empty());
    CHECK(!r.singular_points.empty());
    counts->gaps += static_cast<int>(r.gaps.size());
  }
  ++counts->sweeps;
}

}  // namespace

TEST_CASE("linkages within 1e-5 .. 1e-11 of their change point: every row on the assembly branch at every step and scale",
          "[continuation][property]") {
  Counts counts;
  for (Kind kind : {Kind::kFourBarExtended, Kind::kFourBarFolded, Kind::kSliderCrank}) {
    for (int exponent = 5; exponent <= 11; ++exponent) {
      for (Real sign : {Real(1), Real(-1)}) {
        const Real eps = sign * std::pow(Real(10), -exponent);
        const Linkage l = Make(kind, eps);
        const int side = exponent % 2 == 0 ? 1 : -1;
        const double flat = l.NearFlatInput();
        for (double scale : {1e-4, 1.0, 1e4}) {
          for (double offset_deg : {0.0, 3.0}) {
            const double offset = DegToRad(offset_deg);
            for (double step_deg : {1.0, 7.0, 45.0, 90.0}) CheckSweep(l, eps, side, scale, offset, offset + 2 * kPi, DegToRad(step_deg), &counts);
            // 0.01 deg through the flat stretch (the steps a user takes to look at it closely), the
            // samples shifted off the flat input by a thousandth of the offset
            const double shift = 1e-3 * offset;
            CheckSweep(l, eps, side, scale, flat - DegToRad(2.0) + shift, flat + DegToRad(2.0) + shift, DegToRad(0.01), &counts);
          }
        }
      }
    }
  }
  INFO(counts.sweeps << " sweeps, " << counts.rows << " rows, " << counts.gaps << " gaps");
  CHECK(counts.sweeps == 3 * 7 * 2 * 3 * 2 * 5);
  CHECK(counts.gaps > 0);
}

}  // namespace koppel::continuation_near_flat_test
