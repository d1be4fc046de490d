// The check of a catalog entry's figures against its document (catalog/src/figures.cpp): a
// figure outside its tolerance fails and says both numbers; a figure naming no output is bad
// input at its line. The quantities themselves are tested in figure_quantities_test.cpp.
#include "koppel/catalog/check.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/angles.hpp"
#include "support/temp_file.hpp"

#include "figure_cards.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::figures_test {
TEST_CASE("a figure outside its tolerance fails and says both values", "[catalog][figures]") {
  const std::string figures = "    - {name: swing, quantity: stroke, output: psi, expected: 10, unit: deg, tolerance: 0.1}\n";
  test::TempDir dir;
  const EntryReport r = CheckEntry(dir.Write("f.yaml", test::FourBar(1, 3, 2.5, 3, 0, figures)));
  const CheckOutcome& swing = test::FindOutcome(r, "swing");
  CHECK(swing.status == CheckStatus::kFailed);
  CHECK_THAT(swing.detail, Catch::Contains("document 10, koppel "));
  CHECK(swing.Ratio() > 1);
  CHECK_FALSE(r.passed());
}

TEST_CASE("a figure naming no output is bad input at its line", "[catalog][figures]") {
  // `phi` is no output of the four-bar (psi and A are); the figure is the first of the card's
  // list, line 25 of the file FourBar writes (reference: a hand count of its template)
  const std::string figures = "    - {name: swing, quantity: stroke, output: phi, expected: 10, unit: deg, tolerance: 0.1}\n";
  test::TempDir dir;
  const std::string path = dir.Write("f.yaml", test::FourBar(1, 3, 2.5, 3, 0, figures));
  try {
    CheckEntry(path);
    FAIL("no InputError");
  } catch (const InputError& e) {
    // (a second report follows, "this figure is not an angle: it has no unit": a consequence of the
    // unknown output, noted in the report, not asserted here)
    REQUIRE_FALSE(e.diagnostics().empty());
    const Diagnostic& d = e.diagnostics()[0];
    CHECK(d.file == path);
    CHECK(d.line == 25);
    CHECK(d.path == "catalog.figures[0].output");
    CHECK_THAT(d.message, Catch::Contains("names output 'phi', which the file does not declare"));
  }
}

}  // namespace koppel::figures_test
