#include "koppel/solver/point_schedule.hpp"

#include "point_schedule_parts.hpp"

#include "koppel/solver/constraints.hpp"
#include "koppel/core/angles.hpp"  // kPi
#include "koppel/solver/taylor.hpp"  // SinCos

#include <algorithm>
#include <cmath>

namespace koppel {
using namespace point_schedule_parts;

PointSchedule::PointSchedule(const ConstraintSystem& system)
    : system_(system), mechanism_(system.mechanism()), length_scale_(system.length_scale()) {
  const Mechanism& m = mechanism_;
  const int n_links = static_cast<int>(m.links.size());
  n_links_ = n_links;
  frame_ = m.FrameLink();
  states_.assign(kHistory, std::vector<LinkJet>(n_links));
  state_input_.assign(kHistory, 0.0);
  now_ = states_[0].data();
  before_ = now_;
  if (m.FrameLink() < 0 || system.NumEquations() != system.NumCoordinates()) {
    why_not_ = "the mechanism is not a square system with a frame";
    return;
  }
  if (!system.problems().empty()) {  // an output it cannot evaluate (a file's reader refuses such)
    why_not_ = system.problems().front();
    return;
  }
  std::vector<bool> posed(n_links, false), used(m.joints.size(), false);
  posed[m.FrameLink()] = true;
  while (AddDriveStage(posed, used) || AddDyadStage(posed, used) || AddSlideDyadStage(posed, used)) {
  }
  for (int l = 0; l < n_links && why_not_.empty(); ++l) {
    if (!posed[l]) why_not_ = "link '" + m.links[l].name + "' is not posed by a drive or a dyad";
  }
  for (size_t k = 0; k < used.size() && why_not_.empty(); ++k) {
    if (!used[k]) why_not_ = "joint '" + m.joints[k].name + "' is not part of a drive or a dyad";
  }
  if (why_not_.empty()) CompileOutputs();
  if (!why_not_.empty()) stages_.clear();
}

bool PointSchedule::AddDriveStage(std::vector<bool>& posed, std::vector<bool>& used) {
  const Mechanism& m = mechanism_;
  const int d = m.drive.joint;
  if (d < 0 || used[d]) return false;
  const Joint& j = m.joints[d];
  Stage s;
  s.axis = j.axis;
  s.angle = j.angle;
  if (j.type == JointType::kRevolute && posed[j.link_a] != posed[j.link_b]) {
    s.kind = Kind::kDriveR;
    s.sign = posed[j.link_a] ? 1.0 : -1.0;
    s.base = posed[j.link_a] ? j.link_a : j.link_b;
    s.link = OtherLink(m, d, s.base);
  } else if (j.type == JointType::kPrismatic && posed[j.link_a] && !posed[j.link_b]) {
    s.kind = Kind::kDriveP;
    s.base = j.link_a;
    s.link = j.link_b;
  } else {
    return false;
  }
  s.cos_turn = std::cos(s.angle);
  s.sin_turn = std::sin(s.angle);
  s.base_point = LocalAt(m, d, s.base);
  s.link_point = LocalAt(m, d, s.link);
  used[d] = posed[s.link] = true;
  stages_.push_back(s);
  return true;
}

bool PointSchedule::AddDyadStage(std::vector<bool>& posed, std::vector<bool>& used) {
  const Mechanism& m = mechanism_;
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (used[k] || k == m.drive.joint || j.type != JointType::kRevolute || posed[j.link_a] || posed[j.link_b]) continue;
    for (const auto& [a, b] : {std::pair{j.link_a, j.link_b}, std::pair{j.link_b, j.link_a}}) {
      Stage s;
      const int ka = FreeJointToPosed(m, a, k, JointType::kRevolute, posed, used);
      if (ka < 0) continue;
      s.a = a;
      s.b = b;
      s.anchor_a = OtherLink(m, ka, a);
      s.a_at_anchor = LocalAt(m, ka, a);
      s.anchor_a_point = LocalAt(m, ka, s.anchor_a);
      s.a_at_j = LocalAt(m, k, a);
      s.b_at_j = LocalAt(m, k, b);
      s.length_a = (s.a_at_j - s.a_at_anchor).norm();
      const int kb = CloseDyad(s, k, posed, used);
      // The gauge is the dyad's own: its normalised determinant (the sine between its rows, in its
      // own links' lengths) says whether this dyad is near a fold or a branch point, whatever the
      // whole mechanism's size L. The Jacobian is block-triangular in the stages' order, so it is
      // singular exactly where one dyad's block is: a chain of many small loops (links 1/500 of L)
      // compiles as a single loop does.
      const double shortest = kb < 0 ? 0.0 : s.kind == Kind::kDyadRR ? std::min(s.length_a, s.length_b) : s.length_a;
      if (kb < 0 || !(shortest > 0.0)) continue;
      s.per_length_a = 1.0 / s.length_a;
      s.per_length_b = s.kind == Kind::kDyadRR ? 1.0 / s.length_b : 0.0;
      s.landing2 = kLanding * shortest * shortest;
      used[k] = used[ka] = used[kb] = true;
      posed[a] = posed[b] = true;
      stages_.push_back(s);
      return true;
    }
  }
  return false;
}

