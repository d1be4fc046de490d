// First-order sensitivities (sensitivity.hpp) on seed 000's slider-crank (l1, l2, e): the pose's
// dq/dp against central differences of poses solved anew, the output's directional derivative
// against a central difference along the direction, ds/dp and dmu/dp against central differences
// of seed 000's closed form, the crank pin's play against the geometry of the coupler
// (ds = delta . (B - A) / (B - A)_x, from |B - A'| = l2 with the slide along x), and the play of
// every joint against poses solved anew with the pin moved by hand, each output read off the links.
#include "koppel/analysis/sensitivity.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace koppel::sensitivity_test {
namespace {

// [1/1] a derivative against a central difference with step kH: truncation O(h^2 q''') ~ 1e-10
// and rounding O(eps / h) ~ 1e-11 of the reference, plus the Newton tolerance of two solved
// poses over 2 h
constexpr double kDifference = 1e-8;
constexpr double kH = 1e-5;
// [1/1] an exact gradient against the geometry's closed form: rounding of a converged pose
constexpr double kRoundoff = 1e-10;

// parameters l1, l2, e of seed 000's slider-crank; lengths must be positive
const MechanismBuilder kBuilder = [](const std::vector<double>& p) -> Expected<Mechanism> {
  if (!(p[0] > 0 && p[1] > 0)) return Expected<Mechanism>::Error("lengths must be positive");
  return test::SliderCrank(p[0], p[1], p[2]);
};
const std::vector<double> kNominal = {1.0, 2.6, 0.8};

// The pose at `input` [rad], reached from the assembly at 0 in steps of at most 10 degrees, so
// that it stays on the assembled branch; the solver's factorisation is then at q.
Eigen::VectorXd PoseAt(PositionSolver& solver, double input) {
  Eigen::VectorXd q;
  REQUIRE(solver.Assemble(q).ok());
  const int steps = static_cast<int>(std::ceil(std::abs(input) / DegToRad(10))) + 1;
  for (int k = 1; k <= steps; ++k) REQUIRE(solver.Correct(input * k / steps, q).ok());
  return q;
}

}  // namespace

TEST_CASE("Perturb builds the mechanisms at p +- step e_j, step = relative_step max(1, |p_j|)", "[sensitivity]") {
  const std::vector<double> p = {0.5, 2.6, -0.8};
  const double relative = 1e-3;
  Perturbations out;
  REQUIRE(Perturb(kBuilder, p, &out, relative));
  REQUIRE(out.step.size() == 3);
  // the definition: max(1, |p_j|) is 1, 2.6, 1
  CHECK(out.step[0] == relative);
  CHECK(out.step[1] == relative * 2.6);
  CHECK(out.step[2] == relative);
  for (int j = 0; j < 3; ++j) {
    std::vector<double> plus = p, minus = p;
    plus[j] += out.step[j];
    minus[j] -= out.step[j];
    const Mechanism reference_plus = *kBuilder(plus), reference_minus = *kBuilder(minus);
    INFO("parameter " << j);
    for (size_t l = 0; l < reference_plus.links.size(); ++l) {
      for (size_t k = 0; k < reference_plus.links[l].points.size(); ++k) {
        CHECK(out.plus[j].links[l].points[k].local == reference_plus.links[l].points[k].local);
        CHECK(out.minus[j].links[l].points[k].local == reference_minus.links[l].points[k].local);
      }
    }
  }
  // the default step is kParameterStep
  REQUIRE(Perturb(kBuilder, kNominal, &out));
  CHECK(out.step[1] == kParameterStep * 2.6);
}

TEST_CASE("Perturb is false when the builder refuses a perturbed value", "[sensitivity]") {
  // l1 = 1e-7 minus its step 1e-6 is negative: refused
  Perturbations out;
  CHECK_FALSE(Perturb(kBuilder, {1e-7, 2.6, 0.8}, &out, 1e-6));
}

