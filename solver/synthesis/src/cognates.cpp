#include "koppel/synthesis/cognates.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"

#include "koppel/solver/position.hpp"
#include "koppel/solver/sweep.hpp"

#include <cmath>
#include <complex>

namespace koppel {
namespace {

using Complex = std::complex<double>;

Eigen::Vector2d V(Complex z) { return {z.real(), z.imag()}; }

// A binary link with its body frame at `from`, x along `from -> to`, and extra points.
void AddLinkAlong(Mechanism& m, const std::string& name, const std::string& from_name, Complex from, const std::string& to_name,
                  Complex to, const std::vector<std::pair<std::string, Complex>>& extra = {}) {
  const Complex axis = (to - from) / std::abs(to - from);
  PointList points = {{from_name, Eigen::Vector2d::Zero()}, {to_name, Eigen::Vector2d(std::abs(to - from), 0.0)}};
  for (const auto& [n, z] : extra) points.push_back({n, V((z - from) / axis)});
  AddLink(m, name, points);
}

// Frame, crank, coupler (with K), rocker, pinned in a loop; drive at the crank's frame pivot.
Mechanism BuildFourBar(const std::string& name, const std::string& p0, Complex z0, const std::string& p1, Complex z1,
                       const std::string& p2, Complex z2, const std::string& p3, Complex z3, Complex k, double input) {
  Mechanism m;
  m.name = name;
  AddLink(m, "frame", {{p0, V(z0)}, {p3, V(z3)}}, true);
  AddLinkAlong(m, "crank", p0, z0, p1, z1);
  AddLinkAlong(m, "coupler", p1, z1, p2, z2, {{"K", k}});
  AddLinkAlong(m, "rocker", p3, z3, p2, z2);
  Revolute(m, p0, "frame", "crank");
  Revolute(m, p1, "crank", "coupler");
  Revolute(m, p2, "coupler", "rocker");
  Revolute(m, p3, "frame", "rocker");
  // joint angle = crank direction; the input reads `input` at this pose
  SetDrive(m, p0, std::arg(z1 - z0) - input);
  PointOutput(m, "K", "coupler", "K");
  HintInput(m, input);
  HintPoint(m, "crank", p0, V(z0));
  HintPoint(m, "crank", p1, V(z1));
  HintPoint(m, "coupler", p1, V(z1));
  HintPoint(m, "coupler", p2, V(z2));
  HintPoint(m, "coupler", "K", V(k));
  HintPoint(m, "rocker", p3, V(z3));
  HintPoint(m, "rocker", p2, V(z2));
  return m;
}

// The original four-bar's joints A0, A, B, B0 and the coupler point K at its assembled pose.
struct OriginalFourBarPose {
  Complex a0, a, b, b0, k;
};

Expected<OriginalFourBarPose> AssembleOriginalFourBar(const Mechanism& m, const FourBarJoints& f, const PointRef& point) {
  PositionSolver solver(m);
  Eigen::VectorXd q(solver.NumCoordinates());
  const SolveReport assembled = solver.Assemble(q);
  if (!assembled.ok()) return Expected<OriginalFourBarPose>::Error("cannot assemble the original: " + assembled.message);
  auto at = [&](const PointRef& ref) {
    double xy[2];
    solver.system().GlobalPoint(ref, q.data(), xy);
    return Complex(xy[0], xy[1]);
  };
  auto joint_on = [&](int joint, int link) {
    const Joint& j = m.joints[joint];
    return at(j.link_a == link ? PointRef{j.link_a, j.point_a} : PointRef{j.link_b, j.point_b});
  };
  return OriginalFourBarPose{joint_on(f.a0, f.crank), joint_on(f.a, f.crank), joint_on(f.b, f.coupler),
                             joint_on(f.b0, f.rocker), at(point)};
}

// The link lengths of both cognates (frame, crank, coupler, rocker, and K's distances from the
// coupler's joints), from their pivots and joints.
void SetCognateLengths(Cognates* c, Complex k, Complex a0, Complex a1, Complex c1, Complex c0, Complex c2, Complex b2,
                       Complex b0) {
  c->frame_first = std::abs(c0 - a0);
  c->crank_first = std::abs(a1 - a0);
  c->coupler_first = std::abs(c1 - a1);
  c->rocker_first = std::abs(c1 - c0);
  c->k_first = std::abs(k - a1);
  c->l_first = std::abs(k - c1);
  c->frame_second = std::abs(b0 - c0);
  c->crank_second = std::abs(c2 - c0);
  c->coupler_second = std::abs(b2 - c2);
  c->rocker_second = std::abs(b2 - b0);
  c->k_second = std::abs(k - b2);
  c->l_second = std::abs(k - c2);
}

// The original with two outputs: its coupler's direction (A to B) and the point K.
Mechanism CouplerDirectionAndPoint(const Mechanism& m, const FourBarJoints& f, const PointRef& point) {
  Mechanism traced = m;
  traced.outputs.clear();
  Output coupler;
  coupler.name = "coupler";
  coupler.kind = OutputKind::kDirection;
  auto on_coupler = [&](int joint) {
    const Joint& j = m.joints[joint];
    return PointRef{f.coupler, j.link_a == f.coupler ? j.point_a : j.point_b};
  };
  coupler.p = on_coupler(f.a);
  coupler.q = on_coupler(f.b);
  Output traced_k;
  traced_k.name = "K";
  traced_k.kind = OutputKind::kPoint;
  traced_k.p = point;
  traced.outputs = {coupler, traced_k};
  return traced;
}

// Cognate 1's input range over a turn of the original: its crank turns with the original's
// coupler, so its input is `start` plus the unwrapped turning of the coupler direction (column 0
// of `sweep`, which begins at `coupler_start`).
void SetFirstCognateInputRange(Cognates* c, const SweepResult& sweep, double coupler_start, double start) {
  c->first_input_min = c->first_input_max = start;
  double previous = coupler_start, unwrapped = start;
  for (size_t i = 0; i < sweep.inputs.size(); ++i) {
    // unwrap the sampled direction so a full turn of the coupler shows as one
    const double d = std::remainder(sweep.outputs(i, 0) - previous, 2 * kPi);
    previous += d;
    unwrapped += d;
    c->first_input_min = std::min(c->first_input_min, unwrapped);
    c->first_input_max = std::max(c->first_input_max, unwrapped);
  }
}

// Roberts' theorem says cognate 2, driven with the original's input, puts K where the original
// does; proved here on this mechanism, sample by sample (its hint could have picked the other
// assembly branch, which traces another curve). Empty when it does, else why not.
std::string SecondCognateTracesOriginal(const Mechanism& m, const Cognates& c, const SweepOptions& turn,
                                        const SweepResult& original) {
  const SweepResult second = Sweep(c.second, turn);
  const double same = 1e-9 * std::max(1.0, LengthScale(m));
  double worst = 0;
  const size_t n = std::min(original.inputs.size(), second.inputs.size());
  for (size_t i = 0; i < n; ++i) {
    if (std::abs(original.inputs[i] - second.inputs[i]) > 1e-12) break;
    const auto row = static_cast<Eigen::Index>(i);
    worst = std::max({worst, std::abs(second.outputs(row, 0) - original.outputs(row, 1)),
                      std::abs(second.outputs(row, 1) - original.outputs(row, 2))});
  }
  if (n < 2) return "cognate 2 could not be swept beside the original: " + second.message;
  if (!(worst <= same))
    return "cognate 2 does not trace the original's coupler curve (off by " + std::to_string(worst) + "): not reported";
  return "";
}

}  // namespace

Expected<FourBarJoints> IdentifyFourBar(const Mechanism& m) {
  using Result = Expected<FourBarJoints>;
  FourBarJoints joints;
  FourBarJoints* f = &joints;
  if (m.links.size() != 4 || m.joints.size() != 4) {
    return Result::Error("cognates need a four-bar: 4 links and 4 joints");
  }
  for (const Joint& j : m.joints) {
    if (j.type != JointType::kRevolute) {
      return Result::Error("cognates need a four-bar of revolute joints (joint '" + j.name + "' is prismatic)");
    }
  }
  f->frame = m.FrameLink();
  f->a0 = m.drive.joint;
  const Joint& drive = m.joints[f->a0];
  if (drive.link_a != f->frame && drive.link_b != f->frame) {
    return Result::Error("the drive must be a frame joint (the crank's pivot)");
  }
  f->crank = drive.link_a == f->frame ? drive.link_b : drive.link_a;
  auto other_joint = [&](int link, int joint) {
    for (int k = 0; k < 4; ++k) {
      if (k != joint && (m.joints[k].link_a == link || m.joints[k].link_b == link)) return k;
    }
    return -1;
  };
  auto other_link = [&](int joint, int link) { return m.joints[joint].link_a == link ? m.joints[joint].link_b : m.joints[joint].link_a; };
  f->a = other_joint(f->crank, f->a0);
  f->coupler = other_link(f->a, f->crank);
  f->b = other_joint(f->coupler, f->a);
  f->rocker = other_link(f->b, f->coupler);
  f->b0 = other_joint(f->rocker, f->b);
  if (f->b0 < 0 || other_link(f->b0, f->rocker) != f->frame) {
    return Result::Error("the links do not form one loop frame-crank-coupler-rocker");
  }
  return joints;
}

std::optional<std::array<FourBarPose, 2>> CognatePoses(const FourBarPose& o) {
  auto z = [](const Eigen::Vector2d& v) { return Complex(v.x(), v.y()); };
  const Complex a0 = z(o.a0), a = z(o.a), b = z(o.b), b0 = z(o.b0), k = z(o.k);
  if (std::abs(b - a) == 0) return std::nullopt;
  // K = A + r (B - A); the frame triangle A0 B0 C0 is similar to A B K
  const Complex r = (k - a) / (b - a);
  if (std::abs(1.0 - r) < 1e-12 || std::abs(r) < 1e-12) return std::nullopt;
  const Complex c0 = a0 + r * (b0 - a0);
  const Complex a1 = a0 + r * (b - a), c1 = a1 + r * (a - a0);
  const Complex c2 = c0 + (1.0 - r) * (a - a0), b2 = b0 + (r - 1.0) * (b - a);
  return std::array<FourBarPose, 2>{FourBarPose{o.a0, V(a1), V(c1), V(c0), o.k}, FourBarPose{V(c0), V(c2), V(b2), o.b0, o.k}};
}

Cognates RobertsCognates(const Mechanism& m, const PointRef& point) {
  Cognates c;
  c.status = DesignStatus::kInvalidRequest;
  const Expected<FourBarJoints> identified = IdentifyFourBar(m);
  if (!identified) {
    c.message = identified.error();
    return c;
  }
  const FourBarJoints& f = *identified;
  if (point.link != f.coupler) {
    c.message = "the point must lie on the coupler '" + m.links[f.coupler].name + "'";
    return c;
  }
  const Expected<OriginalFourBarPose> original = AssembleOriginalFourBar(m, f, point);
  if (!original) {
    c.message = original.error();
    return c;
  }
  const auto [a0, a, b, b0, k] = *original;
  c.status = DesignStatus::kNoDesign;  // from here on: the geometry has no cognates
  if (std::abs(b - a) == 0) {
    c.message = "the coupler joints coincide";
    return c;
  }
  const std::optional<std::array<FourBarPose, 2>> poses = CognatePoses({V(a0), V(a), V(b), V(b0), V(k)});
  if (!poses) {
    c.message = "the coupler point coincides with a coupler joint: its cognates degenerate";
    return c;
  }
  auto z = [](const Eigen::Vector2d& v) { return Complex(v.x(), v.y()); };
  const Complex c0 = z((*poses)[0].b0), a1 = z((*poses)[0].a), c1 = z((*poses)[0].b);
  const Complex c2 = z((*poses)[1].a), b2 = z((*poses)[1].b);
  const double input = m.hint.input;
  // cognate 1's crank turns with the original coupler: its input is that coupler's direction
  c.first = BuildFourBar(m.name + "-cognate-1", "A0", a0, "A1", a1, "C1", c1, "C0", c0, k, std::arg(a1 - a0));
  // cognate 2's crank turns with the original crank: the same input as the original
  c.second = BuildFourBar(m.name + "-cognate-2", "C0", c0, "C2", c2, "B2", b2, "B0", b0, k, input);
  SetCognateLengths(&c, k, a0, a1, c1, c0, c2, b2, b0);
  // cognate 1's input over a turn of the original: the direction of r (B - A)
  SweepOptions turn;
  turn.from = input;
  turn.to = input + 2 * kPi;
  turn.step = kPi / 360;
  turn.order = 0;  // columns: the coupler's direction, K_x, K_y
  const SweepResult sweep = Sweep(CouplerDirectionAndPoint(m, f, point), turn);
  SetFirstCognateInputRange(&c, sweep, std::arg(b - a), std::arg(a1 - a0));
  const std::string mismatch = SecondCognateTracesOriginal(m, c, turn, sweep);
  if (!mismatch.empty()) {
    c.status = DesignStatus::kReanalysisFailed;
    c.message = mismatch;
    return c;
  }
  c.status = DesignStatus::kOk;
  c.message.clear();
  return c;
}

std::string Cognates::Brief() const {
  return std::string(ToString(status)) + (ok() ? ": cognate frames " + std::to_string(frame_first) + " and " + std::to_string(frame_second)
                                              : ": " + message);
}

}  // namespace koppel