int PointSchedule::CloseDyad(Stage& s, int k, const std::vector<bool>& posed, const std::vector<bool>& used) const {
  const Mechanism& m = mechanism_;
  const int b = s.b;
  if (const int kb = FreeJointToPosed(m, b, k, JointType::kRevolute, posed, used); kb >= 0) {
    s.kind = Kind::kDyadRR;
    s.anchor_b = OtherLink(m, kb, b);
    s.b_at_anchor = LocalAt(m, kb, b);
    s.anchor_b_point = LocalAt(m, kb, s.anchor_b);
    s.length_b = (s.b_at_j - s.b_at_anchor).norm();
    return s.length_b > 0.0 ? kb : -1;
  }
  const int kb = FreeJointToPosed(m, b, k, JointType::kPrismatic, posed, used);
  if (kb < 0) return -1;
  const Joint& p = m.joints[kb];
  s.kind = Kind::kDyadRP;
  s.anchor_b = OtherLink(m, kb, b);
  s.block_is_guide_side = (p.link_a == b);
  s.axis = p.axis;
  s.angle = p.angle;
  s.cos_turn = std::cos(p.angle);
  s.sin_turn = (s.block_is_guide_side ? -1.0 : 1.0) * std::sin(p.angle);
  // the slide's point on the block (b_at_anchor) and on the guide (anchor_b_point)
  s.b_at_anchor = LocalAt(m, kb, b);
  s.anchor_b_point = LocalAt(m, kb, s.anchor_b);
  s.line_at_rest = s.anchor_b == frame_;
  if (s.line_at_rest) {  // the frame's angle is 0: the block's is the joint's, the line's either
    s.rest_x = s.anchor_b_point - Turned(s.cos_turn, s.sin_turn, s.b_at_anchor - s.b_at_j);
    s.rest_n = s.block_is_guide_side ? Perp(Turned(s.cos_turn, s.sin_turn, s.axis)) : Perp(s.axis);
  }
  return kb;
}

void PointSchedule::PoseByAngle(int link, const double theta[3], double c, double s, const Eigen::Vector2d& local,
                                const PointJet& where) {
  LinkJet& l = now_[link];
  l.theta[0] = theta[0];  // (not std::copy: three doubles, not a call to memmove)
  StorePair(&l.theta[1], theta[1], theta[2]);
  l.angle_pending = false;
  l.turns = before_[link].turns;
  StorePair(&l.c, c, s);
  l.at[0] = where.p[0];
  l.at[1] = where.p[1];
  l.at[2] = where.p[2];
  l.at_local = local;
}

