// The coupler point of path synthesis's closed-form pre-polish minus its target (the triangle
// A B B0), for doubles here and for Ceres' Jets in the module that fits it (ceres_solves.cpp):
// cos, sqrt, atan2 and acos are found for Jets by argument-dependent lookup.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace koppel {

// unknowns v: A0x, A0y, B0x, B0y, crank, coupler, rocker, K along A -> B, K left of it; phi the
// crank angle. False where the loop does not close.
struct PointResidual {
  Eigen::Vector2d target;
  int branch;
  template <class T> bool operator()(const T* const v, const T* const phi, T* residual) const {
    using std::acos, std::atan2, std::cos, std::sin, std::sqrt;
    const T ax = v[0] + v[4] * cos(phi[0]), ay = v[1] + v[4] * sin(phi[0]);
    const T dx = v[2] - ax, dy = v[3] - ay;
    const T r = sqrt(dx * dx + dy * dy);
    const T cos_gamma = (v[5] * v[5] + r * r - v[6] * v[6]) / (T(2) * v[5] * r);
    if (!(cos_gamma > T(-1) && cos_gamma < T(1))) return false;  // the loop does not close here
    const T gamma = atan2(dy, dx) + T(branch) * acos(cos_gamma);
    const T ux = cos(gamma), uy = sin(gamma);
    residual[0] = ax + v[7] * ux - v[8] * uy - T(target.x());
    residual[1] = ay + v[7] * uy + v[8] * ux - T(target.y());
    return true;
  }
};

}  // namespace koppel
