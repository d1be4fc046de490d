// The compiled step's dyads with two slides (point_schedule.hpp): PRP, two blocks on posed guides
// hinged to each other, and RPR, a block hinged to a posed link sliding on the line of a link that
// turns about a posed pivot (a slotted link, Schleife). Neither needs Newton: PRP is the meeting
// point of two lines, RPR the line's normal n at the distance `offset` from the block's hinge A,
// measured from the pivot B: n . (A - B) = offset, a unit vector given by the square root below
// on the branch the walk stands on. Both hand over to the general kernel, as the other dyads, where
// their normalised determinant falls below the step's gauge (lines turning parallel; the hinge
// reaching the line's offset circle, a dead centre of the slotted link).
#include "koppel/solver/constraints.hpp"
#include "koppel/solver/point_schedule.hpp"

#include "point_schedule_parts.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {
using namespace point_schedule_parts;

namespace {

// An unused P joint whose block is `link` and whose guide is posed (not the drive, not `except`).
int BlockJointToPosed(const Mechanism& m, int link, int except, const std::vector<bool>& posed, const std::vector<bool>& used) {
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (k == except || k == m.drive.joint || used[k] || j.type != JointType::kPrismatic || j.link_b != link) continue;
    if (posed[j.link_a]) return k;
  }
  return -1;
}

}  // namespace

// What a slide's row knows before the solve: n . (J - X) = 0, the normal n and the point X that
// J keeps the line's offset from (the block's slide point turned with the block, which turns with
// the guide), with their derivatives ([k][0], [k][1]: x and y of the k-th); the block's cos and
// sin and angular rates. In scalars: PointOf's points are scalars, and 2-vectors built from them
// would go through the stack (see PointOf).
struct PointSchedule::LineRow {
  double x[3][2], n[3][2];
  double bc = 1.0, bs = 0.0, t1 = 0.0, t2 = 0.0;
  // n . X and the k-th derivative's rows
  double Along(int k, double jx, double jy) const { return n[k][0] * jx + n[k][1] * jy; }
};

void PointSchedule::PrepareLine(const Slide& slide, const Eigen::Vector2d& at_j, LineRow& row) const {
  const Eigen::Vector2d local = slide.block_point - at_j;
  if (slide.guide == frame_) {  // a line at rest: no derivatives
    row.bc = slide.cos_turn;
    row.bs = slide.sin_turn;
    row.t1 = row.t2 = 0.0;
    row.x[0][0] = slide.guide_point.x() - (row.bc * local.x() - row.bs * local.y());
    row.x[0][1] = slide.guide_point.y() - (row.bs * local.x() + row.bc * local.y());
    row.n[0][0] = -slide.axis.y();
    row.n[0][1] = slide.axis.x();
    for (int k = 1; k < 3; ++k) row.x[k][0] = row.x[k][1] = row.n[k][0] = row.n[k][1] = 0.0;
    return;
  }
  const LinkJet& guide = now_[slide.guide];
  row.bc = guide.c * slide.cos_turn - guide.s * slide.sin_turn;
  row.bs = guide.s * slide.cos_turn + guide.c * slide.sin_turn;
  const double t1 = row.t1 = guide.theta[1], t2 = row.t2 = guide.theta[2], t11 = t1 * t1;
  // w: the slide point from J, turned with the block; X = line - w, X' = line' - t1 perp(w), ...
  const double wx = row.bc * local.x() - row.bs * local.y(), wy = row.bs * local.x() + row.bc * local.y();
  const PointJet line = GlobalPoint(slide.guide, slide.guide_point);
  row.x[0][0] = line.p[0].x() - wx;
  row.x[0][1] = line.p[0].y() - wy;
  row.x[1][0] = line.p[1].x() + t1 * wy;
  row.x[1][1] = line.p[1].y() - t1 * wx;
  row.x[2][0] = line.p[2].x() + t2 * wy + t11 * wx;
  row.x[2][1] = line.p[2].y() - t2 * wx + t11 * wy;
  // n = perp(the axis turned with the guide), n' = t1 perp(n), n'' = t2 perp(n) - t1^2 n
  const double nx = -(guide.s * slide.axis.x() + guide.c * slide.axis.y()), ny = guide.c * slide.axis.x() - guide.s * slide.axis.y();
  row.n[0][0] = nx;
  row.n[0][1] = ny;
  row.n[1][0] = -t1 * ny;
  row.n[1][1] = t1 * nx;
  row.n[2][0] = -t2 * ny - t11 * nx;
  row.n[2][1] = t2 * nx - t11 * ny;
}

