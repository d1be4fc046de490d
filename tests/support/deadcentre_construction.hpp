// Independent references for the dead-centre synthesis tests (seed 002, "Totlagensynthese der
// Kurbelschwinge"): the document's ruler-and-compass construction, and a closed-form four-bar
// driven through a full turn. Angles in radians, crank counter-clockwise, A0 = 0, B0 = (d, 0).
#pragma once

#include <Eigen/Core>

#include <optional>

namespace koppel::test {

// The document's construction ("Vorgehen"), with the crank turning counter-clockwise:
// the pole P where the lines through A0 at phi0/2 and through B0 at s psi0/2 meet (s = +1: the
// angles laid off in the same sense, "gleichsinnig"; s = -1 the other pairing); k_a the circle on
// A0P as diameter (M_a its middle), k_b the circle through A0 and P with its centre M_b on B0P;
// L the second intersection of the circle about P through A0 with k_b; E for phi0 < 180 deg on
// k_b and the line L B0, for phi0 = 180 deg at B0, for phi0 > 180 deg on k_b and the frame line.
struct DocumentConstruction {
  Eigen::Vector2d pole, m_a, m_b, l, e;
  double r_b = 0;
};
DocumentConstruction Construct(double phi0, double psi0, int s, double d = 1.0);
// E on k_b and the line L B0 (the document's rule for phi0 < 180 deg).
Eigen::Vector2d PointEOnLineLB0(const DocumentConstruction& c, double d = 1.0);

// B_a chosen on k_b along the ray from A0 at angle phi_a; A_a on that ray and on k_a (the foot of
// the perpendicular from P). Lengths l1 = |A0A_a|, l2 = |A_aB_a|, l3 = |B0B_a|.
struct ConstructedDesign {
  double l1 = 0, l2 = 0, l3 = 0;
  Eigen::Vector2d b_a = Eigen::Vector2d::Zero();
};
ConstructedDesign DesignOnRay(const DocumentConstruction& c, double phi_a, double d = 1.0);

// A four-bar driven by closed-form circle intersection from the extended dead centre at crank
// angle phi_a, on the branch of B_a, through a full counter-clockwise turn in `samples` steps.
// nullopt when it does not assemble at some sample (no full turn). Else: the rocker angle's
// largest and smallest value (golden section about the extreme samples, to 1e-13) and the crank angles
// there, and the smallest transmission angle (folded to 0..90 deg) over the samples and the two
// positions with the crank along the frame line.
struct FourBarTurn {
  double psi_max = 0, psi_min = 0, phi_at_max = 0, phi_at_min = 0;
  double mu_min = 0;
};
std::optional<FourBarTurn> TurnFourBar(double l1, double l2, double l3, double d, double phi_a, const Eigen::Vector2d& b_a, int samples);

}  // namespace koppel::test