double PointSchedule::AngleIn(const LinkJet* state, int l) {
  const LinkJet& jet = state[l];
  if (jet.angle_pending) {
    jet.theta[0] = std::atan2(jet.s, jet.c) + 2.0 * kPi * jet.turns;
    jet.angle_pending = false;
  }
  return jet.theta[0];
}

bool PointSchedule::PoseByTwoPoints(int link, const Eigen::Vector2d& local_from, const PointJet& from,
                                    const Eigen::Vector2d& local_to, double per_span, const PointJet& to) {
  // (in scalars: see PointOf)
  const double dx = to.p[0].x() - from.p[0].x(), dy = to.p[0].y() - from.p[0].y();
  const double d1x = to.p[1].x() - from.p[1].x(), d1y = to.p[1].y() - from.p[1].y();
  const double d2x = to.p[2].x() - from.p[2].x(), d2y = to.p[2].y() - from.p[2].y();
  const double lx = local_to.x() - local_from.x(), ly = local_to.y() - local_from.y();
  // |d| is the span (a dyad's equation, solved to roundoff: kLanding): 1 / |d|^2 and
  // 1 / (|d| span) by one Newton step for the reciprocal and for the reciprocal square root from
  // the span's, whose error is the square of d's relative misfit (1e-31): roundoff, without a
  // division or a square root after Newton.
  const double per_span2 = per_span * per_span, misfit = (dx * dx + dy * dy) * per_span2;
  const double per_r2 = per_span2 * (2.0 - misfit), per_norms = per_span2 * (1.5 - 0.5 * misfit);
  // theta = atan2(d) - atan2(dl): its cos and sin without trigonometry, d's direction turned back
  // by dl's (+ 0.0: no -0 sine, which atan2 would put on the other side of the cut)
  const double c = (dx * lx + dy * ly) * per_norms, sn = (lx * dy - ly * dx) * per_norms;
  const double t1 = (dx * d1y - dy * d1x) * per_r2;
  const double t2 = ((dx * d2y - dy * d2x) - 2.0 * (dx * d1x + dy * d1y) * t1) * per_r2;
  return PoseByCosSin(link, c, sn, t1, t2, local_from, from);
}

bool PointSchedule::PoseByCosSin(int link, double c, double sn, double t1, double t2, const Eigen::Vector2d& local, const PointJet& at) {
  sn += 0.0;  // no -0 sine, which atan2 would put on the other side of the cut
  // The turns: atan2(s, c) jumps by a turn where the link crosses the negative x axis. A step
  // that turns the link by less than 90 degrees (cos of the turn > 0) crosses it only with
  // both ends left of the y axis, so the sign change of s there counts it.
  const LinkJet& before = before_[link];
  if (!(c * before.c + sn * before.s > 0.0)) return false;
  int turns = before.turns;
  if (c < 0.0) turns += (before.s >= 0.0 && sn < 0.0) ? 1 : (before.s < 0.0 && sn >= 0.0) ? -1 : 0;
  const double theta[3] = {0.0, t1, t2};
  PoseByAngle(link, theta, c, sn, local, at);
  now_[link].turns = turns;
  now_[link].angle_pending = true;
  return true;
}

double PointSchedule::AngleBeforeTurns(int link, double input) const {
  for (const Stage& s : stages_) {
    if ((s.kind == Kind::kDriveR || s.kind == Kind::kDriveP) && s.link == link)
      return now_[s.base].theta[0] + (s.kind == Kind::kDriveR ? s.sign * (mechanism_.drive.zero + input) : s.angle);
    if (s.kind == Kind::kDyadRP && s.b == link) return now_[s.anchor_b].theta[0] + (s.block_is_guide_side ? -1.0 : 1.0) * s.angle;
  }
  return std::atan2(now_[link].s, now_[link].c);
}

