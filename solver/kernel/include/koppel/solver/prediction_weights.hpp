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

namespace koppel {

struct PredictionWeights {
  static constexpr double kQuinticReach = 4.0;
  double j1 = 0.0, j2 = 0.0, m0 = 0.0, m1 = 0.0, m2 = 0.0;
  bool quintic = false;
  // (inline: every step of a walk computes them, before its first dyad)
  void For(double h, double h_before) {
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
};

}  // namespace koppel
