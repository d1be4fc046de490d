// Masses, units, gravity and loads in mechanism files: a good file read in all its parts and
// written back, and every kind of bad input with its line and a key phrase.
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_writer.hpp"

#include "support/text.hpp"

#include <catch2/catch.hpp>

namespace koppel::loads_reader_test {
namespace {

using test::LineOf;
using test::Replace;

const char* kGood = R"(koppel: 1
name: loaded
units: {length: mm}
gravity: [0, -9.81]
parameters:
  l1: 50
  F0: 300
links:
  frame:
    frame: true
    points: {A0: [0, 0], F: [0, 0], G: [-100, 20]}
  crank:
    points: {A0: [0, 0], A: [0, -l1]}
    mass: 1.5
    cg: [0, -10]
    inertia: 0.002
  coupler:
    points: {A: [0, 0], B: [160, 0], S2: [56, 0]}
    mass: 0.6
    cg: S2
  slider:
    points: {B: [0, 0]}
    mass: 0.4
    cg: B
    inertia: 0
joints:
  A0: {type: R, links: [frame, crank]}
  A: {type: R, links: [crank, coupler]}
  B: {type: R, links: [coupler, slider]}
  S: {type: P, links: [frame, slider], points: [F, B], axis: [1, 0]}
drive: {joint: A0}
outputs:
  s: {joint: S}
loads:
  piston: {force: slider.B, direction: [-1, 0], magnitude: F0*(1 + s/1000)}
  lift: {force: coupler.B, direction: [0, 2], in: coupler, magnitude: "10*sin(phi) + phi_dot/100 + t"}
  brake: {torque: crank, magnitude: -2}
  k: {spring: [frame.G, coupler.S2], stiffness: 2000, free_length: 80, damping: 5}
  c: {damper: [frame.G, slider.B], damping: 12}
assembly: {input: 0, points: {B: [150, 0]}}
)";

std::vector<Diagnostic> Bad(const std::string& text) {
  try {
    ParseMechanismText(text, "mech.yaml");
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  FAIL("the file was accepted");
  return {};
}

// The single diagnostic of `text`, which must be at the line of `needle` and contain `phrase`.
void ExpectError(const std::string& text, const std::string& needle, const std::string& phrase) {
  const std::vector<Diagnostic> d = Bad(text);
  INFO(InputError(d).what());
  REQUIRE(d.size() >= 1);
  CHECK(d[0].line == LineOf(text, needle));
  CHECK_THAT(d[0].message, Catch::Contains(phrase));
}

}  // namespace

TEST_CASE("a mechanism file with masses and loads reads in all its parts", "[loads]") {
  const MechanismFile f = ParseMechanismText(kGood, "loaded.yaml");
  const Loads& l = f.loads;
  const Mechanism& m = f.mechanism;
  CHECK(l.metres_per_unit == 0.001);
  CHECK(l.gravity == Eigen::Vector2d(0, -9.81));
  REQUIRE(l.masses.size() == 3);
  CHECK(l.masses[0].link == m.FindLink("crank"));
  CHECK(l.masses[0].mass == 1.5);
  CHECK(l.masses[0].centre == Eigen::Vector2d(0, -10));
  CHECK(l.masses[0].inertia == 0.002);
  CHECK(l.masses[1].centre == Eigen::Vector2d(56, 0));  // the point S2
  CHECK(l.masses[1].inertia == 0.0);                    // a point mass unless given
  REQUIRE(l.forces.size() == 2);
  CHECK(l.forces[0].point.link == m.FindLink("slider"));
  CHECK(l.forces[0].direction == Eigen::Vector2d(-1, 0));
  CHECK(l.forces[0].direction_link == m.FrameLink());
  CHECK(l.forces[0].magnitude == "F0*(1 + s/1000)");
  CHECK(l.forces[1].direction == Eigen::Vector2d(0, 1));  // made unit
  CHECK(l.forces[1].direction_link == m.FindLink("coupler"));
  REQUIRE(l.torques.size() == 1);
  CHECK(l.torques[0].link == m.FindLink("crank"));
  REQUIRE(l.springs.size() == 2);
  CHECK(l.springs[0].stiffness == 2000);
  CHECK(l.springs[0].free_length == 80);
  CHECK(l.springs[0].damping == 5);
  CHECK(l.springs[1].stiffness == 0);
  CHECK(l.springs[1].damping == 12);
  CHECK(l.parameters.Value("F0") == 300);
  CHECK(CheckLoads(m, l).empty());
}

TEST_CASE("length units by name or in metres; SI by default", "[loads]") {
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}", "units: {length: in}"), "x.yaml").loads.metres_per_unit == 0.0254);
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}", "units: {length: 1/1000}"), "x.yaml").loads.metres_per_unit == 0.001);
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}\n", ""), "x.yaml").loads.metres_per_unit == 1.0);
  // whether the file names its unit (a DXF says so in $INSUNITS, else it is unitless)
  CHECK(ParseMechanismText(kGood, "x.yaml").loads.length_unit_given);
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}", "units: {length: 1/1000}"), "x.yaml").loads.length_unit_given);
  CHECK_FALSE(ParseMechanismText(Replace(kGood, "units: {length: mm}\n", ""), "x.yaml").loads.length_unit_given);
}

