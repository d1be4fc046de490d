// Statics and kinetostatics (AnalyseForces) against seed 000's closed form, against the balance
// of every link computed here from the reported reactions, and against the power balance of a
// four-bar whose kinetic energy comes from the sweep's own transfer functions.
#include "koppel/analysis/forces.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/constraints.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::forces_test {
namespace {

// the normal force is the reaction's projection on the slide's normal, computed again here: the same
// two products of O(1) numbers, different only by the rounding of the rotation
constexpr double kSameProjection = 1e-12;

// Drive torque against a closed form: both exact, so they agree to roundoff of sums of O(10)
// terms of the loads' size.
constexpr double kExact = 1e-9;
// Sums of forces and moments over a link: O(10) terms, each up to the largest force times the
// largest lever; roundoff and the Newton tolerance (1e-13 L) leave far less than this fraction.
constexpr double kBalance = 1e-9;
// Central difference of the kinetic energy over the input with h = 1e-4 rad: truncation
// h^2/6 |E'''| ~ 2e-9 of E's scale, roundoff eps |E| / h ~ 1e-12.
constexpr double kEnergyDifference = 1e-7;
constexpr double kGravity = 9.81;

Eigen::Vector2d Rotate(double theta, const Eigen::Vector2d& v) {
  return {std::cos(theta) * v.x() - std::sin(theta) * v.y(), std::sin(theta) * v.x() + std::cos(theta) * v.y()};
}
double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The test's own forward kinematics from the coordinate layout (x, y, theta per moving link).
struct Poser {
  const Mechanism& m;
  ConstraintSystem system;
  explicit Poser(const Mechanism& mechanism) : m(mechanism), system(mechanism) {}
  double Angle(const Eigen::VectorXd& q, int link) const {
    const int i = system.CoordinateOf(link);
    return i < 0 ? 0.0 : q(i + 2);
  }
  Eigen::Vector2d Global(const Eigen::VectorXd& q, int link, const Eigen::Vector2d& local) const {
    const int i = system.CoordinateOf(link);
    if (i < 0) return local;
    return Eigen::Vector2d(q(i), q(i + 1)) + Rotate(q(i + 2), local);
  }
  Eigen::Vector2d Global(const Eigen::VectorXd& q, const PointRef& p) const {
    return Global(q, p.link, m.links[p.link].points[p.point].local);
  }
};

// Sum of forces and of moments about the global origin on every link.
struct Wrenches {
  std::vector<Eigen::Vector2d> force;
  std::vector<double> moment;
  double largest = 0.0;  // the largest force or moment added: the scale of the sums
  explicit Wrenches(size_t links) : force(links, Eigen::Vector2d::Zero()), moment(links, 0.0) {}
  void Add(int link, const Eigen::Vector2d& at, const Eigen::Vector2d& f) {
    force[link] += f;
    moment[link] += Cross(at, f);
    largest = std::max({largest, f.norm(), std::abs(Cross(at, f))});
  }
  void AddMoment(int link, double value) {
    moment[link] += value;
    largest = std::max(largest, std::abs(value));
  }
};

// Every joint's reaction on both its links and the drive's torque, from the reported row:
// the R joint force acts at the joint point, the P joint force and moment at the block's point.
void AddReactions(const Poser& poser, const ForcesRow& row, Wrenches& w) {
  const Mechanism& m = poser.m;
  for (size_t k = 0; k < m.joints.size(); ++k) {
    const Joint& j = m.joints[k];
    const Eigen::Vector2d at = poser.Global(row.q, {j.link_b, j.point_b});
    const JointReaction& r = row.joints[k];
    w.Add(j.link_b, at, r.force);
    w.Add(j.link_a, at, -r.force);
    if (j.type == JointType::kPrismatic) {
      w.AddMoment(j.link_b, r.moment);
      w.AddMoment(j.link_a, -r.moment);
      const Eigen::Vector2d axis = Rotate(poser.Angle(row.q, j.link_a), j.axis);
      CHECK(std::abs(r.force.dot(axis)) <= kBalance * std::max(1.0, r.force.norm()));  // a slide carries no force along it
      CHECK_THAT(r.normal, Catch::Matchers::WithinAbs(r.force.dot(Eigen::Vector2d(-axis.y(), axis.x())), kSameProjection));
    }
  }
  const Joint& d = m.joints[m.drive.joint];
  if (d.type == JointType::kRevolute) {
    w.AddMoment(d.link_b, row.drive);
    w.AddMoment(d.link_a, -row.drive);
  } else {
    const Eigen::Vector2d at = poser.Global(row.q, {d.link_b, d.point_b});
    const Eigen::Vector2d f = row.drive * Rotate(poser.Angle(row.q, d.link_a), d.axis);
    w.Add(d.link_b, at, f);
    w.Add(d.link_a, at, -f);
  }
}

void CheckBalanced(const Mechanism& m, const Wrenches& w) {
  for (size_t l = 0; l < m.links.size(); ++l) {
    if (m.links[l].is_frame) continue;
    INFO("link " << m.links[l].name);
    CHECK(w.force[l].norm() <= kBalance * w.largest);
    CHECK(std::abs(w.moment[l]) <= kBalance * w.largest);
  }
}

SweepOptions Degrees(double from, double to, double step) {
  SweepOptions s;
  s.from = DegToRad(from);
  s.to = DegToRad(to);
  s.step = DegToRad(step);
  return s;
}

PointForce ForceAt(const Mechanism& m, const std::string& link, const std::string& point, Eigen::Vector2d direction,
                   const std::string& magnitude) {
  PointForce f;
  f.name = "F";
  f.point = {m.FindLink(link), m.links[m.FindLink(link)].FindPoint(point)};
  f.direction = direction.normalized();
  f.direction_link = m.FrameLink();
  f.magnitude = magnitude;
  return f;
}

// A link's centre of gravity as a named point "S" with point and angle outputs "S_<link>" and
// "theta_<link>", so that the sweep itself gives their exact transfer functions.
void AddMass(Mechanism& m, Loads& loads, const std::string& link, double mass, Eigen::Vector2d centre, double inertia) {
  const int l = m.FindLink(link);
  m.links[l].points.push_back({"S", centre});
  loads.masses.push_back({l, mass, centre, inertia});
  Output s;
  s.name = "S_" + link;
  s.kind = OutputKind::kPoint;
  s.p = {l, static_cast<int>(m.links[l].points.size()) - 1};
  Output theta;
  theta.name = "theta_" + link;
  theta.kind = OutputKind::kLinkAngle;
  theta.link = l;
  m.outputs.push_back(s);
  m.outputs.push_back(theta);
}

// The kinematics of each mass at sweep row i: p, p', p'' of its centre and theta', theta''.
struct MassMotion {
  Eigen::Vector2d p, d1, d2;
  double w1, w2;
};
MassMotion MotionOf(const Mechanism& m, const SweepResult& sweep, const std::string& link, int row) {
  const int s = m.FindOutput("S_" + link), t = m.FindOutput("theta_" + link);
  const int x = OutputColumn(m, s, 0, sweep.order), y = OutputColumn(m, s, 1, sweep.order), a = OutputColumn(m, t, 0, sweep.order);
  const auto& o = sweep.outputs;
  return {{o(row, x), o(row, y)}, {o(row, x + 1), o(row, y + 1)}, {o(row, x + 2), o(row, y + 2)}, o(row, a + 1), o(row, a + 2)};
}

}  // namespace

