// SweepLayout (tools/api/src/sweep_layout.cpp): the names, units and orders of a sweep table's
// columns, against a hand-written table and against the kernel's own layout of the numbers
// (OutputColumn, position.hpp), so that a column's name is the number it holds.
#include "koppel/api/sweep_layout.hpp"

#include "koppel/solver/position.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

namespace koppel::sweep_layout_test {
namespace {

// tests/support: a four-bar driven at A0 with outputs K (a coupler point), psi (the rocker's
// angle), phi (the joint angle at A0) and mu (the transmission angle).
Mechanism FourBar() { return test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1); }

TEST_CASE("the columns of a four-bar's table, as written by hand", "[sweep_layout]") {
  const SweepColumns t = SweepLayout(FourBar(), 2, "mm");
  const std::vector<std::string> names = {"phi", "K_x", "K_x_d1", "K_x_d2", "K_y", "K_y_d1", "K_y_d2", "psi", "psi_d1",
                                          "psi_d2", "phi", "phi_d1", "phi_d2", "mu", "mu_d1", "mu_d2", "singular"};
  const std::vector<std::string> units = {"deg", "mm", "mm/rad", "mm/rad^2", "mm", "mm/rad", "mm/rad^2", "deg", "rad/rad",
                                          "rad/rad^2", "deg", "rad/rad", "rad/rad^2", "deg", "rad/rad", "rad/rad^2", "1"};
  CHECK(t.names == names);
  CHECK(t.units == units);
  REQUIRE(t.order_of_column.size() == names.size());
  REQUIRE(t.angle_value.size() == names.size());
  CHECK(t.order_of_column.front() == -1);
  CHECK(t.order_of_column.back() == -1);
  for (size_t c = 1; c + 1 < names.size(); ++c) {
    INFO(names[c]);
    const bool angle = names[c].rfind("K_", 0) != 0;
    CHECK(t.order_of_column[c] == static_cast<int>((c - 1) % 3));  // three orders per component
    CHECK(t.angle_value[c] == (angle && t.order_of_column[c] == 0));
  }
  CHECK_FALSE(t.angle_value.front());  // the input is converted apart (InputShown)
}

TEST_CASE("column c holds number c - 1 of the kernel's output derivatives", "[sweep_layout]") {
  // reference: the kernel's OutputColumn, the one place that knows its own layout
  const Mechanism m = FourBar();
  for (int order : {0, 1, 3}) {
    const SweepColumns t = SweepLayout(m, order);
    PositionSolver solver(m);
    REQUIRE(static_cast<int>(t.names.size()) == solver.OutputWidth(order) + 2);
    for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
      for (int c = 0; c < m.outputs[o].Components(); ++c) {
        const int column = 1 + OutputColumn(m, o, c, order);
        std::string base = m.outputs[o].name;
        if (m.outputs[o].Components() == 2) base += c == 0 ? "_x" : "_y";
        CHECK(t.names[column] == base);
        for (int k = 1; k <= order; ++k) CHECK(t.names[column + k] == base + "_d" + std::to_string(k));
      }
    }
  }
}

TEST_CASE("lengths are labelled by the unit given, 'length' when none", "[sweep_layout]") {
  const SweepColumns t = SweepLayout(FourBar(), 1);
  CHECK(t.units[1] == "length");
  CHECK(t.units[2] == "length/rad");
}

}  // namespace
}  // namespace koppel::sweep_layout_test
