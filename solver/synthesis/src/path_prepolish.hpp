// A fast first polish of an atlas candidate in closed form (private to path_synthesis.cpp): the
// four-bar's coupler point as an explicit function of its pivots, lengths, coupler point, branch
// and each target's crank angle, fitted to the points by Ceres with automatic derivatives. It
// brings many candidates near their minimum in milliseconds; the fit through the real mechanism
// (fit.hpp) then finishes the few best, and its result is the one reported.
#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace koppel {

// unknowns: A0x, A0y, B0x, B0y, crank, coupler, rocker, K along A -> B, K left of it; inputs:
// one crank angle per point (updated). Returns the RMS distance at the end (infinity when the
// start does not close the loop at every point). `bounds` (when given): [lower, upper] per unknown,
// infinite where free; the start must lie inside them.
double PrePolish(const std::vector<Eigen::Vector2d>& points, int branch, std::vector<double>* unknowns, std::vector<double>* inputs,
                 const std::vector<std::pair<double, double>>* bounds = nullptr);

// The points' size: their largest distance from their centroid (path synthesis's tolerances are
// relative to it).
double PointsScale(const std::vector<Eigen::Vector2d>& points);

// The coupler point of `unknowns` at crank angle phi on `branch`; false where the loop does not close.
bool CouplerPointAt(const std::vector<double>& unknowns, int branch, double phi, Eigen::Vector2d* point);

}  // namespace koppel