[[gnu::flatten]] void PointSchedule::PoseDrive(const Stage& s, double input) {
  const LinkJet& base = now_[s.base];
  const double zero = mechanism_.drive.zero;
  if (s.kind == Kind::kDriveR) {
    const double turn = s.sign * (zero + input);
    double st, ct;
    SinCos(turn, st, ct);  // the one trigonometric call of a step: the input's
    if (s.base == frame_) {  // a crank on the frame (angle 0, at rest): the general case's terms that are 0 or 1
      const double theta[3] = {turn + 2.0 * kPi * before_[s.link].turns, s.sign, 0.0};
      PointJet where;
      where.p[0] = s.base_point;
      where.p[1].setZero();
      where.p[2].setZero();
      PoseByAngle(s.link, theta, ct, st, s.link_point, where);
      return;
    }
    const double theta[3] = {Angle(s.base) + turn + 2.0 * kPi * before_[s.link].turns, base.theta[1] + s.sign, base.theta[2]};
    PoseByAngle(s.link, theta, base.c * ct - base.s * st, base.s * ct + base.c * st, s.link_point, GlobalPoint(s.base, s.base_point));
    return;
  }
  // P: the block's point at zero + input along the guide's axis u from the guide's point
  const Eigen::Vector2d u(base.c * s.axis.x() - base.s * s.axis.y(), base.s * s.axis.x() + base.c * s.axis.y());
  const Eigen::Vector2d u1 = base.theta[1] * Perp(u), u2 = base.theta[2] * Perp(u) - base.theta[1] * base.theta[1] * u;
  const double v = zero + input;
  PointJet where = GlobalPoint(s.base, s.base_point);
  where.p[0] += v * u;
  where.p[2] += 2.0 * u1 + v * u2;
  where.p[1] += u + v * u1;
  const double theta[3] = {Angle(s.base) + s.angle + 2.0 * kPi * before_[s.link].turns, base.theta[1], base.theta[2]};
  PoseByAngle(s.link, theta, base.c * s.cos_turn - base.s * s.sin_turn, base.s * s.cos_turn + base.c * s.sin_turn, s.link_point, where);
}

// What a dyad's rows know before its Newton: the first row's posed hinge A and, for the second,
// RR: the posed hinge B; RP: the slide line's normal n and the point X that J keeps the line's
// offset from (both known: the block's angle is the guide's), with the block's angle.
struct PointSchedule::DyadRows {
  PointJet a, b, x;
  // (RP only, as block_theta, bc, bs)
  Eigen::Vector2d n[3];
  double block_theta[3];
  double bc, bs;  // cos and sin of the block's angle
  // at the solved J: the Jacobian's rows (unnormalised: J - A, and J - B or n), its determinant
  double r1x = 0.0, r1y = 0.0, r2x = 0.0, r2y = 0.0, det = 0.0;
};

