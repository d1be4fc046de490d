// Dead-centre synthesis (Totlagensynthese, seed 002) as computation.
//
// Crank-rocker: frame A0 = (0, 0), B0 = (d, 0). In the dead centres A0, A, B are collinear:
// extended (Strecklage) A0B_a = l2 + l1, folded (Decklage) A0B_i = l2 - l1. Given the crank angle
// phi0 and the rocker angle psi0 between the two dead centres and the free angle
// beta = angle B0 A0 B_a, the rays A0B_a (at beta) and A0B_i (at beta - phi0 + 180 deg) and the
// rotation of B about B0 by psi0 give a linear system for A0B_a and A0B_i; this is the
// document's construction (pole P, circles k_a, k_b) written as algebra, and every beta on the
// arc LE gives a crank-rocker with exactly phi0 and psi0.
// Senses (checked by re-analysis in the tests): from the folded to the extended dead centre the
// crank turns counter-clockwise by phi0 and the rocker clockwise by psi0; the extended dead centre
// lies at crank angle beta. MirrorMechanism gives the opposite senses (the document's negative
// rotation). This pairing is the one whose best beta reproduces the document's max mu_min.
//
// Slider-crank: A0 = (0, 0), slide line y = e. The rays A0B_a and A0B_i enclose |phi0 - 180 deg|;
// with the stroke s0 = B_a - B_i and the offset e this fixes l1 and l2.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <string>

namespace koppel {

struct CrankRockerDesign {
  bool ok = false;
  std::string message;
  double phi0 = 0, psi0 = 0, beta = 0;      // radians
  double l1 = 0, l2 = 0, l3 = 0, l4 = 0;    // crank, coupler, rocker, frame
  double mu_min = 0;                        // smallest transmission angle over a turn [rad]
  double mu_min_at = 0;                     // crank angle where it occurs (0 or pi, against A0B0)
};

// Given beta. Not ok when beta lies outside the arc LE (no crank-rocker).
CrankRockerDesign CrankRockerFromDeadCentres(double phi0, double psi0, double beta, double frame_length = 1.0);
// beta chosen to maximise mu_min (scan at 0.1 deg, then golden section to 1e-10 rad).
CrankRockerDesign BestCrankRocker(double phi0, double psi0, double frame_length = 1.0);

struct SliderCrankDesign {
  bool ok = false;
  std::string message;
  double phi0 = 0, stroke = 0, e = 0;  // e: offset of the slide line from A0
  double l1 = 0, l2 = 0;
  double beta = 0;       // angle between the slide line and A0B_a
  double mu_min = 0;     // 90 deg - asin((l1 + |e|)/l2)
  double mu_min_at = 0;  // crank angle (from the normal to the slide, as seed 000) where it occurs
};

SliderCrankDesign SliderCrankFromDeadCentres(double phi0, double stroke, double offset);
SliderCrankDesign BestSliderCrank(double phi0, double stroke);
// With beta (angle between the slide line and A0B_a) free instead of e: B_a = (e cot beta, e),
// B_i = (e cot(beta + theta), e), so e = s0 / (cot beta - cot(beta + theta)).
SliderCrankDesign SliderCrankFromBeta(double phi0, double stroke, double beta);

// Mechanisms in koppel's conventions: the crank-rocker with A0 = 0, B0 = (l4, 0), input = crank
// angle against A0B0, assembled with B on the side the synthesis put B_a; outputs psi (rocker
// angle) and mu. The slider-crank in seed 000's conventions (A0 = (0, -e), phi from -y), outputs s
// and mu.
Mechanism CrankRockerMechanism(const CrankRockerDesign& design);
Mechanism SliderCrankMechanism(const SliderCrankDesign& design);

}  // namespace koppel