TEST_CASE("slider-crank with a force on the slider: drive torque = F s'(phi) (seed 000)", "[forces]") {
  const double l1 = 1.0, l2 = 2.6, force = 100.0;
  for (double e : {0.0, 0.8, -0.8}) {
    INFO("e = " << e);
    const Mechanism m = test::SliderCrank(l1, l2, e);
    Loads loads;
    loads.forces.push_back(ForceAt(m, "slider", "B", {-1, 0}, "100"));  // pushes back against the stroke
    ForcesOptions options;
    options.sweep = Degrees(0, 360, 5);
    const ForcesResult r = AnalyseForces(m, loads, options);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    REQUIRE(r.rows.size() == 73);
    CHECK(r.worst_disagreement < kVirtualWorkAgreement);
    const Poser poser(m);
    for (const ForcesRow& row : r.rows) {
      INFO("phi = " << RadToDeg(row.input));
      REQUIRE(row.computed);
      const double expected = force * test::SliderCrank(l1, l2, e, row.input).s1;
      CHECK_THAT(row.drive, Catch::Matchers::WithinAbs(expected, kExact * force * l1));
      CHECK_THAT(row.drive_virtual_work, Catch::Matchers::WithinAbs(expected, kExact * force * l1));
      // every link in balance under its joint reactions and the load
      Wrenches w(m.links.size());
      AddReactions(poser, row, w);
      w.Add(m.FindLink("slider"), poser.Global(row.q, m.FindLink("slider"), {0, 0}), {-force, 0});
      CheckBalanced(m, w);
    }
  }
}