void PointSchedule::PrepareDyad(const Stage& s, DyadRows& d) const {
  d.a = GlobalPoint(s.anchor_a, s.anchor_a_point);
  if (s.kind == Kind::kDyadRR) {
    d.b = GlobalPoint(s.anchor_b, s.anchor_b_point);
    return;
  }
  const double sign = s.block_is_guide_side ? -1.0 : 1.0;
  if (s.line_at_rest) {
    d.block_theta[0] = sign * s.angle + 2.0 * kPi * before_[s.b].turns;
    d.block_theta[1] = d.block_theta[2] = 0.0;
    d.bc = s.cos_turn;
    d.bs = s.sin_turn;
    d.x.p[0] = s.rest_x;
    d.n[0] = s.rest_n;
    return;
  }
  const LinkJet& guide = now_[s.anchor_b];
  d.block_theta[0] = Angle(s.anchor_b) + sign * s.angle + 2.0 * kPi * before_[s.b].turns;
  d.block_theta[1] = guide.theta[1];
  d.block_theta[2] = guide.theta[2];
  // the block's angle is the guide's turned by the joint's: cos and sin by the sum formulas
  d.bc = guide.c * s.cos_turn - guide.s * s.sin_turn;
  d.bs = guide.s * s.cos_turn + guide.c * s.sin_turn;
  const double t1 = d.block_theta[1], t2 = d.block_theta[2];
  // the block's slide point relative to J, turned with the block
  const Eigen::Vector2d local = s.b_at_anchor - s.b_at_j;
  const Eigen::Vector2d w(d.bc * local.x() - d.bs * local.y(), d.bs * local.x() + d.bc * local.y());
  const PointJet line = GlobalPoint(s.anchor_b, s.anchor_b_point);
  d.x.p[0] = line.p[0] - w;
  d.x.p[1] = line.p[1] - t1 * Perp(w);
  d.x.p[2] = line.p[2] - (t2 * Perp(w) - t1 * t1 * w);
  // the normal turns with the line's link: the guide, or the block when the line is on it
  const double c = s.block_is_guide_side ? d.bc : guide.c, sn = s.block_is_guide_side ? d.bs : guide.s;
  const Eigen::Vector2d axis(c * s.axis.x() - sn * s.axis.y(), sn * s.axis.x() + c * s.axis.y());
  d.n[0] = Perp(axis);
  d.n[1] = t1 * Perp(d.n[0]);
  d.n[2] = t2 * Perp(d.n[0]) - t1 * t1 * d.n[0];
}

int PointSchedule::NewtonDyad(const Stage& s, DyadRows& d, double& jx, double& jy, const StepOptions& options) const {
  const bool rr = s.kind == Kind::kDyadRR;
  // The rows scaled to r1 . dj = g1, r2 . dj = g2 (RR: [r1 / a; r2 / b], RP: [r1 / a; n]), with
  // g1 = (a^2 - |r1|^2) / 2 and (RR) (b^2 - |r2|^2) / 2, (RP) n . (X - J).
  // In scalars: the points come from PointOf's scalars, and 2-vectors built from them would go
  // through the stack (see PointOf).
  const double a2 = s.length_a * s.length_a, b2 = s.length_b * s.length_b;
  const double ax = d.a.p[0].x(), ay = d.a.p[0].y();
  // RR: B; RP: the line's normal and the point X
  const double bx = rr ? d.b.p[0].x() : d.x.p[0].x(), by = rr ? d.b.p[0].y() : d.x.p[0].y();
  const double nx = rr ? 0.0 : d.n[0].x(), ny = rr ? 0.0 : d.n[0].y();
  // (and within the tolerance the caller asks for, should it be below roundoff)
  const double landing2 = std::min(s.landing2, 2.0 * options.tolerance * length_scale_ * (rr ? std::min(s.length_a, s.length_b) : s.length_a));
  double r2x = nx, r2y = ny;
  for (int it = 0; it < options.max_iterations; ++it) {
    const double r1x = jx - ax, r1y = jy - ay;
    const double g1 = 0.5 * (a2 - (r1x * r1x + r1y * r1y));
    double g2;
    if (rr) {
      r2x = jx - bx;
      r2y = jy - by;
      g2 = 0.5 * (b2 - (r2x * r2x + r2y * r2y));
    } else {
      g2 = nx * (bx - jx) + ny * (by - jy);
    }
    const double det = r1x * r2y - r1y * r2x;
    if (!std::isfinite(g1 + g2) || det == 0.0) return -1;  // (g: either not finite, or both beyond any length)
    const double per_det = 1.0 / det;
    const double dx = per_det * (g1 * r2y - g2 * r1y), dy = per_det * (r1x * g2 - r2x * g1);
    jx += dx;
    jy += dy;
    // The update's own residuals, exactly: a circle's row is -|d|^2 / 2 after it (its square
    // term), a line's 0. Within kLanding of a link's length squared, that is roundoff, as
    // small as evaluating the residuals could show: J is returned, with its rows and
    // determinant (for the derivatives and the guards), without evaluating them once more.
    if (dx * dx + dy * dy <= landing2) {
      d.r1x = jx - ax;
      d.r1y = jy - ay;
      if (rr) {
        r2x = jx - bx;
        r2y = jy - by;
      }
      d.r2x = r2x;
      d.r2y = r2y;
      d.det = d.r1x * r2y - d.r1y * r2x;
      return it + 1;
    }
  }
  return -1;
}

