// A compiled step's prediction of a dyad's joint point J at the step's input h (point_schedule.hpp),
// from the solved state's J, J', J'' (derivatives with respect to the input) and, where there is
// one, the state before it, M, M', M'' (at -h_before); the same weights for every dyad and for x
// and y:
//   2nd order:  J + j1 J' + j2 J''                                       (error O(h^3))
//   quintic:    the same + m0 (M - J) + m1 (M' - J') + m2 (M'' - J''),   (error O(h^6))
// the quintic through both states' J, J' and J'' (Hermite): about 3e-13 L times J's 6th derivative
// at steps of 1 degree, so that Newton's first update lands at roundoff (NewtonDyad). The 2nd
// order where there is no state before (h_before 0: after a Load or a refused step) or the step
// is more than kQuinticReach times the one before: the quintic's weights grow like
// (h / h_before)^5 and would turn the earlier state's roundoff into a far prediction.
#pragma once

#include <cmath>
#include <limits>

namespace koppel {

// A walk steps by the same h again and again (to roundoff: its inputs are start + i h, a step's
// difference off by 1e-13 of it at 1 degree): the weights are kept while h and h_before agree
// with those they were computed for to kKeep (relative). The prediction then moves by about
// kKeep h |J'| times the weights (1 - m0 <= 1e4 at the quintic's reach, 32 at equal steps):
// at most 2e-10 L at 1 degree, within what Newton's first update removes to roundoff
// (kLanding: an update of up to 3e-8 of a link).
struct PredictionWeights {
  static constexpr double kQuinticReach = 4.0;
  static constexpr double kKeep = 1e-12;
  double j1 = 0.0, j2 = 0.0, m0 = 0.0, m1 = 0.0, m2 = 0.0;
  bool quintic = false;
  // (inline: every step of a walk asks, before its first dyad)
  void For(double h, double h_before) {
    if (std::abs(h - h_) <= kKeep * std::abs(h) && std::abs(h_before - h_before_) <= kKeep * std::abs(h_before)) return;
    h_ = h;
    h_before_ = h_before;
    m0 = m1 = m2 = 0.0;
    j1 = h;
    j2 = 0.5 * h * h;
    quintic = h_before != 0.0 && std::abs(h) <= kQuinticReach * std::abs(h_before);
    if (!quintic) return;
    // The quintic p(t) = J + J' t + J'' t^2 / 2 + u (t/H)^3 + v (t/H)^4 + w (t/H)^5 through the
    // earlier M, M' and M'' at t = -H (H = h_before) has, with e0 = M - J + H J' - H^2 J'' / 2,
    // e1 = H (M' - J') + H^2 J'', e2 = H^2 (M'' - J''):  -u + v - w = e0, 3u - 4v + 5w = e1,
    // -6u + 12v - 20w = e2, so at r = h / H
    //   p(h) - (J + J' h + J'' h^2 / 2) = -r^3 (e0 (10 + 15r + 6r^2) + e1 (4 + 7r + 3r^2) + e2 (1 + r)^2 / 2),
    // written here as weights of J', J'' and of the differences M - J, M' - J', M'' - J''.
    const double hh = h_before, r = h / hh, r3 = r * r * r;
    const double a = 10.0 + r * (15.0 + 6.0 * r), b = 4.0 + r * (7.0 + 3.0 * r), c = 0.5 * (1.0 + r) * (1.0 + r);
    m0 = -r3 * a;
    m1 = -r3 * b * hh;
    m2 = -r3 * c * hh * hh;
    j1 += m0 * hh;
    j2 -= r3 * hh * hh * (b - 0.5 * a);
  }

 private:
  // the steps the weights were computed for (none yet: NaN compares false)
  double h_ = std::numeric_limits<double>::quiet_NaN(), h_before_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace koppel