TEST_CASE("reactions balance every link under gravity, springs, torques and inertia", "[forces]") {
  Mechanism m = test::SliderCrank(0.1, 0.35, 0.02);
  Loads loads;
  AddMass(m, loads, "crank", 2.0, {0.01, -0.03}, 0.004);
  AddMass(m, loads, "coupler", 0.8, {0.12, 0.01}, 0.009);
  AddMass(m, loads, "slider", 0.5, {0.0, 0.0}, 0.0);
  loads.gravity = {0.0, -kGravity};
  loads.forces.push_back(ForceAt(m, "slider", "B", {-1, 0.2}, "50 + 20*sin(phi)"));
  loads.torques.push_back({"M", m.FindLink("coupler"), "3*cos(phi)"});
  m.links[0].points.push_back({"G", {-0.2, 0.3}});
  SpringDamper spring;
  spring.name = "k";
  spring.from = {0, static_cast<int>(m.links[0].points.size()) - 1};
  spring.to = {m.FindLink("coupler"), m.links[m.FindLink("coupler")].FindPoint("B")};
  spring.stiffness = 800.0;
  spring.free_length = 0.3;
  spring.damping = 4.0;
  loads.springs.push_back(spring);
  loads.parameters = ParameterSet();

  for (double rpm : {0.0, 900.0}) {
    INFO("speed " << rpm << " rpm");
    const double omega = rpm * 2 * kPi / 60;
    ForcesOptions options;
    options.sweep = Degrees(0, 360, 15);
    options.sweep.order = 2;
    if (rpm > 0) options.speed = omega;
    const ForcesResult r = AnalyseForces(m, loads, options);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    const SweepResult sweep = Sweep(m, options.sweep);  // the masses' motion, independently
    REQUIRE(sweep.inputs.size() == r.rows.size());
    const Poser poser(m);
    for (size_t i = 0; i < r.rows.size(); ++i) {
      const ForcesRow& row = r.rows[i];
      INFO("phi = " << RadToDeg(row.input));
      REQUIRE(row.computed);
      Wrenches w(m.links.size());
      AddReactions(poser, row, w);
      for (const LinkMass& mass : loads.masses) {
        const MassMotion mm = MotionOf(m, sweep, m.links[mass.link].name, static_cast<int>(i));
        w.Add(mass.link, mm.p, mass.mass * loads.gravity);
        w.Add(mass.link, mm.p, -mass.mass * mm.d2 * omega * omega);  // d'Alembert at constant speed
        w.AddMoment(mass.link, -mass.inertia * mm.w2 * omega * omega);
      }
      const double magnitude = 50 + 20 * std::sin(row.input);
      w.Add(m.FindLink("slider"), poser.Global(row.q, m.FindLink("slider"), {0, 0}), magnitude * Eigen::Vector2d(-1, 0.2).normalized());
      w.AddMoment(m.FindLink("coupler"), 3 * std::cos(row.input));
      // the spring-damper: tension k (r - l0) + c dr/dt along the line G -> B
      const Eigen::Vector2d g = poser.Global(row.q, spring.from), b = poser.Global(row.q, spring.to);
      const MassMotion slider = MotionOf(m, sweep, "slider", static_cast<int>(i));  // B is the slider's centre
      const Eigen::Vector2d u = (b - g).normalized();
      const double tension = spring.stiffness * ((b - g).norm() - spring.free_length) + spring.damping * u.dot(slider.d1) * omega;
      w.Add(m.FindLink("coupler"), b, -tension * u);
      CheckBalanced(m, w);
    }
  }
}