TEST_CASE("PoseSensitivity is the derivative of the solved pose", "[sensitivity]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  Perturbations perturbed;
  REQUIRE(Perturb(kBuilder, kNominal, &perturbed));
  for (double degrees : {30.0, 100.0, 250.0}) {
    PositionSolver solver(m);
    const double input = DegToRad(degrees);
    const Eigen::VectorXd q = PoseAt(solver, input);
    for (int j = 0; j < 3; ++j) {
      // reference: (q(p + h e_j) - q(p - h e_j)) / 2h, each pose solved by Newton from q
      std::vector<double> plus = kNominal, minus = kNominal;
      plus[j] += kH;
      minus[j] -= kH;
      const Mechanism mp = *kBuilder(plus), mm = *kBuilder(minus);
      PositionSolver sp(mp), sm(mm);
      Eigen::VectorXd qp = q, qm = q;
      REQUIRE(sp.Correct(input, qp).ok());
      REQUIRE(sm.Correct(input, qm).ok());
      const Eigen::VectorXd reference = (qp - qm) / (2 * kH);
      const Eigen::VectorXd dq = PoseSensitivity(solver, q, input, perturbed, j);
      INFO("phi = " << degrees << ", parameter " << j);
      REQUIRE(dq.size() == q.size());
      CHECK((dq - reference).lpNorm<Eigen::Infinity>() <= kDifference * std::max(1.0, reference.lpNorm<Eigen::Infinity>()));
    }
  }
}

TEST_CASE("OutputDirectional is the derivative of the output along dq", "[sensitivity]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  PositionSolver solver(m);
  const Eigen::VectorXd q = PoseAt(solver, DegToRad(70));
  const ConstraintSystem& system = solver.system();
  // an arbitrary direction: the derivative holds for any q + t dq, converged or not
  Eigen::VectorXd dq(q.size());
  for (int i = 0; i < q.size(); ++i) dq[i] = 0.3 - 0.17 * i;
  for (const char* name : {"s", "mu"}) {
    const int output = m.FindOutput(name);
    REQUIRE(output >= 0);
    // reference: (y(q + h dq) - y(q - h dq)) / 2h
    const Eigen::VectorXd qp = q + kH * dq, qm = q - kH * dq;
    const double reference = (system.Output(output, 0, qp.data()) - system.Output(output, 0, qm.data())) / (2 * kH);
    INFO(name);
    CHECK(OutputDirectional(system, output, 0, q, dq) == Approx(reference).margin(kDifference));
  }
}

TEST_CASE("OutputSensitivity of s and mu against central differences of seed 000's closed form", "[sensitivity]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  Perturbations perturbed;
  REQUIRE(Perturb(kBuilder, kNominal, &perturbed));
  for (double degrees : {0.0, 60.0, 100.0, 250.0}) {
    PositionSolver solver(m);
    const double input = DegToRad(degrees);
    const Eigen::VectorXd q = PoseAt(solver, input);
    for (const char* name : {"s", "mu"}) {
      const int output = m.FindOutput(name);
      const bool angle = IsAngleOutput(m, m.outputs[output]);
      Eigen::MatrixXd d;
      OutputSensitivity(solver, q, input, perturbed, output, 0, 1, angle, &d);
      REQUIRE(d.rows() == 1);
      REQUIRE(d.cols() == 3);
      for (int j = 0; j < 3; ++j) {
        std::vector<double> plus = kNominal, minus = kNominal;
        plus[j] += kH;
        minus[j] -= kH;
        const test::SliderCrankValues vp = test::SliderCrank(plus[0], plus[1], plus[2], input);
        const test::SliderCrankValues vm = test::SliderCrank(minus[0], minus[1], minus[2], input);
        const double reference = std::string(name) == "s" ? (vp.s - vm.s) / (2 * kH) : (vp.mu - vm.mu) / (2 * kH);
        INFO("phi = " << degrees << ", " << name << ", parameter " << j);
        CHECK(d(0, j) == Approx(reference).margin(kDifference));
      }
    }
  }
}