void PointSchedule::DyadDerivatives(const Stage& s, const DyadRows& d, double jx, double jy, double jj[3][2]) const {
  // r1 . J' = r1 . A', r2 . J' = rhs (RR: r2 . B'; RP: n . X' - n' . (J - X)), and so for J''
  // (the rows differentiated twice); in scalars, as NewtonDyad
  const double per_det = 1.0 / d.det;
  const double r1x = d.r1x, r1y = d.r1y, r2x = d.r2x, r2y = d.r2y;
  jj[0][0] = jx;
  jj[0][1] = jy;
  auto solve = [&](double g1, double g2, double* to) {
    to[0] = (g1 * r2y - g2 * r1y) * per_det;
    to[1] = (r1x * g2 - r2x * g1) * per_det;
  };
  const Eigen::Vector2d* a = d.a.p;
  auto dot = [](double x, double y, const Eigen::Vector2d& v) { return x * v.x() + y * v.y(); };
  auto square = [](double x, double y) { return x * x + y * y; };
  const double ra1 = dot(r1x, r1y, a[1]), ra2 = dot(r1x, r1y, a[2]);
  if (s.kind == Kind::kDyadRR) {
    const Eigen::Vector2d* b = d.b.p;
    solve(ra1, dot(r2x, r2y, b[1]), jj[1]);
    const double j1x = jj[1][0], j1y = jj[1][1];
    solve(ra2 - square(j1x - a[1].x(), j1y - a[1].y()), dot(r2x, r2y, b[2]) - square(j1x - b[1].x(), j1y - b[1].y()), jj[2]);
  } else if (s.line_at_rest) {  // n . J' = 0 and n . J'' = 0
    solve(ra1, 0.0, jj[1]);
    solve(ra2 - square(jj[1][0] - a[1].x(), jj[1][1] - a[1].y()), 0.0, jj[2]);
  } else {
    const Eigen::Vector2d* x = d.x.p;
    const double offx = jx - x[0].x(), offy = jy - x[0].y();
    solve(ra1, dot(r2x, r2y, x[1]) - dot(offx, offy, d.n[1]), jj[1]);
    const double j1x = jj[1][0], j1y = jj[1][1];
    solve(ra2 - square(j1x - a[1].x(), j1y - a[1].y()),
          dot(r2x, r2y, x[2]) - dot(offx, offy, d.n[2]) - 2.0 * dot(j1x - x[1].x(), j1y - x[1].y(), d.n[1]), jj[2]);
  }
}

