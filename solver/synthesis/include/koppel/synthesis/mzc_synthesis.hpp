// Meyer zur Capellen straight-line linkages (seed 003, "Konstruktion von Meyer zur Capellen-
// Lenkern"): symmetric double rockers whose coupler point K, at the inflection pole (Wendepol) of
// the crossed symmetric position, has a coupler curve with a six-point tangent.
//
// Given the inflection-circle diameter D, lambda (distance of the coupler line from the pole
// tangent: lambda D, 0.5 <= lambda <= 1.5) and phi0 (angle of the pole rays against the pole
// tangent), Euler–Savary gives
//   l1' = l3' = lambda^2 D / (sin phi0 (lambda - sin^2 phi0)),  l2' = 2 lambda D cot phi0,
//   l4' = 2 lambda D cos phi0 sin phi0 / (lambda - sin^2 phi0),  k' = l' = D / sqrt(1 + 2 lambda);
// six-point contact needs sin^2 phi0 = (1 + 2 lambda)/4, and then
//   tan kappa = (1 - lambda)/lambda sqrt((1 + 2 lambda)/(3 - 2 lambda)), or lambda from kappa by
//   lambda^2 (3 - 2 lambda) = 1/(1 + tan^2 kappa).
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/design_status.hpp"

#include <string>

namespace koppel {

struct MzcDesign {
  DesignStatus status = DesignStatus::kNotRun;  // kOk, kInvalidRequest (lambda, D), kNoDesign
  std::string message;
  double lambda = 0, D = 0, phi0 = 0, kappa = 0;   // phi0, kappa in radians
  double l1 = 0, l2 = 0, l3 = 0, l4 = 0, k = 0;   // k = A'K = B'K
  double pole_height = 0;                           // of the pole P above the frame line
  bool ok() const { return status == DesignStatus::kOk; }
  std::string Brief() const;
};

MzcDesign MzcFromLambda(double lambda, double D);
// lambda from kappa (the root of lambda^2 (3 - 2 lambda) = cos^2 kappa in [0.5, 1]).
Expected<double> LambdaFromKappa(double kappa);

// The double rocker in koppel's conventions: A0' = (-l4/2, 0), B0' = (l4/2, 0), driven at A0'
// with the input = angle of A0'A' against +x (phi0 in the crossed symmetric position, where it
// is assembled); output K.
Mechanism MzcMechanism(const MzcDesign& design);

// The contact order of K's curve with its tangent at the input `at`: the first k >= 2 whose
// Taylor coefficient of K across the tangent is not below `tolerance` relative to the first;
// k = 6 and beyond means (at least) six-point contact.
int TangentContactOrder(const Mechanism& mechanism, const PointRef& point, double at, double tolerance);

}  // namespace koppel
