// The re-analysis that proves every dead-centre design (solver/synthesis/src/design_proof.*):
// it measures what the solver finds, so a design whose dimensions are off by a little is caught.
#include "../../../solver/synthesis/src/design_proof.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/synthesis/deadcentre_synthesis.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::design_proof_test {

TEST_CASE("re-analysis measures phi0, psi0 and mu_min; a design 1e-6 off is seen", "[synthesis]") {
  CrankRockerRequest r;
  r.phi0 = DegToRad(164);
  r.psi0 = DegToRad(60);
  const CrankRockerDesign d = BestCrankRocker(r);
  REQUIRE(d.ok());
  const double quiet = d.phi_a + (2 * kPi - r.phi0) / 2;
  const CrankReanalysis exact = ReanalyseCrank(CrankRockerMechanism(d), 0, 1, quiet);
  REQUIRE(exact.ok());
  CHECK(std::abs(exact.phi0 - r.phi0) < kReanalysisTolerance);
  CHECK(std::abs(exact.turn - r.psi0) < kReanalysisTolerance);  // the same sense: > 0
  CHECK(std::abs(exact.mu_min - d.mu_min) < kReanalysisTolerance);
  // the rocker 1e-6 longer: phi0 and psi0 move by far more than the tolerance
  CrankRockerDesign off = d;
  off.l3 += 1e-6;
  const CrankReanalysis wrong = ReanalyseCrank(CrankRockerMechanism(off), 0, 1, quiet);
  REQUIRE(wrong.ok());
  CHECK(std::abs(wrong.turn - r.psi0) > 100 * kReanalysisTolerance);
  // a linkage whose crank cannot turn fully is no crank mechanism at all
  CrankRockerDesign locked = d;
  locked.l3 = 0.2;
  const CrankReanalysis none = ReanalyseCrank(CrankRockerMechanism(locked), 0, 1, quiet);
  CHECK_FALSE(none.ok());
  CHECK_THAT(none.message, Catch::Contains("full turn") || Catch::Contains("assemble"));
}

}  // namespace koppel::design_proof_test