TEST_CASE("four-bar with masses at constant speed: drive torque = dE/dt / speed at every row", "[forces]") {
  Mechanism m = test::FourBar(1.0, 3.5, 2.5, 3.0, 2.0, 0.4, +1);
  Loads loads;
  AddMass(m, loads, "crank", 1.2, {0.4, 0.05}, 0.05);
  AddMass(m, loads, "coupler", 2.0, {1.6, 0.5}, 0.9);
  AddMass(m, loads, "rocker", 1.5, {1.1, -0.1}, 0.4);
  const double omega = 300 * 2 * kPi / 60;
  for (bool gravity : {false, true}) {
    INFO((gravity ? "with" : "without") << " gravity");
    loads.gravity = gravity ? Eigen::Vector2d(0, -kGravity) : Eigen::Vector2d::Zero();
    ForcesOptions options;
    options.sweep = Degrees(0, 360, 10);
    options.sweep.order = 2;
    options.speed = omega;
    const ForcesResult r = AnalyseForces(m, loads, options);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    const SweepResult sweep = Sweep(m, options.sweep);
    // E = 1/2 omega^2 sum (m p'.p' + J theta'^2) - sum m g.p over the input, with h = 1e-4 rad
    const double h = 1e-4;
    SweepOptions below = options.sweep, above = options.sweep;
    below.from -= h;
    below.to -= h;
    above.from += h;
    above.to += h;
    const SweepResult low = Sweep(m, below), high = Sweep(m, above);
    REQUIRE((sweep.complete() && low.complete() && high.complete()));
    auto energy = [&](const SweepResult& s, int row) {
      double e = 0.0;
      for (const LinkMass& mass : loads.masses) {
        const MassMotion mm = MotionOf(m, s, m.links[mass.link].name, row);
        e += 0.5 * omega * omega * (mass.mass * mm.d1.squaredNorm() + mass.inertia * mm.w1 * mm.w1) - mass.mass * loads.gravity.dot(mm.p);
      }
      return e;
    };
    double scale = 0.0, worst = 0.0, worst_difference = 0.0;
    for (size_t i = 0; i < r.rows.size(); ++i) {
      // dE/dt / omega = dE/dphi: exactly, from the second-order transfer functions
      double power = 0.0;
      for (const LinkMass& mass : loads.masses) {
        const MassMotion mm = MotionOf(m, sweep, m.links[mass.link].name, static_cast<int>(i));
        power += omega * omega * (mass.mass * mm.d1.dot(mm.d2) + mass.inertia * mm.w1 * mm.w2) - mass.mass * loads.gravity.dot(mm.d1);
      }
      const double difference = (energy(high, static_cast<int>(i)) - energy(low, static_cast<int>(i))) / (2 * h);
      scale = std::max(scale, std::abs(power));
      worst = std::max(worst, std::abs(r.rows[i].drive - power));
      worst_difference = std::max(worst_difference, std::abs(r.rows[i].drive - difference));
    }
    INFO("largest |dE/dt / omega| " << scale << " N m; worst |torque - dE/dt / omega| " << worst << " (exact reference), "
                                    << worst_difference << " (central difference)");
    CHECK(worst <= kExact * scale);
    CHECK(worst_difference <= kEnergyDifference * scale);
  }
}

