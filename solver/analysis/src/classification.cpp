#include "koppel/analysis/classification.hpp"

#include "koppel/analysis/ranges.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/assembly.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace koppel {
namespace {

// Grashof equality is decided to this fraction of L: far above the rounding of dimensions given
// as formulas (1e-16), far below any deliberate design difference.
constexpr double kEqualLengths = 1e-9;

std::string Number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}

// The joints of a link, in joint order.
std::vector<int> JointsOf(const Mechanism& m, int link) {
  std::vector<int> joints;
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j) {
    if (m.joints[j].link_a == link || m.joints[j].link_b == link) joints.push_back(j);
  }
  return joints;
}

Eigen::Vector2d Local(const Mechanism& m, const PointRef& p) { return m.links[p.link].points[p.point].local; }

// Distance between the two joint points of a binary link, in its own frame.
double LinkLength(const Mechanism& m, int link) {
  const std::vector<int> joints = JointsOf(m, link);
  return (Local(m, JointPointOn(m.joints[joints[0]], link)) - Local(m, JointPointOn(m.joints[joints[1]], link))).norm();
}

int OtherLink(const Joint& j, int link) { return j.link_a == link ? j.link_b : j.link_a; }

void ClassifyFourBar(const Mechanism& m, double scale, Classification& c) {
  const int frame = m.FrameLink();
  std::array<std::pair<double, int>, 4> by_length;
  for (int l = 0; l < 4; ++l) by_length[l] = {LinkLength(m, l), l};
  std::sort(by_length.begin(), by_length.end());
  const double s = by_length[0].first, p = by_length[1].first, q = by_length[2].first, l = by_length[3].first;
  const int shortest = by_length[0].second;
  c.lengths = {{"s", s}, {"l", l}, {"p", p}, {"q", q}};
  const double difference = (s + l) - (p + q);
  std::string relation = std::abs(difference) <= kEqualLengths * scale ? "=" : (difference < 0 ? "<" : ">");
  c.rule = "s + l = " + Number(s) + " + " + Number(l) + " = " + Number(s + l) + " " + relation + " p + q = " + Number(p) + " + " +
           Number(q) + " = " + Number(p + q);
  if (relation == "=") {
    c.grashof = GrashofType::kChangePoint;
    c.rule += " (Grashof-neutral)";
    return;
  }
  if (relation == ">") {
    c.grashof = GrashofType::kTripleRocker;
    c.rule += " (non-Grashof: no link turns fully)";
    return;
  }
  bool adjacent = false;
  for (int j : JointsOf(m, frame)) adjacent |= OtherLink(m.joints[j], frame) == shortest;
  const std::string name = "'" + m.links[shortest].name + "'";
  if (shortest == frame) {
    c.grashof = GrashofType::kDoubleCrank;
    c.rule += "; the shortest link, " + name + ", is the frame";
  } else if (adjacent) {
    c.grashof = GrashofType::kCrankRocker;
    c.rule += "; the shortest link, " + name + ", is adjacent to the frame (the crank)";
  } else {
    c.grashof = GrashofType::kDoubleRocker;
    c.rule += "; the shortest link, " + name + ", is the coupler, opposite the frame";
  }
}

