// Dead-centre synthesis (Totlagensynthese, seed 002) as computation, every design proved by
// re-analysis with the generic solver before it is returned.
//
// Crank-rocker. Frame A0 = (0, 0), B0 = (d, 0); crank A0A = l1, coupler AB = l2, rocker B0B = l3.
// In the dead centres A0, A, B are collinear: extended (äußere, Strecklage) |A0B_a| = l2 + l1,
// folded (innere, Decklage) |A0B_i| = l2 - l1. phi0 is the angle the crank turns from the folded
// to the extended dead centre in its running sense, psi0 the rocker's swing meanwhile. The
// document measures both in the same sense (RockerSense::kSame: crank and rocker turn the same
// way from the folded to the extended dead centre); kOpposite is the other pairing. The crank
// turns counter-clockwise here; MirrorMechanism gives the document's clockwise ("mathematisch
// negativ") drawing with the same phi0, psi0 and senses.
// Seen from A0, B_a lies at the signed angle beta_signed = phi_a (the crank angle of the
// extended dead centre); the document's beta = angle B0 A0 B_a is |phi_a|. With the crank
// counter-clockwise, B_a lies below A0B0 in the same sense and above it in the opposite sense.
// The designs for given phi0, psi0 form one family: B_a on the document's circle k_b, within its
// arc LE. Written as algebra with lambda = l1/l2 in (0, 1) as the family parameter:
//   rho_a e^{i phi_a} + rho_i e^{i (phi_a + delta)} = d (1 - e^{i s psi0}),
//   delta = s psi0 - phi0, s = +1 (same) or -1 (opposite),
// so |rho_a + rho_i e^{i delta}| = 2 d sin(psi0/2), i.e. l2^2 cos^2(delta/2) + l1^2 sin^2(delta/2)
// = d^2 sin^2(psi0/2): l2 = d sin(psi0/2) / sqrt(lambda^2 sin^2(delta/2) + cos^2(delta/2)).
// This stays regular where the document's construction degenerates (phi0 = 180 deg + s psi0:
// k_b becomes a line, every design has the same beta and l1 = d sin(psi0/2)).
// A design is admissible when it is a crank-rocker (Grashof, crank shortest, strictly: a
// change-point linkage has mu = 0) and B_a, B_i lie strictly on one side of A0B0 (the same
// assembly branch; otherwise the linkage has other dead centres).
//
// Slider-crank. Seed 000's conventions: A0 = (0, -e), slide line y = 0, crank angle from -y,
// counter-clockwise. phi0 from the folded to the extended dead centre, stroke s0 = B_a - B_i.
// The rays A0B_a and A0B_i enclose theta = |phi0 - 180 deg| < 90 deg; phi0 < 180 deg puts A0
// below the slide line (e > 0), phi0 > 180 deg above it (e < 0). The offset |e| lies in
// (0, s0 cot theta) and beta (between the slide line and A0B_a) in (0, 90 deg - theta); at both
// ends of either range the coupler folds onto the crank or B_i reaches the foot point (mu_min -> 0).
// phi0 = 180 deg is the centric slider-crank: l1 = s0/2 and any coupler, no best design.
//
// Every design is re-analysed (design_proof.hpp): the generic solver drives a full turn, its dead
// centres must give phi0 and psi0 (or s0) to kReanalysisTolerance in the stated senses, and
// mu_min is the smallest transmission angle the solver finds, which must agree with the closed
// form (law of cosines) to the same tolerance. Angles in radians, lengths in the frame's unit.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/design_space.hpp"
#include "koppel/synthesis/design_status.hpp"

#include <string>

namespace koppel {

// The re-analysis must reproduce phi0, psi0 (rad) and s0 (length / s0) to this.
inline constexpr double kReanalysisTolerance = 1e-9;

enum class RockerSense { kSame, kOpposite };
const char* ToString(RockerSense sense);  // "same", "opposite"


struct CrankRockerRequest {
  double phi0 = 0;  // crank angle from the folded to the extended dead centre, in (0, 2 pi)
  double psi0 = 0;  // rocker swing between them, in (0, pi)
  RockerSense rocker_sense = RockerSense::kSame;  // the document's definition
  double frame_length = 1;  // d = A0B0 > 0
  bool IsValid(std::string* why) const;
};

struct CrankRockerDesign {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;
  bool ok() const { return status == DesignStatus::kOk; }
  std::string Brief() const;  // one line: status, beta, lengths, mu_min

