// The load model's checks and the names its formulas may use.
#include "koppel/core/loads.hpp"

#include <catch2/catch.hpp>

namespace koppel::loads_test {

namespace {
Mechanism TwoLinks() {
  Mechanism m;
  m.name = "m";
  m.links = {{"frame", true, {{"A0", {0, 0}}}}, {"rod", false, {{"A0", {0, 0}}, {"K", {1, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1)};
  m.drive.joint = 0;
  Output k;
  k.name = "K";
  k.kind = OutputKind::kPoint;
  k.p = {1, 1};
  Output psi;
  psi.name = "psi";
  psi.kind = OutputKind::kLinkAngle;
  psi.link = 1;
  m.outputs = {k, psi};
  return m;
}
}  // namespace

TEST_CASE("load formulas name the input, its speed, t and the outputs", "[loads]") {
  const std::vector<std::string> names = LoadVariables(TwoLinks());
  CHECK(names == std::vector<std::string>{"phi", "phi_dot", "t", "K_x", "K_y", "psi"});
}

TEST_CASE("CheckLoads names each problem", "[loads]") {
  const Mechanism m = TwoLinks();
  Loads loads;
  CHECK(CheckLoads(m, loads).empty());
  CHECK_FALSE(loads.HasMass());
  loads.masses = {{1, 2.0, {0.5, 0}, 0.1}};
  CHECK(loads.HasMass());
  CHECK(CheckLoads(m, loads).empty());
  loads.masses.push_back({1, 1.0, {0, 0}, 0.0});
  loads.masses.push_back({0, 1.0, {0, 0}, 0.0});
  loads.masses.push_back({1, -1.0, {0, 0}, 0.0});
  loads.metres_per_unit = 0.0;
  loads.springs = {{"k", {1, 1}, {0, 0}, -5.0, 1.0, 0.0}};
  loads.forces = {{"F", {1, 7}, {1, 0}, 0, "1"}};
  const std::vector<std::string> problems = CheckLoads(m, loads);
  auto has = [&](const std::string& text) {
    for (const std::string& p : problems) {
      if (p.find(text) != std::string::npos) return true;
    }
    return false;
  };
  CHECK(has("two masses"));
  CHECK(has("is the frame"));
  CHECK(has("not negative"));
  CHECK(has("length unit"));
  CHECK(has("spring 'k'"));
  CHECK(has("force 'F' names no point"));
}

}  // namespace koppel::loads_test