[[gnu::flatten]] bool PointSchedule::SolveDyad(Stage& s, double h, const StepOptions& options) {
  DyadRows d;
  PrepareDyad(s, d);
  // (in scalars, as NewtonDyad)
  const Eigen::Vector2d* before = s.j[read_].p;
  const PredictionWeights& w = prediction_;
  double px = before[0].x() + w.j1 * before[1].x() + w.j2 * before[2].x();
  double py = before[0].y() + w.j1 * before[1].y() + w.j2 * before[2].y();
  if (w.quintic) {  // (see PredictionWeights)
    const Eigen::Vector2d* earlier = s.j[read_ ^ 1].p;
    px += w.m0 * (earlier[0].x() - before[0].x()) + w.m1 * (earlier[1].x() - before[1].x()) + w.m2 * (earlier[2].x() - before[2].x());
    py += w.m0 * (earlier[0].y() - before[0].y()) + w.m1 * (earlier[1].y() - before[1].y()) + w.m2 * (earlier[2].y() - before[2].y());
  }
  double jx = px, jy = py;
  const int it = NewtonDyad(s, d, jx, jy, options);
  if (it < 0) return false;
  const double r1_2 = d.r1x * d.r1x + d.r1y * d.r1y;
  const StageGauge gauge{d.det, s.kind == Kind::kDyadRR ? r1_2 * (d.r2x * d.r2x + d.r2y * d.r2y) : r1_2};
  const int sign = d.det > 0.0 ? 1 : -1;
  if (!gauge.Above(std::max(kSingularGauge, options.min_gauge))) return false;
  if (s.det_sign[read_] != 0 && sign != s.det_sign[read_]) return false;
  if (std::max(std::abs(jx - px), std::abs(jy - py)) > options.max_correction * length_scale_) return false;
  double jj[3][2];
  DyadDerivatives(s, d, jx, jy, jj);
  // the first derivative must continue the predicted one (another branch changes it by O(1))
  const double tx = before[1].x() + h * before[2].x(), ty = before[1].y() + h * before[2].y();
  if (std::max(std::abs(jj[1][0] - tx), std::abs(jj[1][1] - ty)) >
      options.max_tangent_change * (length_scale_ + std::max(std::abs(tx), std::abs(ty))))
    return false;
  s.det_sign[write_] = sign;
  s.gauge[write_] = gauge;
  PointJet& j = s.j[write_];  // stored by pairs: the poses below read it as such
  for (int k = 0; k < 3; ++k) StorePair(j.p[k].data(), jj[k][0], jj[k][1]);
  if (!PoseByTwoPoints(s.a, s.a_at_anchor, d.a, s.a_at_j, s.per_length_a, j)) return false;
  if (s.kind == Kind::kDyadRR) return PoseByTwoPoints(s.b, s.b_at_anchor, d.b, s.b_at_j, s.per_length_b, j);
  PoseByAngle(s.b, d.block_theta, d.bc, d.bs, s.b_at_j, j);
  return true;
}

void PointSchedule::Load(double input, const Eigen::VectorXd& q, const Eigen::MatrixXd& series) {
  write_ = read_;  // the stages' solutions at the loaded pose
  for (int l = 0; l < n_links_; ++l) {
    LinkJet& jet = now_[l];
    const int i = system_.CoordinateOf(l);
    if (i < 0) {
      jet = LinkJet();
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const double factor = k == 2 ? 2.0 : 1.0;  // the series holds d2/2
      jet.at[k] = factor * Eigen::Vector2d(series(i, k), series(i + 1, k));
      jet.theta[k] = factor * series(i + 2, k);
    }
    jet.at[0] = q.segment<2>(i);  // the origin
    jet.at_local.setZero();
    jet.theta[0] = q(i + 2);
    jet.angle_pending = false;
    SinCos(jet.theta[0], jet.s, jet.c);
    jet.s += 0.0;  // no -0 (see PoseByTwoPoints)
  }
  // each link's whole turns against the angle its stage gives it (stages in solve order: a
  // stage's anchors have their angles)
  for (int l = 0; l < n_links_; ++l) {
    if (system_.CoordinateOf(l) >= 0) now_[l].turns = static_cast<int>(std::lround((now_[l].theta[0] - AngleBeforeTurns(l, input)) / (2.0 * kPi)));
  }
  for (Stage& s : stages_) {
    if (s.kind == Kind::kDyadPRP || s.kind == Kind::kDyadRPR) {
      LoadSlideDyad(s);
    } else if (s.kind == Kind::kDyadRR || s.kind == Kind::kDyadRP) {
      s.j[write_] = GlobalPoint(s.a, s.a_at_j);
      const PointJet a = GlobalPoint(s.anchor_a, s.anchor_a_point);
      const Eigen::Vector2d r1 = s.j[write_].p[0] - a.p[0];
      Eigen::Vector2d r2;
      if (s.kind == Kind::kDyadRR) {
        r2 = s.j[write_].p[0] - GlobalPoint(s.anchor_b, s.anchor_b_point).p[0];
      } else {
        const LinkJet& line_link = now_[s.block_is_guide_side ? s.b : s.anchor_b];
        r2 = Perp(Eigen::Vector2d(line_link.c * s.axis.x() - line_link.s * s.axis.y(), line_link.s * s.axis.x() + line_link.c * s.axis.y()));
      }
      s.det_sign[write_] = Cross(r1, r2) > 0.0 ? 1 : -1;
      s.gauge[write_] = {Cross(r1, r2), r1.squaredNorm() * r2.squaredNorm()};
    }
  }
  input_ = input;
  h_before_ = 0.0;
  // every slot a copy of the loaded state: the frame's entry is written only here
  for (int k = 0; k < kHistory; ++k) {
    if (k != at_) states_[k] = states_[at_];
  }
  state_input_[at_] = input;
  history_ = 1;
  before_ = now_;
}

