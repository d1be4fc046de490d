// AnalyseForces (tools/api/src/forces.cpp): the table's layout, the rpm of --speed against the
// energy balance at constant speed (torque(speed) - torque(rest) = J_red' omega^2 / 2, omega in
// rad/s), the two drives (reactions and virtual work) against each other, and what is refused.
#include "koppel/api/forces.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace forces_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// the two drives agree to kVirtualWorkAgreement of the loads' size; the torques here are of the
// loads' size, so this many of the largest torque, with margin for the difference of two
constexpr double kAgreement = 1e-6;

double Cell(const ForcesTable& t, size_t row, const std::string& column) {
  const auto c = std::find(t.columns.begin(), t.columns.end(), column);
  REQUIRE(c != t.columns.end());
  const std::optional<double> v = t.rows[row][c - t.columns.begin()];
  REQUIRE(v.has_value());
  return *v;
}

}  // namespace

TEST_CASE("AnalyseForces: the columns of koppel forces, a P joint's normal force and moment", "[api]") {
  const Model m = Model::Load(test::TestDataPath("slider-crank-loads.yaml"));
  ForcesRequest request;
  request.step = 30;
  const ForcesTable t = AnalyseForces(m, request);
  REQUIRE(t.complete());
  CHECK_FALSE(t.kinetostatic);
  CHECK(t.notes.empty());
  CHECK(t.columns == std::vector<std::string>{"phi", "torque", "torque_vw", "J_red", "J_red_d1", "A0_x", "A0_y", "A_x", "A_y", "B_x",
                                              "B_y", "S_x", "S_y", "S_N", "S_M", "singular"});
  CHECK(t.units == std::vector<std::string>{"deg", "N m", "N m", "kg m^2", "kg m^2/rad", "N", "N", "N", "N", "N", "N", "N", "N", "N",
                                            "N m", "1"});
  REQUIRE(t.rows.size() == 13);  // the file's 0 .. 360 by the request's 30
  for (size_t i = 0; i < t.rows.size(); ++i) CHECK_THAT(Cell(t, i, "phi"), WithinAbs(30.0 * i, 1e-9));
}

TEST_CASE("AnalyseForces: --speed in rpm adds J_red' omega^2 / 2 to the torque at rest", "[api]") {
  const Model m = Model::Load(test::TestDataPath("slider-crank-loads.yaml"));
  ForcesRequest request;
  request.step = 10;
  const ForcesTable rest = AnalyseForces(m, request);
  request.speed = 1500;  // rpm
  const ForcesTable running = AnalyseForces(m, request);
  REQUIRE(rest.complete());
  REQUIRE(running.complete());
  CHECK(running.kinetostatic);
  REQUIRE(running.rows.size() == rest.rows.size());
  const double omega = 1500 * 2 * M_PI / 60;  // rad/s
  double largest = 0;
  for (size_t i = 0; i < running.rows.size(); ++i) largest = std::max(largest, std::abs(Cell(running, i, "torque")));
  for (size_t i = 0; i < running.rows.size(); ++i) {
    INFO("phi = " << Cell(rest, i, "phi"));
    const double inertia = 0.5 * Cell(running, i, "J_red_d1") * omega * omega;
    CHECK_THAT(Cell(running, i, "torque") - Cell(rest, i, "torque"), WithinAbs(inertia, kAgreement * largest));
    CHECK_THAT(Cell(running, i, "torque_vw"), WithinAbs(Cell(running, i, "torque"), kAgreement * largest));
  }
}

TEST_CASE("AnalyseForces: a file without masses and loads is told; a step of 0 is refused", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  ForcesRequest request;
  request.step = 90;
  const ForcesTable t = AnalyseForces(m, request);
  REQUIRE(t.notes.size() == 1);
  CHECK(t.notes[0].find("no masses and no loads") != std::string::npos);
  CHECK_THAT(Cell(t, 0, "torque"), WithinAbs(0, 0));
  request.step = 0;
  std::string why;
  CHECK_FALSE(request.IsValid(m, &why));
  CHECK_FALSE(why.empty());
  CHECK_THROWS_AS(AnalyseForces(m, request), InputError);
  request.step = 1;
  request.speed = std::nan("");
  CHECK_FALSE(request.IsValid(m, &why));
}

TEST_CASE("Model::loads: the file's length unit and masses", "[api]") {
  const Model m = Model::Load(test::TestDataPath("slider-crank-loads.yaml"));
  CHECK(m.loads().length_unit_given);
  CHECK(m.loads().metres_per_unit == 0.001);
  CHECK(m.loads().HasMass());
}

}  // namespace forces_test