PointSchedule::Slide PointSchedule::SlideOf(int k) const {
  const Mechanism& m = mechanism_;
  const Joint& j = m.joints[k];
  Slide slide;
  slide.guide = j.link_a;
  slide.block = j.link_b;
  slide.axis = j.axis.normalized();
  slide.guide_point = m.links[j.link_a].points[j.point_a].local;
  slide.block_point = m.links[j.link_b].points[j.point_b].local;
  slide.cos_turn = std::cos(j.angle);
  slide.sin_turn = std::sin(j.angle);
  return slide;
}

bool PointSchedule::AddSlideDyadStage(std::vector<bool>& posed, std::vector<bool>& used) {
  const Mechanism& m = mechanism_;
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (used[k] || k == m.drive.joint || posed[j.link_a] || posed[j.link_b] || !(j.axis.norm() > 0.0)) continue;
    Stage s;
    int ka = -1, kb = -1;
    if (j.type == JointType::kRevolute) {
      // PRP: each link a block on a posed guide
      ka = BlockJointToPosed(m, j.link_a, k, posed, used);
      kb = BlockJointToPosed(m, j.link_b, k, posed, used);
      if (ka < 0 || kb < 0) continue;
      s.kind = Kind::kDyadPRP;
      s.a = j.link_a;
      s.b = j.link_b;
      s.line_a = SlideOf(ka);
      s.line_b = SlideOf(kb);
      s.anchor_a = s.line_a.guide;
      s.anchor_b = s.line_b.guide;
      s.a_at_j = LocalAt(m, k, s.a);
      s.b_at_j = LocalAt(m, k, s.b);
    } else {
      // RPR: the block (link_b) and the line's link (link_a), each hinged to a posed link
      ka = FreeJointToPosed(m, j.link_b, k, JointType::kRevolute, posed, used);
      kb = FreeJointToPosed(m, j.link_a, k, JointType::kRevolute, posed, used);
      if (ka < 0 || kb < 0) continue;
      CompileRPR(s, k, ka, kb);
    }
    used[k] = used[ka] = used[kb] = true;
    posed[s.a] = posed[s.b] = true;
    stages_.push_back(s);
    return true;
  }
  return false;
}

void PointSchedule::CompileRPR(Stage& s, int k, int ka, int kb) const {
  const Mechanism& m = mechanism_;
  const Joint& j = m.joints[k];
  s.kind = Kind::kDyadRPR;
  s.a = j.link_b;
  s.b = j.link_a;
  s.anchor_a = OtherLink(m, ka, s.a);
  s.a_at_anchor = LocalAt(m, ka, s.a);
  s.anchor_a_point = LocalAt(m, ka, s.anchor_a);
  s.anchor_b = OtherLink(m, kb, s.b);
  s.b_at_anchor = LocalAt(m, kb, s.b);
  s.anchor_b_point = LocalAt(m, kb, s.anchor_b);
  s.line_b = SlideOf(k);
  s.normal = Perp(s.line_b.axis);
  // n . (S - L) = 0 for the block's slide point S and the line's point L, both turning with the
  // line's link apart from the hinge A and the pivot B: n . (A - B) = offset
  s.offset = s.normal.dot(s.line_b.guide_point - s.b_at_anchor) -
             s.normal.dot(Turned(s.line_b.cos_turn, s.line_b.sin_turn, s.line_b.block_point - s.a_at_anchor));
}

[[gnu::flatten]] bool PointSchedule::SolvePRP(Stage& s, const StepOptions& options) {
  LineRow ra, rb;
  PrepareLine(s.line_a, s.a_at_j, ra);
  PrepareLine(s.line_b, s.b_at_j, rb);
  // [na; nb] J = [na . Xa; nb . Xb], differentiated as the RP dyad's line row
  const double r1x = ra.n[0][0], r1y = ra.n[0][1], r2x = rb.n[0][0], r2y = rb.n[0][1];
  const double det = r1x * r2y - r1y * r2x;
  const StageGauge gauge{det, 1.0};  // unit normals: the sine between the lines
  const int sign = det > 0.0 ? 1 : -1;
  if (!gauge.Above(std::max(kSingularGauge, options.min_gauge))) return false;
  if (s.det_sign[read_] != 0 && sign != s.det_sign[read_]) return false;
  const double per_det = 1.0 / det;
  double j[3][2];
  auto solve = [&](double g1, double g2, double* to) {
    to[0] = (g1 * r2y - g2 * r1y) * per_det;
    to[1] = (r1x * g2 - r2x * g1) * per_det;
  };
  solve(ra.Along(0, ra.x[0][0], ra.x[0][1]), rb.Along(0, rb.x[0][0], rb.x[0][1]), j[0]);
  const double oax = j[0][0] - ra.x[0][0], oay = j[0][1] - ra.x[0][1], obx = j[0][0] - rb.x[0][0], oby = j[0][1] - rb.x[0][1];
  solve(ra.Along(0, ra.x[1][0], ra.x[1][1]) - ra.Along(1, oax, oay), rb.Along(0, rb.x[1][0], rb.x[1][1]) - rb.Along(1, obx, oby), j[1]);
  solve(ra.Along(0, ra.x[2][0], ra.x[2][1]) - ra.Along(2, oax, oay) - 2.0 * ra.Along(1, j[1][0] - ra.x[1][0], j[1][1] - ra.x[1][1]),
        rb.Along(0, rb.x[2][0], rb.x[2][1]) - rb.Along(2, obx, oby) - 2.0 * rb.Along(1, j[1][0] - rb.x[1][0], j[1][1] - rb.x[1][1]), j[2]);
  PointJet& jj = s.j[write_];
  for (int k = 0; k < 3; ++k) StorePair(jj.p[k].data(), j[k][0], j[k][1]);
  s.det_sign[write_] = sign;
  s.gauge[write_] = gauge;
  return PoseByCosSin(s.a, ra.bc, ra.bs, ra.t1, ra.t2, s.a_at_j, jj) && PoseByCosSin(s.b, rb.bc, rb.bs, rb.t1, rb.t2, s.b_at_j, jj);
}

