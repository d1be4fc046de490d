// Named tolerances of the solver tests, each with its reason.
#pragma once

namespace koppel::test {

// Closed forms vs the solver: both are exact up to roundoff of O(10) operations on O(1)
// numbers; the issue asks 1e-9 relative to the crank length.
inline constexpr double kClosedForm = 1e-9;
// Jacobian vs central differences with h = 1e-6 max(1, |q|): truncation O(h^2 |F'''|) ~ 1e-11,
// roundoff O(eps |F| / h) ~ 1e-10 for |F| ~ 1.
inline constexpr double kJacobianFd = 1e-7;

// The block path against the dense reference path (NewtonOptions::dense): the same equations
// solved to 1e-13 L, so poses and transfer functions differ by the roundoff of two elimination
// orders; the issue asks them identical to 1e-12 (relative to 1 + the value's size).
inline constexpr double kSamePath = 1e-12;

}  // namespace koppel::test