TEST_CASE("the length unit is labelled as the file names it (issue 22, item 14)", "[loads]") {
  CHECK(ParseMechanismText(kGood, "x.yaml").loads.LengthUnit() == "mm");  // was "length"
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}", "units: {length: in}"), "x.yaml").loads.LengthUnit() == "in");
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}", "units: {length: 0.005}"), "x.yaml").loads.LengthUnit() == "0.005 m");
  CHECK(ParseMechanismText(Replace(kGood, "units: {length: mm}\n", ""), "x.yaml").loads.LengthUnit() == "length");
  // and written back by name
  const MechanismFile f = ParseMechanismText(kGood, "loaded.yaml");
  const std::string text = WriteMechanismYaml(f.mechanism, "round trip", f.sweep, f.parameters.Values(), &f.loads);
  CHECK_THAT(text, Catch::Contains("units: {length: mm}"));
  CHECK(ParseMechanismText(text, "again.yaml").loads.LengthUnit() == "mm");
}

TEST_CASE("the writer writes masses and loads that read back the same", "[loads]") {
  const MechanismFile f = ParseMechanismText(kGood, "loaded.yaml");
  const std::string text = WriteMechanismYaml(f.mechanism, "round trip", f.sweep, f.parameters.Values(), &f.loads);
  const MechanismFile g = ParseMechanismText(text, "again.yaml");
  const Loads &a = f.loads, &b = g.loads;
  CHECK(b.metres_per_unit == a.metres_per_unit);
  CHECK(b.length_unit_given == a.length_unit_given);
  // a file in metres that says so still says so when written again
  const MechanismFile metres = ParseMechanismText(Replace(kGood, "units: {length: mm}", "units: {length: m}"), "m.yaml");
  const std::string metres_text = WriteMechanismYaml(metres.mechanism, "metres", metres.sweep, metres.parameters.Values(), &metres.loads);
  CHECK(ParseMechanismText(metres_text, "m2.yaml").loads.length_unit_given);
  CHECK(b.gravity == a.gravity);
  REQUIRE(b.masses.size() == a.masses.size());
  for (size_t i = 0; i < a.masses.size(); ++i) {
    CHECK(b.masses[i].link == a.masses[i].link);
    CHECK(b.masses[i].mass == a.masses[i].mass);
    CHECK(b.masses[i].centre == a.masses[i].centre);
    CHECK(b.masses[i].inertia == a.masses[i].inertia);
  }
  REQUIRE(b.forces.size() == 2);
  CHECK(b.forces[1].magnitude == a.forces[1].magnitude);
  CHECK(b.forces[1].direction == a.forces[1].direction);
  CHECK(b.forces[1].direction_link == a.forces[1].direction_link);
  REQUIRE(b.springs.size() == 2);
  CHECK(b.springs[0].free_length == a.springs[0].free_length);
  CHECK(b.springs[1].damping == a.springs[1].damping);
  CHECK(b.torques[0].magnitude == a.torques[0].magnitude);
}

TEST_CASE("bad masses and loads are reported at their line", "[loads]") {
  const std::string good = kGood;
  ExpectError(Replace(good, "    mass: 1.5\n", "    mass: -1.5\n"), "mass: -1.5", "must not be negative");
  ExpectError(Replace(good, "    cg: S2\n", "    cg: S9\n"), "cg: S9", "has no point 'S9'");
  ExpectError(Replace(good, "    cg: [0, -10]\n", ""), "mass: 1.5", "mass and its centre of gravity (cg) together");
  ExpectError(Replace(good, "    frame: true\n", "    frame: true\n    mass: 3\n    cg: [0, 0]\n"), "mass: 3", "is the frame");
  ExpectError(Replace(good, "    inertia: 0.002\n", "    inertia: 0.002\n    inertiaa: 1\n"), "inertiaa", "did you mean 'inertia'");
  ExpectError(Replace(good, "units: {length: mm}", "units: {length: furlong}"), "furlong", "unknown length unit 'furlong'");
  ExpectError(Replace(good, "units: {length: mm}", "units: {length: -2}"), "length: -2", "positive number of metres");
  // a unit word koppel does not know: the names it knows, not "does not parse"
  ExpectError(Replace(good, "units: {length: mm}", "units: {length: inch}"), "length: inch", "unknown length unit 'inch': the length unit must be m, dm, cm, mm, um, km, in, ft");
  ExpectError(Replace(good, "gravity: [0, -9.81]", "gravity: 9.81"), "gravity: 9.81", "expected a point");
  ExpectError(Replace(good, "magnitude: F0*(1 + s/1000)", "magnitude: F0*(1 + q/1000)"), "piston", "unknown name 'q'");
  ExpectError(Replace(good, "force: slider.B", "force: slider.Q"), "piston", "'slider.Q' is no point");
  ExpectError(Replace(good, "direction: [-1, 0]", "direction: [0, 0]"), "piston", "must not be zero");
  ExpectError(Replace(good, "in: coupler", "in: coupla"), "lift", "unknown link 'coupla'");
  ExpectError(Replace(good, "torque: crank", "torque: frame"), "brake", "the frame does not move");
  ExpectError(Replace(good, "stiffness: 2000, ", ""), "k: {spring", "missing required key 'stiffness'");
  ExpectError(Replace(good, "damping: 12", "damping: -12"), "c: {damper", "must not be negative");
  ExpectError(Replace(good, "c: {damper: [frame.G, slider.B]", "c: {damper: [frame.G]"), "c: {damper", "expected two points");
  ExpectError(Replace(good, "brake: {torque: crank,", "brake: {torque: crank, spring: [frame.G, slider.B],"), "brake",
              "exactly one of force, torque, spring, damper");
  ExpectError(Replace(good, "  F0: 300\n", "  F0: 300\n  t: 2\n"), "t: 2", "parameter 't' has the name of a load formula variable");
  ExpectError(Replace(good, "brake: {torque: crank, magnitude: -2}", "brake: {torque: crank}"), "brake", "missing required key 'magnitude'");
}

}  // namespace koppel::loads_reader_test