TEST_CASE("the crank pin's play moves s along B - A by 1 / cos psi", "[sensitivity]") {
  const double l1 = 1.0, l2 = 2.6, e = 0.8;
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const int joint = m.FindJoint("A"), output = m.FindOutput("s");
  // the pin on the crank (link_a), its hole in the coupler (link_b)
  REQUIRE(m.links[m.joints[joint].link_a].name == "crank");
  REQUIRE(m.links[m.joints[joint].link_b].name == "coupler");
  for (double degrees : {0.0, 45.0, 170.0, 300.0}) {
    PositionSolver solver(m);
    const double input = DegToRad(degrees);
    const Eigen::VectorXd q = PoseAt(solver, input);
    // the header: the joint's point on link_a (the crank's A) is displaced by delta from its point
    // on link_b (the coupler's end A'), so A' = A - delta stays l2 from B = (s, 0) on the slide:
    // (B - A) . (ds e_x + delta) = 0, so ds/d delta = -(B - A) / (B - A)_x
    const double s = test::SliderCrank(l1, l2, e, input).s;
    const Eigen::Vector2d a(l1 * std::sin(input), -e - l1 * std::cos(input));
    const Eigen::Vector2d ba = Eigen::Vector2d(s, 0) - a;
    const Eigen::Vector2d reference = -ba / ba.x();
    const Eigen::Vector2d gradient = ClearanceGradient(solver, q, joint, output, 0);
    INFO("phi = " << degrees);
    CHECK(gradient.x() == Approx(reference.x()).margin(kRoundoff));
    CHECK(gradient.y() == Approx(reference.y()).margin(kRoundoff));
    // its length is 1 / cos psi, sin psi = -lambda cos phi - eps (seed 000)
    const double sin_psi = -(l1 / l2) * std::cos(input) - e / l2;
    CHECK(gradient.norm() == Approx(1 / std::sqrt(1 - sin_psi * sin_psi)).margin(kRoundoff));
  }
}

namespace {

// [1/1] a clearance gradient against central differences of poses solved anew with a pin moved by
// hand, step kPinStep: truncation h^2 y''' ~ 1e-10, the Newton tolerance 1e-13 L over 2 h ~ 1e-8
constexpr double kPinStep = 1e-5;
constexpr double kPinDifference = 1e-7;

// The acute angle between two lines of directions alpha and beta: a transmission angle by its
// definition, from the two links' directions.
double AcuteBetween(double alpha, double beta) {
  const double g = std::abs(WrapToHalfTurn(alpha - beta));
  return std::min(g, kPi - g);
}

// An output of a mechanism whose bars lie along their links' body x axes, read here from the link
// poses: a transmission angle as the acute angle between the coupler's and the output link's
// bars; any other through the kernel's formula (it reads the points and links it names).
double ReadOff(const ConstraintSystem& system, int output, int component, const Eigen::VectorXd& q) {
  const Output& o = system.mechanism().outputs[output];
  if (o.kind != OutputKind::kTransmissionAngle) return system.Output(output, component, q.data());
  const Joint& joint = system.mechanism().joints[o.joint];
  const int output_link = joint.link_a == o.link ? joint.link_b : joint.link_a;
  return AcuteBetween(system.LinkAngle(output_link, q.data()), system.LinkAngle(o.link, q.data()));
}

// |d y / d delta| by central differences: joint `joint`'s point on link_a (the other side from
// DisplacePin's link_b) moved by delta in link_a's frame as a new point, solved by Newton from the
// nominal pose q0. Its length does not depend on the frame delta is taken in.
double PinGradientByHand(const Mechanism& m, int joint, double input, const Eigen::VectorXd& q0, int output, int component) {
  const ConstraintSystem parts(m);  // the points an output names keep their indices after the move
  auto y = [&](const Eigen::Vector2d& delta) {
    Mechanism moved = m;
    Joint& j = moved.joints[joint];
    NamedPoint pin = moved.links[j.link_a].points[j.point_a];
    pin.local -= delta;
    moved.links[j.link_a].points.push_back(pin);
    j.point_a = static_cast<int>(moved.links[j.link_a].points.size()) - 1;
    PositionSolver solver(moved);
    Eigen::VectorXd q = q0;
    REQUIRE(solver.Correct(input, q).ok());
    return ReadOff(parts, output, component, q);
  };
  const double h = kPinStep;
  const bool angle = m.OutputIsAngle(output);
  auto difference = [&](double plus, double minus) { return (angle ? WrapToHalfTurn(plus - minus) : plus - minus) / (2 * h); };
  return std::hypot(difference(y({h, 0}), y({-h, 0})), difference(y({0, h}), y({0, -h})));
}

}  // namespace