bool PointSchedule::Step(double input, const StepOptions& options) {
  const double h = input - input_;
  prediction_.For(h, h_before_);
  const int next = (at_ + 1) % kHistory;
  before_ = now_;  // the state stepped from; the next slot is written stage by stage
  now_ = states_[next].data();
  write_ = read_ ^ 1;
  for (Stage& s : stages_) {
    bool ok = true;
    if (s.kind == Kind::kDriveR || s.kind == Kind::kDriveP) {
      PoseDrive(s, input);
    } else {
      ok = s.kind == Kind::kDyadPRP ? SolvePRP(s, options) : s.kind == Kind::kDyadRPR ? SolveRPR(s, options) : SolveDyad(s, h, options);
    }
    if (!ok) {
      h_before_ = 0.0;  // the stages' other buffers may hold this step's refused solutions
      now_ = states_[at_].data();
      write_ = read_;
      return false;
    }
  }
  at_ = next;
  h_before_ = h;
  read_ = write_;
  state_input_[at_] = input;
  history_ = std::min(history_ + 1, kHistory);
  input_ = input;
  return true;
}

void PointSchedule::HistoryPose(int back, Eigen::VectorXd& q) const {
  const LinkJet* state = states_[Slot(back)].data();
  q.resize(system_.NumCoordinates());
  for (int l = 0; l < n_links_; ++l) {
    const int i = system_.CoordinateOf(l);
    if (i < 0) continue;
    q.segment<2>(i) = PointOf(state[l], Eigen::Vector2d::Zero()).p[0];
    q(i + 2) = AngleIn(state, l);
  }
}

void PointSchedule::Series(Eigen::MatrixXd& series) const {
  for (int l = 0; l < n_links_; ++l) {
    const int i = system_.CoordinateOf(l);
    if (i < 0) continue;
    const LinkJet& jet = now_[l];
    const PointJet origin = PointOf(jet, Eigen::Vector2d::Zero());
    for (int k = 0; k < 3; ++k) {
      const double factor = k == 2 ? 0.5 : 1.0;
      series(i, k) = factor * origin.p[k].x();
      series(i + 1, k) = factor * origin.p[k].y();
      series(i + 2, k) = factor * (k == 0 ? Angle(l) : jet.theta[k]);
    }
  }
}

int PointSchedule::DeterminantSign() const {
  int sign = 1;
  for (const Stage& s : stages_) {
    if (IsDyad(s.kind)) sign *= s.det_sign[read_];
  }
  return sign;
}

double PointSchedule::Gauge() const {
  double gauge = 1.0;
  for (const Stage& s : stages_) {
    if (IsDyad(s.kind)) gauge = std::min(gauge, s.gauge[read_].Value());
  }
  return gauge;
}

}  // namespace koppel