TEST_CASE("the length unit: a mechanism in mm gives the forces it gives in m", "[forces]") {
  // scale every length by 1000 and declare 1 unit = 1 mm
  auto scaled = [](Mechanism m, double factor) {
    for (Link& l : m.links) {
      for (NamedPoint& p : l.points) p.local *= factor;
    }
    for (AssemblyHint::Entry& e : m.hint.points) e.global *= factor;
    if (!m.InputIsAngle()) m.hint.input *= factor;
    return m;
  };
  for (bool slide_drive : {false, true}) {
    INFO((slide_drive ? "P drive" : "R drive"));
    Mechanism metres = test::SliderCrank(0.1, 0.26, 0.03);
    if (slide_drive) {
      metres.drive.joint = metres.FindJoint("S");
      metres.drive.input_name = "s_in";
      metres.hint.input = 0.3;
      metres.hint.points[0].global = {0.3, 0.0};
      metres.hint.points.push_back({{1, 1}, Rotate(DegToRad(60), {0, -0.1}) + Eigen::Vector2d(0, -0.03)});
    }
    const Mechanism millimetres = scaled(metres, 1000.0);
    auto loads_for = [&](const Mechanism& m, double metres_per_unit) {
      Loads loads;
      loads.metres_per_unit = metres_per_unit;
      loads.gravity = {0, -kGravity};
      loads.masses.push_back({2, 0.8, Eigen::Vector2d(0.1, 0.01) / metres_per_unit, 0.004});
      loads.masses.push_back({1, 0.3, Eigen::Vector2d(0.0, -0.05) / metres_per_unit, 0.001});
      loads.forces.push_back(ForceAt(m, "slider", "B", {-1, 0}, "40"));
      loads.torques.push_back({"M", 1, "-2"});
      return loads;
    };
    ForcesOptions a, b;
    if (slide_drive) {
      a.sweep.from = 0.2;
      a.sweep.to = 0.34;
      a.sweep.step = 0.02;
    } else {
      a.sweep = Degrees(0, 360, 30);
    }
    a.speed = slide_drive ? 0.5 : 50.0;
    b = a;
    if (slide_drive) {
      b.sweep.from *= 1000;
      b.sweep.to *= 1000;
      b.sweep.step *= 1000;
      *b.speed *= 1000;
    }
    const ForcesResult in_m = AnalyseForces(metres, loads_for(metres, 1.0), a);
    const ForcesResult in_mm = AnalyseForces(millimetres, loads_for(millimetres, 0.001), b);
    REQUIRE(in_m.status == AnalysisStatus::kComplete);
    REQUIRE(in_mm.status == AnalysisStatus::kComplete);
    REQUIRE(in_m.rows.size() == in_mm.rows.size());
    for (size_t i = 0; i < in_m.rows.size(); ++i) {
      const ForcesRow &x = in_m.rows[i], &y = in_mm.rows[i];
      const double size = std::abs(x.drive) + 1.0;
      CHECK_THAT(y.drive, Catch::Matchers::WithinAbs(x.drive, kExact * size));
      CHECK(y.reduced_inertia == Approx(x.reduced_inertia).epsilon(kExact));
      CHECK_THAT(y.reduced_inertia_derivative, Catch::Matchers::WithinAbs(x.reduced_inertia_derivative, kExact * (std::abs(x.reduced_inertia_derivative) + 1)));
      for (size_t k = 0; k < x.joints.size(); ++k) {
        CHECK((y.joints[k].force - x.joints[k].force).norm() <= kExact * (x.joints[k].force.norm() + 1.0));
        CHECK_THAT(y.joints[k].moment, Catch::Matchers::WithinAbs(x.joints[k].moment, kExact * (std::abs(x.joints[k].moment) + 1.0)));
      }
    }
  }
}

TEST_CASE("slider-crank driven at the slider: drive force = -M / s'(phi) for a torque M on the crank", "[forces]") {
  const double l1 = 1.0, l2 = 2.6, e = 0.8, torque = 7.0;
  Mechanism m = test::SliderCrank(l1, l2, e);
  m.drive.joint = m.FindJoint("S");
  m.hint.input = 2.5;
  m.hint.points[0].global = {2.5, 0.0};
  m.hint.points.push_back({{1, 1}, Rotate(DegToRad(60), {0, -l1}) + Eigen::Vector2d(0, -e)});
  Loads loads;
  loads.torques.push_back({"M", m.FindLink("crank"), "7"});
  ForcesOptions options;
  options.sweep.from = 1.5;
  options.sweep.to = 3.4;
  options.sweep.step = 0.1;
  const ForcesResult r = AnalyseForces(m, loads, options);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  for (const ForcesRow& row : r.rows) {
    const double phi = row.q(2);  // the crank's angle is the seed's phi (A = A0 + l1 (sin phi, -cos phi))
    INFO("s = " << row.input << ", phi = " << RadToDeg(phi));
    const double expected = -torque / test::SliderCrank(l1, l2, e, phi).s1;
    CHECK_THAT(row.drive, Catch::Matchers::WithinAbs(expected, kExact * std::abs(expected)));
    const Poser poser(m);
    Wrenches w(m.links.size());
    AddReactions(poser, row, w);
    w.AddMoment(m.FindLink("crank"), torque);
    CheckBalanced(m, w);
  }
}