TEST_CASE("the clearance gradient of every output at every joint against a pin moved by hand on the joint's other link", "[sensitivity]") {
  // a four-bar with a coupler point (point, rocker angle, joint angle, transmission angle), a
  // Watt six-bar with a transmission angle on its second loop, the slider-crank (slide, mu)
  Mechanism six_bar = test::WattSixBar();
  six_bar.outputs.push_back(
      Output{.name = "mu2", .kind = OutputKind::kTransmissionAngle, .joint = six_bar.FindJoint("D"), .link = six_bar.FindLink("link5"), .p = {}, .q = {}});
  for (const Mechanism& m : {test::FourBar(1, 3.5, 3, 4, 2, 0.5, +1), six_bar, test::SliderCrank(1.0, 2.6, 0.8)}) {
    PositionSolver solver(m);
    const double input = DegToRad(60);
    const Eigen::VectorXd q = PoseAt(solver, input);
    for (int joint = 0; joint < static_cast<int>(m.joints.size()); ++joint) {
      if (m.joints[joint].type != JointType::kRevolute) continue;
      for (int output = 0; output < static_cast<int>(m.outputs.size()); ++output) {
        for (int component = 0; component < m.outputs[output].Components(); ++component) {
          INFO(m.name << ", play at " << m.joints[joint].name << ", output " << m.outputs[output].name << " " << component);
          CHECK(ClearanceGradient(solver, q, joint, output, component).norm() ==
                Approx(PinGradientByHand(m, joint, input, q, output, component)).margin(kPinDifference));
        }
      }
    }
  }
}

TEST_CASE("OutputOnLinks: a transmission angle from the two links' directions where play opens the output joint", "[sensitivity]") {
  // the crank-rocker with the rocker's end of B moved by 0.05 in its hole: the kernel's formula
  // takes the coupler's end as the rocker's point too; read off the links, mu is the acute angle
  // between the coupler's bar and the rocker's
  const Mechanism parts = test::FourBar(1, 3.5, 3, 4, 0, 0, +1);
  Mechanism assembly = parts;
  DisplacePin(&assembly, assembly.FindJoint("B"), Eigen::Vector2d(0.03, -0.04));
  PositionSolver solver(assembly);
  const Eigen::VectorXd q = PoseAt(solver, DegToRad(60));
  const ConstraintSystem links(parts);
  const int mu = parts.FindOutput("mu"), psi = parts.FindOutput("psi");
  const double reference = AcuteBetween(links.LinkAngle(parts.FindLink("rocker"), q.data()), links.LinkAngle(parts.FindLink("coupler"), q.data()));
  CHECK(OutputOnLinks(links, mu, 0, q) == Approx(reference).margin(kRoundoff));
  // the kernel's formula reads another angle here (else this test would prove nothing)
  CHECK(std::abs(links.Output(mu, 0, q.data()) - reference) > 1e-3);
  // every other output is the kernel's
  CHECK(OutputOnLinks(links, psi, 0, q) == links.Output(psi, 0, q.data()));
}

}  // namespace koppel::sensitivity_test