void ClassifySliderCrank(const Mechanism& m, int slide, double scale, Classification& c) {
  const int frame = m.FrameLink();
  const Joint& p = m.joints[slide];
  if (p.link_a != frame) {
    c.notes.push_back("an inversion of the slider-crank chain (the slide is not on the frame): no Grashof type is given");
    return;
  }
  const int slider = p.link_b;
  const int slider_pin = OtherJointOfBinaryLink(m, slider, slide);
  const int coupler = OtherLink(m.joints[slider_pin], slider);
  const int crank_pin = OtherJointOfBinaryLink(m, coupler, slider_pin);
  const int crank = OtherLink(m.joints[crank_pin], coupler);
  const int pivot = OtherJointOfBinaryLink(m, crank, crank_pin);
  if (OtherLink(m.joints[pivot], crank) != frame) return;
  const double a = LinkLength(m, crank), b = LinkLength(m, coupler);
  // the line the coupler's pin B runs on: the slide line shifted by B's offset from the block's
  // slide point (the block keeps its angle `angle` against the frame)
  const Eigen::Vector2d offset = Local(m, JointPointOn(m.joints[slider_pin], slider)) - Local(m, {slider, p.point_b});
  const double ca = std::cos(p.angle), sa = std::sin(p.angle);
  const Eigen::Vector2d on_line = Local(m, {frame, p.point_a}) + Eigen::Vector2d(ca * offset.x() - sa * offset.y(), sa * offset.x() + ca * offset.y());
  const Eigen::Vector2d a0 = Local(m, JointPointOn(m.joints[pivot], frame)) - on_line;
  const double e = p.axis.x() * a0.y() - p.axis.y() * a0.x();
  c.lengths = {{"a", a}, {"b", b}, {"e", e}};
  const double difference = a + std::abs(e) - b;
  const std::string relation = std::abs(difference) <= kEqualLengths * scale ? "=" : (difference < 0 ? "<" : ">");
  c.rule = "a + |e| = " + Number(a) + " + " + Number(std::abs(e)) + " = " + Number(a + std::abs(e)) + " " + relation + " b = " + Number(b) +
           " (a crank '" + m.links[crank].name + "', b coupler '" + m.links[coupler].name + "', e offset of the crank pivot)";
  c.grashof = relation == "=" ? GrashofType::kChangePoint : (relation == "<" ? GrashofType::kCrankSlider : GrashofType::kRockerSlider);
}

}  // namespace

const char* ToString(GrashofType type) {
  switch (type) {
    case GrashofType::kNotApplicable: return "not-applicable";
    case GrashofType::kCrankRocker: return "crank-rocker";
    case GrashofType::kDoubleCrank: return "double-crank";
    case GrashofType::kDoubleRocker: return "double-rocker";
    case GrashofType::kTripleRocker: return "triple-rocker";
    case GrashofType::kChangePoint: return "change-point";
    case GrashofType::kCrankSlider: return "crank-slider";
    case GrashofType::kRockerSlider: return "rocker-slider";
  }
  return "not-applicable";
}

Classification ClassifyChain(const Mechanism& m) {
  Classification c;
  c.mobility = AnalyseStructure(m).gruebler_mobility;
  if (m.links.size() != 4 || m.joints.size() != 4 || m.FrameLink() < 0) return c;
  for (int l = 0; l < 4; ++l) {
    if (JointsOf(m, l).size() != 2) return c;  // not a single loop of binary links
  }
  int prismatic = -1, prismatic_count = 0;
  for (int j = 0; j < 4; ++j) {
    if (m.joints[j].type == JointType::kPrismatic) {
      prismatic = j;
      ++prismatic_count;
    }
  }
  const double scale = LengthScale(m);
  if (prismatic_count == 0) ClassifyFourBar(m, scale, c);
  if (prismatic_count == 1) ClassifySliderCrank(m, prismatic, scale, c);
  return c;
}

Classification Classify(const Mechanism& m) {
  Classification c = ClassifyChain(m);
  const MobilityReport mobility = CheckMobility(m);
  c.rank_mobility = mobility.rank_mobility;
  c.assembled = mobility.assembled;
  if (!mobility.note.empty()) c.notes.push_back(mobility.note);
  if (!mobility.error.empty()) c.notes.push_back(mobility.error);
  if (c.assembled && mobility.ok() && m.InputIsAngle()) {
    const RangeReport ranges = DrivableRanges(m);
    c.drive_turns_fully = !ranges.branches.empty() && ranges.branches[0].to_kind == RangeEnd::kFullTurn;
  }
  return c;
}

}  // namespace koppel
