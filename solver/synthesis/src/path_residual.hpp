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

namespace koppel {

// The design space's constraints that are not bounds on the timed search's unknowns (the pivot
// B0's box, the ratio of the links, the crank turning fully): a start or a step outside them
// cannot be evaluated, so the least-squares solver rejects that step and shortens the next.
struct TimedLimits {
  bool crank = false;                                  // Grashof, the crank or the frame shortest
  double ratio = 0;                                    // longest / shortest at most this (0: any)
  double b0_x[2] = {-1e300, 1e300}, b0_y[2] = {-1e300, 1e300};  // B0's box
  // with `crank`: cos of the least transmission angle over the turn (above 1: any). A crank's
  // transmission angle is extreme with the crank along the frame line (A0 A over A0 B0 and
  // opposite it), where A B0 is |frame -+ crank|: both must keep |cos mu| <= cos_mu.
  double cos_mu = 2;
  template <class T> bool Admit(const T* u, const T& b0x, const T& b0y) const {
    if (b0x < T(b0_x[0]) || b0x > T(b0_x[1]) || b0y < T(b0_y[0]) || b0y > T(b0_y[1])) return false;
    if (!crank && ratio <= 0) return true;
    const T links[4] = {u[2], u[4], u[5], u[6]};  // frame, crank, coupler, rocker
    int shortest = 0, longest = 0;
    for (int i = 1; i < 4; ++i) {
      if (links[i] < links[shortest]) shortest = i;
      if (links[i] > links[longest]) longest = i;
    }
    if (ratio > 0 && links[longest] > T(ratio) * links[shortest]) return false;
    const T sum = links[0] + links[1] + links[2] + links[3];
    const bool grashof = T(2) * (links[shortest] + links[longest]) <= sum;
    if (!crank) return true;
    if (!grashof || !(shortest == 0 || shortest == 1)) return false;
    if (cos_mu > 1) return true;
    for (const T& f : {u[2] - u[4], u[2] + u[4]}) {
      const T cos_gamma = (u[5] * u[5] + u[6] * u[6] - f * f) / (T(2) * u[5] * u[6]);
      if (cos_gamma > T(cos_mu) || cos_gamma < T(-cos_mu)) return false;
    }
    return true;
  }
};

// Path synthesis with prescribed timing: the coupler point at crank angle phi_1 + offset (the
// crank's angle from the frame line A0 -> B0) minus its target. Unknowns u: A0x, A0y, the frame
// |A0B0|, the frame line's angle against +x, crank, coupler, rocker, K along A -> B, K left of it,
// phi_1. False where the loop does not close or the limits are broken.
struct TimedPointResidual {
  Eigen::Vector2d target;
  double offset;
  int branch;
  const TimedLimits* limits;
  template <class T> bool operator()(const T* const u, T* residual) const {
    using std::cos, std::sin;
    const T b0x = u[0] + u[2] * cos(u[3]), b0y = u[1] + u[2] * sin(u[3]);
    if (!limits->Admit(u, b0x, b0y)) return false;
    const T v[9] = {u[0], u[1], b0x, b0y, u[4], u[5], u[6], u[7], u[8]};
    const T phi = u[3] + u[9] + T(offset);
    return PointResidual{target, branch}(v, &phi, residual);
  }
};

}  // namespace koppel

namespace koppel {

// Path synthesis with the timing free, the global search's form: TimedPointResidual's unknowns u
// (u[9], phi_1, unused) and the point's own crank angle from the frame line, t.
struct FreePointResidual {
  Eigen::Vector2d target;
  int branch;
  const TimedLimits* limits;
  template <class T> bool operator()(const T* const u, const T* const t, T* residual) const {
    T w[10];
    for (int j = 0; j < 9; ++j) w[j] = u[j];
    w[9] = t[0];
    return TimedPointResidual{target, 0.0, branch, limits}(w, residual);
  }
};

}  // namespace koppel