  CrankRockerRequest request;
  double beta = 0;             // the document's beta = angle B0 A0 B_a, in (0, pi)
  double phi_a = 0, phi_i = 0; // crank angles of the extended / folded dead centre (ccw from A0B0)
  double lambda = 0;           // l1 / l2, the family parameter
  double l1 = 0, l2 = 0, l3 = 0, l4 = 0;  // crank, coupler, rocker, frame
  double mu_min = 0;           // smallest transmission angle over a turn, by the solver
  double mu_min_at = 0;        // crank angle where it occurs (0 or pi against A0B0)
  // the arc LE: the document's beta at its ends (beta_l at L, where the coupler is as long as
  // the crank; beta_e at E), an interval containing beta
  double beta_l = 0, beta_e = 0;
  // what the generic solver measured: phi0 (crank, folded -> extended, counter-clockwise) and
  // the signed rocker turn over the same motion (> 0 counter-clockwise)
  double reanalysed_phi0 = 0, reanalysed_psi = 0;
};

// The design at the document's beta (unsigned). kNoDesign when beta lies outside the arc LE.
CrankRockerDesign CrankRockerFromBeta(const CrankRockerRequest& request, double beta);
// The design at lambda = l1/l2 in (0, 1) (every point of the arc, also where beta is degenerate).
CrankRockerDesign CrankRockerFromLambda(const CrankRockerRequest& request, double lambda);
// The design with the largest mu_min. kBoundaryOptimum when the supremum lies where a link
// vanishes (phi0 = 180 deg: l1, l3 -> 0), kNoDesign when the arc LE is empty.
CrankRockerDesign BestCrankRocker(const CrankRockerRequest& request);

// The design with the largest mu_min inside `space` (A0 at the origin, B0 at (d, 0), the closed
// form's lengths and mu_min on the family's grid, refined; then proved, and the proved design
// checked against the space again). kNoDesign naming the constraint the best design without the
// space broke when no member of the family lies inside. An empty space: BestCrankRocker.
CrankRockerDesign BestCrankRockerInSpace(const CrankRockerRequest& request, const DesignSpace& space);

struct SliderCrankRequest {
  double phi0 = 0;    // crank angle from the folded to the extended dead centre, in (0, 2 pi)
  double stroke = 0;  // s0 > 0
  bool IsValid(std::string* why) const;
};

struct SliderCrankDesign {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;
  bool ok() const { return status == DesignStatus::kOk; }
  std::string Brief() const;

  SliderCrankRequest request;
  double e = 0;          // offset, seed 000's sign: > 0 puts A0 below the slide line
  double l1 = 0, l2 = 0;
  double beta = 0;       // angle between the slide line and A0B_a, in (0, pi/2 - theta)
  double mu_min = 0;     // by the solver; closed form 90 deg - asin((l1 + |e|)/l2)
  double mu_min_at = 0;  // crank angle (seed 000's phi) where it occurs
  // the ranges that give a crank: |e| in (0, offset_max), beta in (0, beta_max)
  double offset_max = 0, beta_max = 0;
  double reanalysed_phi0 = 0, reanalysed_stroke = 0;
};

// With the offset |e| given (its sign follows from phi0; a negative one is an invalid request).
SliderCrankDesign SliderCrankFromOffset(const SliderCrankRequest& request, double offset);
// With beta given instead: B_a = (e cot beta, e), B_i = (e cot(beta + theta), e).
SliderCrankDesign SliderCrankFromBeta(const SliderCrankRequest& request, double beta);
// The offset with the largest mu_min. kBoundaryOptimum at phi0 = 180 deg.
SliderCrankDesign BestSliderCrank(const SliderCrankRequest& request);

// Mechanisms in koppel's conventions. Crank-rocker: A0 = 0, B0 = (l4, 0), input = crank angle
// against A0B0 (counter-clockwise), assembled in the extended dead centre; outputs psi (rocker
// angle) and mu. Slider-crank: seed 000's conventions, outputs s and mu.
Mechanism CrankRockerMechanism(const CrankRockerDesign& design);
Mechanism SliderCrankMechanism(const SliderCrankDesign& design);

}  // namespace koppel
