// Closed-form references for the tests, each citing its source. Angles in radians.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace koppel::test {

// Seed 000 (Ebene Schubkurbel mit einstellbarer Versetzung), "Übertragungsfunktionen":
// lambda = l1/l2, eps = e/l2, sin psi = -lambda cos phi - eps, cos psi = +sqrt(1 - (...)^2),
// s/l1 = sin phi + cos psi/lambda, s'/l1 = cos(phi + psi)/cos psi,
// s''/l1 = -[sin(phi + psi)/cos psi + lambda sin^2 phi / cos^3 psi], mu = pi/2 - |psi|.
// Convention (catalog/entries/slider-crank-offset.yaml): A0 = (0, -e), A = A0 + l1 (sin phi, -cos phi).
struct SliderCrankValues {
  double s, s1, s2, mu;
};
SliderCrankValues SliderCrank(double l1, double l2, double e, double phi);
// Dead centres (seed 000, "Totlagen-Größen", phi_i with the corrected 3/2 pi):
double SliderCrankPhiA(double l1, double l2, double e);  // pi/2 + asin(eps/(1 + lambda))
double SliderCrankPhiI(double l1, double l2, double e);  // 3 pi/2 + asin(eps/(1 - lambda))

// Seed 001 (Proportionalgetriebe), "Übertragungsfunktionen": lambda = l1/l6, c = l1 h/l6,
// s = c sin phi/(1 - lambda cos phi), s' = c (cos phi - lambda)/(1 - lambda cos phi)^2,
// s'' = -c sin phi (1 - 2 lambda^2 + lambda cos phi)/(1 - lambda cos phi)^3.
struct ProportionalValues {
  double s, s1, s2;
};
ProportionalValues Proportional(double l6, double l1, double h, double phi);
// s itself, for high-order finite differences of the closed form.
double ProportionalS(double l6, double l1, double h, double phi);

// An independent four-bar model (seed 003 dimensions): A0 = 0, B0 = (l4, 0),
// A = l1 (cos phi, sin phi); B the intersection of circle(A, l2) and circle(B0, l3) to the left
// (side = +1) or right (side = -1) of A -> B0; K = A + k R(kappa) (B - A)/|B - A|.
Eigen::Vector2d FourBarCouplerPoint(double l1, double l2, double l3, double l4, double k, double kappa, double phi, int side);

// Four-bar by circle intersection (any textbook, e.g. Luck/Modler, Getriebetechnik, ch. 3):
// A0 = 0, B0 = (d, 0), A = a (cos phi, sin phi), |AB| = b, |B0B| = c, B to the left (side +1) or
// right (side -1) of A -> B0; psi = angle of B0 -> B. psi' from the loop's velocity equation
// a phi' sin(phi - theta) = c psi' sin(psi - theta), theta the coupler angle A -> B.
// Empty where the dyad cannot close.
struct RockerValues {
  double psi, psi1;
  Eigen::Vector2d b;
};
std::optional<RockerValues> FourBarRocker(double a, double b, double c, double d, double phi, int side);
// Crank angles in [0, 2 pi) of the four-bar's limit points (|A B0| = b + c or |b - c|, law of cosines).
std::vector<double> FourBarLimits(double a, double b, double c, double d);

// Seed 000's slider-crank on either assembly branch: A = (l1 sin phi, -e - l1 cos phi),
// B = (s, 0) with s = A_x + side sqrt(l2^2 - A_y^2); s' by differentiating that. Empty where
// the coupler cannot reach the slide line.
struct SlideValues {
  double s, s1;
};
std::optional<SlideValues> SliderCrankBranch(double l1, double l2, double e, double phi, int side);
// Crank angles in [0, 2 pi) of its limit points (|A_y| = l2).
std::vector<double> SliderCrankLimits(double l1, double l2, double e);
// Seed 000's transmission angle mu = 90 deg - |psi|, sin psi = -lambda cos phi - eps, folds at
// 90 deg where lambda cos phi + eps = 0: cos phi = -e/l1 (both crank angles in [0, 2 pi); none
// for |e| >= l1). Its stationary points are phi = 0 and 180 deg (d/dphi of lambda cos phi + eps).
std::vector<double> SliderCrankMuFolds(double l1, double e);

// Crank-rocker (Grashof, crank a shortest) A0 = 0, B0 = (d, 0), crank a, coupler b, rocker c, B
// above the frame line (Kerle, Corves, Hüsing: Getriebetechnik, 5th ed., ch. 3 "Übertragungswinkel",
// "Totlagen"; the law of cosines in the triangles A B0 B and A0 B0 B). The diagonal
// e^2 = a^2 + d^2 - 2 a d cos phi, the coupler-rocker angle cos gamma = (b^2 + c^2 - e^2)/(2 b c),
// mu = min(gamma, 180 deg - gamma); e is extreme at phi = 0 and 180 deg, so mu is stationary there.
double CrankRockerMu(double a, double b, double c, double d, double phi);
// Where gamma passes 90 deg (e^2 = b^2 + c^2) mu folds at 90 deg: cos phi = (a^2 + d^2 - b^2 - c^2)/(2 a d),
// both crank angles in [0, 2 pi); none when gamma stays on one side of 90 deg.
std::vector<double> CrankRockerMuFolds(double a, double b, double c, double d);
// The rocker's dead centres: A0B = a + b (extended) at phi_a = acos(((a+b)^2 + d^2 - c^2)/(2 (a+b) d)),
// A0B = b - a (folded) at phi_i = 180 deg + acos(((b-a)^2 + d^2 - c^2)/(2 (b-a) d)); the rocker angle
// there psi = 180 deg - acos((c^2 + d^2 - A0B^2)/(2 c d)) (the angle at B0 of triangle A0 B0 B).
struct CrankRockerDeadCentre {
  double phi, psi;
};
CrankRockerDeadCentre CrankRockerExtended(double a, double b, double c, double d);
CrankRockerDeadCentre CrankRockerFolded(double a, double b, double c, double d);

}  // namespace koppel::test