TEST_CASE("singular rows carry no forces and make the result partial", "[forces]") {
  // a parallelogram four-bar folds flat at phi = 0: a branch point, where the reactions are
  // not determined
  Mechanism m = test::FourBar(1.0, 3.0, 1.0, 3.0, 1.0, 0.0, +1);
  m.hint.input = DegToRad(-20);
  m.hint.points = {{{2, 1}, Eigen::Vector2d(3, 0) + Rotate(DegToRad(-20), {1, 0})}};
  Loads loads;
  loads.torques.push_back({"M", 3, "1"});
  ForcesOptions options;
  options.sweep = Degrees(-30, 30, 10);
  const ForcesResult r = AnalyseForces(m, loads, options);
  REQUIRE(r.status == AnalysisStatus::kPartial);
  int singular = 0;
  for (const ForcesRow& row : r.rows) {
    INFO("phi = " << RadToDeg(row.input));
    CHECK(row.computed == !row.singular);
    if (row.singular) {
      ++singular;
      CHECK(std::abs(row.input) < 1e-12);
      CHECK_THAT(row.problem, Catch::Contains("singular"));
      CHECK(row.joints.empty());
    } else {
      CHECK_THAT(row.drive, Catch::Matchers::WithinAbs(-1.0, kExact));  // the rocker turns with the crank: M is held by -M
    }
  }
  CHECK(singular == 1);
  CHECK_THAT(r.message, Catch::Contains("1 of 7"));
}

TEST_CASE("redundant joints: drive torque by virtual work, reactions statically indeterminate", "[forces]") {
  // a parallelogram with a third parallel crank: 13 equations for 12 coordinates
  Mechanism m;
  m.name = "double-parallelogram";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {3, 0}}, {"C0", {1.5, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {3, 0}}, {"C", {1.5, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {1, 0}}}},
             {"middle", false, {{"C0", {0, 0}}, {"C", {1, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1), PinJoint(m, "A", 1, 2), PinJoint(m, "B", 2, 3), PinJoint(m, "B0", 0, 3),
              PinJoint(m, "C", 2, 4), PinJoint(m, "C0", 0, 4)};
  m.drive.joint = 0;
  m.hint.input = DegToRad(60);
  m.hint.points.push_back({{2, 0}, {0.5, std::sqrt(0.75)}});
  m.hint.points.push_back({{2, 1}, {3.5, std::sqrt(0.75)}});
  REQUIRE(CheckConsistency(m).empty());
  Loads loads;
  loads.gravity = {0, -kGravity};
  loads.masses.push_back({2, 2.0, {1.5, 0}, 0.3});
  ForcesOptions options;
  options.sweep = Degrees(30, 150, 30);
  const ForcesResult r = AnalyseForces(m, loads, options);
  CHECK(r.indeterminate);
  CHECK(r.status == AnalysisStatus::kPartial);
  CHECK_THAT(r.message, Catch::Contains("statically indeterminate"));
  for (const ForcesRow& row : r.rows) {
    CHECK_FALSE(row.computed);
    REQUIRE(row.virtual_work);
    // the coupler translates on a circle of radius 1: V = m g sin(phi), so the drive holds m g cos(phi)
    CHECK_THAT(row.drive_virtual_work, Catch::Matchers::WithinAbs(2.0 * kGravity * std::cos(row.input), kExact * 20));
    CHECK(row.reduced_inertia == Approx(2.0).epsilon(kExact));
  }
}

TEST_CASE("invalid loads and a formula without a value are reported, not computed", "[forces]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  Loads loads;
  loads.forces.push_back(ForceAt(m, "slider", "B", {1, 0}, "1 + nosuch"));
  ForcesOptions options;
  options.sweep = Degrees(0, 90, 30);
  ForcesResult r = AnalyseForces(m, loads, options);
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK(r.bad_input);
  CHECK_THAT(r.message, Catch::Contains("force 'F'") && Catch::Contains("nosuch"));

  loads.forces[0].magnitude = "sqrt(0.6 - phi)";  // no value beyond phi = 0.6 rad = 34 deg
  r = AnalyseForces(m, loads, options);
  REQUIRE(r.status == AnalysisStatus::kPartial);
  REQUIRE(r.rows.size() == 4);
  CHECK(r.rows[1].computed);
  CHECK_FALSE(r.rows[2].computed);
  CHECK_THAT(r.rows[2].problem, Catch::Contains("no finite value"));

  loads.forces.clear();
  loads.masses.push_back({0, 1.0, {0, 0}, 0.0});  // on the frame
  r = AnalyseForces(m, loads, options);
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK(r.bad_input);
  CHECK_THAT(r.message, Catch::Contains("frame"));
}

}  // namespace koppel::forces_test
