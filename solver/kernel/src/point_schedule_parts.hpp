// What the files of the compiled walk step (point_schedule.cpp, point_schedule_slides.cpp,
// point_schedule_outputs.cpp) share: plane geometry, the thresholds, the mechanism's graph.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <limits>
#include <vector>

namespace koppel::point_schedule_parts {

// The left normal: the vector turned by +90 degrees.
inline Eigen::Vector2d Perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
inline double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
// v turned by the angle whose cos and sin are c, s
inline Eigen::Vector2d Turned(double c, double s, const Eigen::Vector2d& v) { return {c * v.x() - s * v.y(), s * v.x() + c * v.y()}; }

// Two adjacent doubles written by one 16-byte store. The next stage reads a link's cos and sin,
// and its theta' and theta'', as pairs (the compiler vectorises the turning of a point): two
// 8-byte stores make such a load wait until they retire (a store-forwarding stall, 5 % of a
// four-bar step by perf), one 16-byte store is forwarded.
inline void StorePair(double* to, double first, double second) {
#if defined(__SSE2__)
  _mm_storeu_pd(to, _mm_set_pd(second, first));
#else
  to[0] = first;
  to[1] = second;
#endif
}

// A stage's 2 x 2 Jacobian below this normalised determinant (the sine of the angle between its
// rows) counts as singular: the general kernel takes over there.
inline constexpr double kSingularGauge = 1e-12;
// Newton's landing (NewtonDyad): an update whose squared length is within this times a link's
// length squared leaves residuals of at most this over 2 times the length squared (a circle's row
// after an update is exactly -|update|^2 / 2, a line's 0), 2 ulp: roundoff, as small as
// evaluating the residuals could show. Its point is returned without another evaluation, and the
// derivatives there carry roundoff only.
inline constexpr double kLanding = 4.0 * std::numeric_limits<double>::epsilon();

// Joint k's local point on `link`, and the link across it.
inline Eigen::Vector2d LocalAt(const Mechanism& m, int k, int link) {
  const Joint& j = m.joints[k];
  return j.link_a == link ? m.links[link].points[j.point_a].local : m.links[link].points[j.point_b].local;
}
inline int OtherLink(const Mechanism& m, int k, int link) { return m.joints[k].link_a == link ? m.joints[k].link_b : m.joints[k].link_a; }

// An unused joint of `type` between `link` and a posed link, other than `except` and the drive;
// -1 when there is none.
inline int FreeJointToPosed(const Mechanism& m, int link, int except, JointType type, const std::vector<bool>& posed,
                            const std::vector<bool>& used) {
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (k == except || k == m.drive.joint || used[k] || j.type != type || (j.link_a != link && j.link_b != link)) continue;
    if (posed[OtherLink(m, k, link)]) return k;
  }
  return -1;
}

}  // namespace koppel::point_schedule_parts