[[gnu::flatten]] bool PointSchedule::SolveRPR(Stage& s, const StepOptions& options) {
  const PointJet a = GlobalPoint(s.anchor_a, s.anchor_a_point);  // the block's hinge
  const PointJet b = GlobalPoint(s.anchor_b, s.anchor_b_point);  // the line's pivot
  const Eigen::Vector2d d = a.p[0] - b.p[0], d1 = a.p[1] - b.p[1], d2 = a.p[2] - b.p[2];
  const double dd = d.squaredNorm(), root2 = dd - s.offset * s.offset;
  if (!(root2 > 0.0)) return false;
  const double root = std::sqrt(root2);
  // n . d = offset, |n| = 1: n = (offset d + branch root perp(d)) / |d|^2
  const Eigen::Vector2d n = (s.offset * d + s.branch * root * Perp(d)) * (1.0 / dd);
  // d(n . d)/d theta = perp(n) . d = -branch root (perp(perp(d)) = -d): its inverse taken from
  // root, beside 1 / dd rather than after it
  const double det = -s.branch * root, per_det = -s.branch / root;
  const StageGauge gauge{root, dd};
  const int sign = det > 0.0 ? 1 : -1;
  if (!gauge.Above(std::max(kSingularGauge, options.min_gauge))) return false;
  if (s.det_sign[read_] != 0 && sign != s.det_sign[read_]) return false;
  // n' = theta' perp(n): theta' (perp(n) . d) + n . d' = 0, and once more
  const double t1 = -n.dot(d1) * per_det;
  const double t2 = (t1 * t1 * s.offset - 2.0 * t1 * Perp(n).dot(d1) - n.dot(d2)) * per_det;
  s.det_sign[write_] = sign;
  s.gauge[write_] = gauge;
  // n = R(theta) normal: cos and sin of the line's link; the block turned by the joint's angle
  const double c = s.normal.dot(n), sn = Cross(s.normal, n);
  const double bc = c * s.line_b.cos_turn - sn * s.line_b.sin_turn, bs = sn * s.line_b.cos_turn + c * s.line_b.sin_turn;
  return PoseByCosSin(s.b, c, sn, t1, t2, s.b_at_anchor, b) && PoseByCosSin(s.a, bc, bs, t1, t2, s.a_at_anchor, a);
}

void PointSchedule::LoadSlideDyad(Stage& s) {
  double det = 0.0, norm2 = 1.0;
  if (s.kind == Kind::kDyadPRP) {
    LineRow ra, rb;
    PrepareLine(s.line_a, s.a_at_j, ra);
    PrepareLine(s.line_b, s.b_at_j, rb);
    det = ra.n[0][0] * rb.n[0][1] - ra.n[0][1] * rb.n[0][0];
    s.j[write_] = GlobalPoint(s.a, s.a_at_j);
  } else {
    const Eigen::Vector2d d = GlobalPoint(s.anchor_a, s.anchor_a_point).p[0] - GlobalPoint(s.anchor_b, s.anchor_b_point).p[0];
    const LinkJet& line = now_[s.b];
    const Eigen::Vector2d n = Turned(line.c, line.s, s.normal);
    s.branch = Perp(d).dot(n) >= 0.0 ? 1.0 : -1.0;
    det = Perp(n).dot(d);
    norm2 = d.squaredNorm();
  }
  s.det_sign[write_] = det > 0.0 ? 1 : -1;
  s.gauge[write_] = {det, norm2};
}

}  // namespace koppel
