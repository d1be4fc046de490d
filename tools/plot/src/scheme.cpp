#include "koppel/plot/scheme.hpp"
#include "koppel/core/angles.hpp"

#include "koppel/plot/label_layout.hpp"
#include "koppel/plot/svg.hpp"
#include "plot_support.hpp"
#include "koppel/solver/constraints.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

namespace koppel::plot {
namespace {

using Vec = Eigen::Vector2d;

// Sizes of the symbols in px, independent of the mechanism's size.
constexpr double kJointRadius = 4.5, kBlockLength = 30, kBlockWidth = 15, kMargin = 40, kCaption = 22;
constexpr double kPivotHeight = 13, kPivotHalfWidth = 9, kHatch = 6, kArrowRadius = 26, kMarkRadius = 2.2;
// Font sizes of the labels (as in kSchemeStyle): the label layout estimates their extent from them.
constexpr double kLabelFont = 13, kOverlayLabelFont = 12, kCaptionFont = 14;
const char* kInk = "#1d2b3a";
const char* kLinkFill = "#d3e2f1";

const char* kSchemeStyle =
    "<style>"
    "text{font-family:DejaVu Sans,Arial,sans-serif;font-size:13px;fill:#1d2b3a}"
    ".caption{font-size:14px}.overlay-labels text{fill:#777;font-size:12px}"
    ".hatch{stroke:#1d2b3a;stroke-width:1}.trace{fill:none;stroke:#c0392b;stroke-width:1.4}"
    ".leader{stroke:#1d2b3a;stroke-width:.7}.overlay-labels .leader{stroke:#999}"
    ".guide-axis{stroke:#1d2b3a;stroke-width:.7;stroke-dasharray:12 3 2 3}"
    "</style>";

struct View {
  double scale = 1, ox = 0, oy = 0;
  Vec operator()(const Vec& w) const { return {ox + scale * w.x(), oy - scale * w.y()}; }
};

struct LinkPose {
  Vec origin = Vec::Zero();
  double theta = 0;
  Vec ToGlobal(const Vec& local) const { return origin + Eigen::Rotation2Dd(theta) * local; }
};

LinkPose PoseOf(const ConstraintSystem& system, int link, const Eigen::VectorXd& q) {
  const int c = system.CoordinateOf(link);
  if (c < 0) return {};
  return {Vec(q[c], q[c + 1]), q[c + 2]};
}

// The SVG transform from a link's body frame to the picture: body -> global -> px (y flipped).
std::string Transform(const View& view, const LinkPose& pose) {
  const double s = view.scale, c = std::cos(pose.theta), n = std::sin(pose.theta);
  return "matrix(" + Num(s * c, 6) + " " + Num(-s * n, 6) + " " + Num(-s * n, 6) + " " + Num(-s * c, 6) + " " +
         Num(view.ox + s * pose.origin.x(), 3) + " " + Num(view.oy - s * pose.origin.y(), 3) + ")";
}

// A point's label: where the point is (px), the text, and where the layout put it.
struct PointLabel {
  std::string name, text;  // the point's name; the text shown (with an overlay's suffix)
  PointRef ref;
  Vec anchor = Vec::Zero();
  bool needs_mark = false;  // no joint circle or block shows the point: a dot does
  PlacedLabel placed;
};

class SchemeWriter {
 public:
  SchemeWriter(const Mechanism& m, const SchemeScene& scene) : m_(m), scene_(scene), system_(m) {
    for (const Eigen::VectorXd* q : AllPoses())
      if (q->size() != system_.NumCoordinates()) throw std::invalid_argument("DrawScheme: pose of the wrong size");
    GuideExtents();
    FitView();
  }

  std::string Write() {
    PlaceAllLabels();
    Svg svg(scene_.width, height_);
    svg.Defs(kSchemeStyle);
    svg.Rect(0, 0, scene_.width, height_, {{"fill", "#fff"}});
    if (!scene_.trace.empty()) {
      std::vector<std::vector<Vec>> runs;
      for (const auto& run : scene_.trace) {
        runs.emplace_back();
        for (const Vec& p : run) runs.back().push_back(view_(p));
      }
      svg.Path(runs, {{"class", "trace"}, {"data-name", scene_.trace_name}});
    }
    for (size_t i = 0; i < scene_.overlays.size(); ++i) Overlay(svg, scene_.overlays[i], labels_[i + 1]);
    Frame(svg);
    // bodies first, then joint circles, so that every joint sits on top of the links it joins
    for (int pass = 0; pass < 2; ++pass)
      for (int l = 0; l < static_cast<int>(m_.links.size()); ++l)
        if (!m_.links[l].is_frame) MovingLink(svg, l, pass == 1);
    // the labels last, so that no link covers one
    for (size_t i = 1; i < labels_.size(); ++i) Labels(svg, labels_[i], true);
    Labels(svg, labels_.front(), false);
    svg.Text({kMargin / 2, 17}, scene_.caption, {{"class", "caption"}, {"id", "caption"}});
    // the world -> px map, for the page's animation and for readers of the picture
    return svg.Finish({{"class", "scheme"}, {"data-scale", Num(view_.scale, 9)}, {"data-ox", Num(view_.ox, 6)}, {"data-oy", Num(view_.oy, 6)}});
  }

 private:
  std::vector<const Eigen::VectorXd*> AllPoses() const {
    std::vector<const Eigen::VectorXd*> poses = {&scene_.q};
    for (const auto& o : scene_.overlays) poses.push_back(&o.q);
    for (const auto& q : scene_.extent) poses.push_back(&q);
    return poses;
  }

  Vec Global(const PointRef& p, const Eigen::VectorXd& q) const {
    double xy[2];
    system_.GlobalPoint(p, q.data(), xy);
    return {xy[0], xy[1]};
  }

  // The travel of every slider along its guide (guide body frame, from the guide's point), so
  // that a guide is drawn as long as the block moves on it.
  void GuideExtents() {
    travel_.assign(m_.joints.size(), {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()});
    for (size_t j = 0; j < m_.joints.size(); ++j) {
      const Joint& joint = m_.joints[j];
      if (joint.type != JointType::kPrismatic) continue;
      auto& [low, high] = travel_[j];
      if (!m_.links[joint.link_a].is_frame) low = high = 0;  // a slot starts at its own point
      else  // a guide on the frame reaches the frame's points on its line (the foot point F)
        for (const NamedPoint& p : m_.links[joint.link_a].points) {
          const Vec along = p.local - m_.links[joint.link_a].points[joint.point_a].local;
          if (std::abs(along.x() * joint.axis.y() - along.y() * joint.axis.x()) > 1e-9 * LengthScale(m_)) continue;
          low = std::min(low, along.dot(joint.axis));
          high = std::max(high, along.dot(joint.axis));
        }
      for (const Eigen::VectorXd* q : AllPoses()) {
        const LinkPose guide = PoseOf(system_, joint.link_a, *q);
        const Vec axis = Eigen::Rotation2Dd(guide.theta) * joint.axis;
        const double s = axis.dot(Global({joint.link_b, joint.point_b}, *q) - Global({joint.link_a, joint.point_a}, *q));
        low = std::min(low, s);
        high = std::max(high, s);
      }
    }
  }

  // Ends of a guide in its body frame, the block's half length beyond the travel.
  std::pair<Vec, Vec> GuideEnds(int j) const {
    const Joint& joint = m_.joints[j];
    const Vec p = m_.links[joint.link_a].points[joint.point_a].local;
    const double margin = 0.75 * kBlockLength / view_.scale;
    return {p + (travel_[j].first - margin) * joint.axis, p + (travel_[j].second + margin) * joint.axis};
  }

  void FitView() {
    // first with a unit scale for the world box, then again with the guides' margins at scale
    for (int round = 0; round < 2; ++round) {
      Vec low = Vec::Constant(std::numeric_limits<double>::infinity()), high = -low;
      auto add = [&](const Vec& p) { low = low.cwiseMin(p), high = high.cwiseMax(p); };
      for (const Eigen::VectorXd* q : AllPoses()) {
        for (int l = 0; l < static_cast<int>(m_.links.size()); ++l)
          for (int i = 0; i < static_cast<int>(m_.links[l].points.size()); ++i) add(Global({l, i}, *q));
        if (round == 1)
          for (size_t j = 0; j < m_.joints.size(); ++j)
            if (m_.joints[j].type == JointType::kPrismatic) {
              const LinkPose guide = PoseOf(system_, m_.joints[j].link_a, *q);
              const auto [a, b] = GuideEnds(static_cast<int>(j));
              add(guide.ToGlobal(a));
              add(guide.ToGlobal(b));
            }
      }
      for (const auto& run : scene_.trace)
        for (const Vec& p : run) add(p);
      const Vec size = (high - low).cwiseMax(Vec::Constant(1e-9 * std::max(1.0, LengthScale(m_))));
      const double usable = scene_.width - 2 * kMargin;
      view_.scale = usable / size.x();
      height_ = size.y() * view_.scale + 2 * kMargin + kCaption;
      if (height_ > 1.1 * scene_.width) {
        view_.scale = (1.1 * scene_.width - 2 * kMargin - kCaption) / size.y();
        height_ = 1.1 * scene_.width;
      }
      view_.ox = kMargin + (usable - size.x() * view_.scale) / 2 - view_.scale * low.x();
      view_.oy = kMargin + kCaption + view_.scale * high.y();
    }
  }

  void Hatching(Svg& svg, const Vec& from, const Vec& to, const Vec& side) const {
    const Vec t = (to - from).normalized();
    const double length = (to - from).norm();
    std::string d;
    for (double s = 2; s <= length; s += kHatch) {
      const Vec a = from + s * t, b = a + kHatch * side - 0.8 * kHatch * t;
      d.append("M").append(Num(a.x())).append(",").append(Num(a.y())).append("L").append(Num(b.x())).append(",").append(Num(b.y()));
    }
    svg.PathData(d, {{"class", "hatch"}});
  }

  // A guide on the frame in px: the ends of its slide line, and the side of its hatching (below
  // a level guide).
  std::tuple<Vec, Vec, Vec> FrameGuide(int j) const {
    const auto [a, b] = GuideEnds(j);
    const Vec pa = view_(a), pb = view_(b);
    const Vec t = (pb - pa).normalized();
    Vec side(-t.y(), t.x());
    if (side.y() < 0 || (side.y() == 0 && side.x() < 0)) side = -side;
    return {pa, pb, side};
  }

  void Frame(Svg& svg) const {
    svg.OpenGroup({{"class", "frame"}});
    for (size_t j = 0; j < m_.joints.size(); ++j) {
      const Joint& joint = m_.joints[j];
      const bool a_frame = m_.links[joint.link_a].is_frame, b_frame = m_.links[joint.link_b].is_frame;
      if (!a_frame && !b_frame) continue;
      if (joint.type == JointType::kRevolute) {
        // pivot: a triangle standing on a hatched ground line
        const Vec c = view_(Global(a_frame ? PointRef{joint.link_a, joint.point_a} : PointRef{joint.link_b, joint.point_b}, scene_.q));
        const Vec l = c + Vec(-kPivotHalfWidth, kPivotHeight), r = c + Vec(kPivotHalfWidth, kPivotHeight);
        svg.Polygon({c, l, r}, {{"class", "pivot"}, {"fill", "#fff"}, {"stroke", kInk}, {"stroke-width", "1.4"}});
        const Vec g1 = l - Vec(5, 0), g2 = r + Vec(5, 0);
        svg.Line(g1, g2, {{"stroke", kInk}, {"stroke-width", "1.6"}});
        Hatching(svg, g1, g2, Vec(0, 1));
      } else if (a_frame) {
        // a guide on the frame: the line the block slides on, hatched on one side
        const auto [pa, pb, side] = FrameGuide(static_cast<int>(j));
        const Vec offset = side * (kBlockWidth / 2);
        svg.Line(pa + offset, pb + offset, {{"class", "guide"}, {"stroke", kInk}, {"stroke-width", "1.6"}});
        Hatching(svg, pa + offset, pb + offset, side);
        // the slide line itself, through the blocks' centres and the frame's points on it
        svg.Line(pa, pb, {{"class", "guide-axis"}, {"data-joint", joint.name}});
      }
    }
    for (const PointLabel& l : labels_.front())
      if (l.needs_mark && m_.links[l.ref.link].is_frame)
        svg.Circle(l.anchor, kMarkRadius, {{"class", "point-mark"}, {"data-point", l.name}, {"fill", kInk}});
    DriveArrow(svg);
    svg.CloseGroup();
  }

  std::string DriveLetter() const { return m_.drive.input_name == "phi" ? "φ" : m_.drive.input_name; }
  // The baseline of the input's name beside the drive arrow about the pivot at c (px), centred.
  static Vec DriveLetterAt(const Vec& c) {
    return c + (kArrowRadius + 12) * Vec(std::cos(DegToRad(200)), -std::sin(DegToRad(200))) + Vec(0, 4);
  }

  void DriveArrow(Svg& svg) const {
    const Joint& drive = m_.joints[m_.drive.joint];
    const bool a_frame = m_.links[drive.link_a].is_frame;
    if (!a_frame && !m_.links[drive.link_b].is_frame) return;  // a drive between moving links: no arrow
    if (drive.type == JointType::kRevolute) {
      const Vec c = view_(Global(a_frame ? PointRef{drive.link_a, drive.point_a} : PointRef{drive.link_b, drive.point_b}, scene_.q));
      // world angles 150..250 deg: left of the pivot, clear of the ground symbol; counter-clockwise
      const double a0 = DegToRad(150), a1 = DegToRad(250);
      const Vec p0 = c + kArrowRadius * Vec(std::cos(a0), -std::sin(a0)), p1 = c + kArrowRadius * Vec(std::cos(a1), -std::sin(a1));
      svg.PathData("M" + Num(p0.x()) + "," + Num(p0.y()) + " A" + Num(kArrowRadius) + "," + Num(kArrowRadius) + " 0 0 0 " +
                       Num(p1.x()) + "," + Num(p1.y()),
                   {{"class", "drive-arrow"}, {"fill", "none"}, {"stroke", kInk}, {"stroke-width", "1.4"}});
      const Vec t(-std::sin(a1), -std::cos(a1)), n(-t.y(), t.x());
      svg.Polygon({p1 + 2 * t, p1 - 7 * t + 3.5 * n, p1 - 7 * t - 3.5 * n}, {{"class", "drive-arrow-head"}, {"fill", kInk}});
      svg.Text(DriveLetterAt(c), DriveLetter(), {{"text-anchor", "middle"}});
    } else {
      const auto [a, b] = GuideEnds(m_.drive.joint);
      const Vec pa = view_(a), pb = view_(b), t = (pb - pa).normalized();
      Vec side(-t.y(), t.x());
      if (side.y() > 0 || (side.y() == 0 && side.x() > 0)) side = -side;  // opposite the hatching
      const Vec mid = 0.5 * (pa + pb) + side * (kBlockWidth / 2 + 14), from = mid - 20 * t, to = mid + 20 * t;
      svg.Line(from, to, {{"class", "drive-arrow"}, {"stroke", kInk}, {"stroke-width", "1.4"}});
      const Vec n(-t.y(), t.x());
      svg.Polygon({to + 2 * t, to - 7 * t + 3.5 * n, to - 7 * t - 3.5 * n}, {{"class", "drive-arrow-head"}, {"fill", kInk}});
    }
  }

  void MovingLink(Svg& svg, int l, bool joints_pass) const {
    const Link& link = m_.links[l];
    const double u = 1 / view_.scale;  // one px in body units
    Attrs group = {{"class", joints_pass ? "joints" : "link"}, {"data-link", link.name},
                   {"transform", Transform(view_, PoseOf(system_, l, scene_.q))}};
    if (scene_.animatable) group.push_back({"data-coord", std::to_string(system_.CoordinateOf(l))});
    svg.OpenGroup(group);
    const Attrs thin = {{"vector-effect", "non-scaling-stroke"}, {"stroke", kInk}, {"stroke-width", "1.4"}};
    auto with = [&](Attrs a, const Attrs& more) {
      a.insert(a.end(), more.begin(), more.end());
      return a;
    };
    if (joints_pass) {
      for (const Joint& joint : m_.joints) {
        if (joint.type != JointType::kRevolute) continue;
        // the circle rides on link_b, or on link_a when link_b is the frame
        const int carrier = m_.links[joint.link_b].is_frame ? joint.link_a : joint.link_b;
        if (carrier != l) continue;
        const Vec p = link.points[carrier == joint.link_b ? joint.point_b : joint.point_a].local;
        svg.Circle(p, kJointRadius * u, with(thin, {{"class", "joint"}, {"data-joint", joint.name}, {"fill", "#fff"}}));
      }
      for (const PointLabel& label : labels_.front())
        if (label.needs_mark && label.ref.link == l)
          svg.Circle(link.points[label.ref.point].local, kMarkRadius * u, {{"class", "point-mark"}, {"data-point", label.name}, {"fill", kInk}});
      svg.CloseGroup();
      return;
    }
    // slots: this link guides a block
    for (size_t j = 0; j < m_.joints.size(); ++j)
      if (m_.joints[j].type == JointType::kPrismatic && m_.joints[j].link_a == l) {
        const auto [a, b] = GuideEnds(static_cast<int>(j));
        svg.Line(a, b, {{"class", "slot"}, {"vector-effect", "non-scaling-stroke"}, {"stroke", kInk}, {"stroke-width", "11"},
                        {"stroke-linecap", "round"}});
        svg.Line(a, b, {{"vector-effect", "non-scaling-stroke"}, {"stroke", "#fff"}, {"stroke-width", "8"}, {"stroke-linecap", "round"}});
      }
    // the body: a bar between two points, a polygon around three or more
    std::vector<Vec> points;
    for (const NamedPoint& p : link.points) points.push_back(p.local);
    const std::vector<Vec> hull = ConvexHull(points);
    if (hull.size() >= 3) {
      svg.Polygon(hull, with(thin, {{"class", "body polygon"}, {"fill", kLinkFill}, {"stroke-linejoin", "round"}}));
    } else if (hull.size() == 2) {
      svg.Line(hull[0], hull[1], {{"class", "body bar"}, {"vector-effect", "non-scaling-stroke"}, {"stroke", kInk}, {"stroke-width", "7"},
                                  {"stroke-linecap", "round"}});
      svg.Line(hull[0], hull[1], {{"vector-effect", "non-scaling-stroke"}, {"stroke", kLinkFill}, {"stroke-width", "4.2"},
                                  {"stroke-linecap", "round"}});
    }
    // blocks: this link slides on a guide
    for (const Joint& joint : m_.joints)
      if (joint.type == JointType::kPrismatic && joint.link_b == l) {
        const Vec c = link.points[joint.point_b].local;
        const Vec along = Eigen::Rotation2Dd(-joint.angle) * joint.axis, across(-along.y(), along.x());
        const Vec h = 0.5 * kBlockLength * u * along, w = 0.5 * kBlockWidth * u * across;
        svg.Polygon({c - h - w, c + h - w, c + h + w, c - h + w}, with(thin, {{"class", "block"}, {"data-joint", joint.name}, {"fill", "#f2f2f2"}}));
      }
    svg.CloseGroup();
  }

  // One label per point name, at the frame's point if the frame has it; overlays label the
  // moving points only (a frame pivot does not move).
  std::vector<PointLabel> LabelledPoints(const Eigen::VectorXd& q, const std::string& suffix) const {
    std::map<std::string, PointRef> chosen;
    for (int l = 0; l < static_cast<int>(m_.links.size()); ++l) {
      if (!suffix.empty() && m_.links[l].is_frame) continue;
      for (int i = 0; i < static_cast<int>(m_.links[l].points.size()); ++i) {
        const std::string& name = m_.links[l].points[i].name;
        const auto it = chosen.find(name);
        if (it == chosen.end() || (m_.links[l].is_frame && !m_.links[it->second.link].is_frame)) chosen[name] = {l, i};
      }
    }
    const int frame = m_.FrameLink();
    std::vector<PointLabel> labels;
    for (const auto& [name, ref] : chosen) {
      if (!suffix.empty() && m_.links[frame].FindPoint(name) >= 0) continue;
      PointLabel label;
      label.name = name;
      label.text = suffix.empty() ? name : name + "_" + suffix;
      label.ref = ref;
      label.anchor = view_(Global(ref, q));
      label.needs_mark = !HasSymbolAt(Global(ref, q), q);
      labels.push_back(label);
    }
    return labels;
  }

  // A joint circle or a block is drawn at this point of pose q.
  bool HasSymbolAt(const Vec& world, const Eigen::VectorXd& q) const {
    const double close = 0.5 / view_.scale;  // half a px
    for (const Joint& joint : m_.joints) {
      const PointRef at = joint.type == JointType::kRevolute ? PointRef{joint.link_a, joint.point_a} : PointRef{joint.link_b, joint.point_b};
      if ((Global(at, q) - world).norm() < close) return true;
    }
    return false;
  }

  // Every label of the picture placed at once, the pose drawn first (it gets the better places).
  void PlaceAllLabels() {
    labels_ = {LabelledPoints(scene_.q, "")};
    for (const OverlayPose& o : scene_.overlays) labels_.push_back(LabelledPoints(o.q, o.suffix));
    std::vector<LabelRequest> requests;
    for (size_t set = 0; set < labels_.size(); ++set)
      for (const PointLabel& l : labels_[set]) requests.push_back({l.text, l.anchor, set == 0 ? kLabelFont : kOverlayLabelFont});
    // the page moves the labels with their links: there they keep the nearest ring (no leaders)
    const std::vector<PlacedLabel> placed = PlaceLabels(requests, LabelObstacles(scene_.animatable ? 1 : 6));
    size_t next = 0;
    for (auto& set : labels_)
      for (PointLabel& l : set) l.placed = placed[next++];
  }

  // What the labels must not cover (symbols, the caption) and should not cross (links, guides).
  LabelScene LabelObstacles(int rings) const {
    LabelScene ls;
    ls.rings = rings;
    ls.area = {0, 0, scene_.width, height_};
    ls.symbols.push_back(TextBox(scene_.caption, kCaptionFont, {kMargin / 2, 17}));
    auto square = [&](const Vec& c, double r) { ls.symbols.push_back({c.x() - r, c.y() - r, c.x() + r, c.y() + r}); };
    std::vector<const Eigen::VectorXd*> poses = {&scene_.q};
    for (const OverlayPose& o : scene_.overlays) poses.push_back(&o.q);
    for (size_t k = 0; k < poses.size(); ++k) {
      const Eigen::VectorXd& q = *poses[k];
      for (const Joint& joint : m_.joints) {
        if (joint.type == JointType::kRevolute) square(view_(Global({joint.link_a, joint.point_a}, q)), k == 0 ? kJointRadius + 1 : 4);
        else if (k == 0) ls.symbols.push_back(BlockBox(joint, q));
      }
      for (int l = 0; l < static_cast<int>(m_.links.size()); ++l) {
        if (m_.links[l].is_frame) continue;
        std::vector<Vec> points;
        for (int i = 0; i < static_cast<int>(m_.links[l].points.size()); ++i) points.push_back(view_(Global({l, i}, q)));
        const std::vector<Vec> hull = ConvexHull(points);
        for (size_t i = 0; hull.size() >= 2 && i < hull.size(); ++i) ls.lines.push_back({hull[i], hull[(i + 1) % hull.size()]});
      }
    }
    for (const auto& set : labels_)
      for (const PointLabel& l : set)
        if (l.needs_mark) square(l.anchor, kMarkRadius + 1);
    for (const auto& run : scene_.trace)
      for (size_t i = 1; i < run.size(); ++i) ls.lines.push_back({view_(run[i - 1]), view_(run[i])});
    FrameObstacles(ls);
    return ls;
  }

  // The px box around a slider's block as MovingLink draws it.
  LabelBox BlockBox(const Joint& joint, const Eigen::VectorXd& q) const {
    const LinkPose pose = PoseOf(system_, joint.link_b, q);
    const Vec along = Eigen::Rotation2Dd(pose.theta - joint.angle) * joint.axis, across(-along.y(), along.x());
    const Vec c = view_(Global({joint.link_b, joint.point_b}, q));
    const Vec h = 0.5 * kBlockLength * Vec(along.x(), -along.y()), w = 0.5 * kBlockWidth * Vec(across.x(), -across.y());
    const Vec extent = h.cwiseAbs() + w.cwiseAbs() + Vec::Constant(1);
    return {c.x() - extent.x(), c.y() - extent.y(), c.x() + extent.x(), c.y() + extent.y()};
  }

  // The pivots, the drive arrow with its letter, and the guides on the frame.
  void FrameObstacles(LabelScene& ls) const {
    for (size_t j = 0; j < m_.joints.size(); ++j) {
      const Joint& joint = m_.joints[j];
      const bool a_frame = m_.links[joint.link_a].is_frame;
      if (!a_frame && !m_.links[joint.link_b].is_frame) continue;
      if (joint.type == JointType::kRevolute) {
        const Vec c = view_(Global(a_frame ? PointRef{joint.link_a, joint.point_a} : PointRef{joint.link_b, joint.point_b}, scene_.q));
        ls.symbols.push_back({c.x() - kPivotHalfWidth - 6, c.y() + kJointRadius, c.x() + kPivotHalfWidth + 6, c.y() + kPivotHeight + kHatch + 1});
        if (static_cast<int>(j) == m_.drive.joint) {  // the arc 150..250 deg and its letter (DriveArrow)
          ls.symbols.push_back({c.x() - kArrowRadius - 2, c.y() - 0.5 * kArrowRadius - 2, c.x() - 8, c.y() + kArrowRadius});
          LabelBox letter = TextBox(DriveLetter(), kLabelFont, DriveLetterAt(c));
          const double half = 0.5 * (letter.right - letter.left);  // written centred
          letter.left -= half, letter.right -= half;
          ls.symbols.push_back(letter);
        }
      } else if (a_frame) {
        // the slide line may be crossed; the guide with its hatching may not be covered
        const auto [pa, pb, side] = FrameGuide(static_cast<int>(j));
        ls.lines.push_back({pa, pb});
        const Vec strip = side * (kBlockWidth / 2 + kHatch / 2), t = (pb - pa).normalized();
        for (double s = 0; s <= (pb - pa).norm(); s += kHatch) {
          const Vec c = pa + strip + s * t;
          ls.symbols.push_back({c.x() - kHatch / 2 - 1, c.y() - kHatch / 2 - 1, c.x() + kHatch / 2 + 1, c.y() + kHatch / 2 + 1});
        }
      }
    }
  }

  // A label and, where it had to move away from its point, a leader line back to it.
  void Labels(Svg& svg, const std::vector<PointLabel>& labels, bool overlay) const {
    svg.OpenGroup({{"class", overlay ? "overlay-labels" : "labels"}});
    for (const PointLabel& l : labels) {
      if (l.placed.leader) {
        const Vec end = l.placed.ink.Nearest(l.anchor), towards = (end - l.anchor).normalized();
        svg.Line(l.anchor + (kJointRadius + 1) * towards, end, {{"class", "leader"}, {"data-point", l.name}});
      }
      Attrs attrs = {{"class", "label"}, {"data-point", l.name}, {"data-x", Num(l.anchor.x())}, {"data-y", Num(l.anchor.y())}};
      if (scene_.animatable && !overlay && !m_.links[l.ref.link].is_frame) {
        const Vec local = m_.links[l.ref.link].points[l.ref.point].local, offset = l.placed.baseline - l.anchor;
        attrs.insert(attrs.end(), {{"data-coord", std::to_string(system_.CoordinateOf(l.ref.link))},
                                   {"data-px", Num(local.x(), 9)}, {"data-py", Num(local.y(), 9)},
                                   {"data-dx", Num(offset.x())}, {"data-dy", Num(offset.y())}});
      }
      svg.Text(l.placed.baseline, l.text, attrs);
    }
    svg.CloseGroup();
  }

  // Another pose, faint: the links as thin lines, the joints as small circles, the other labelled
  // points as dots (its labels, with a suffix, are drawn with the others).
  void Overlay(Svg& svg, const OverlayPose& o, const std::vector<PointLabel>& labels) const {
    svg.OpenGroup({{"class", "overlay"}, {"data-suffix", o.suffix}, {"stroke", "#8a8a8a"}, {"stroke-dasharray", "5 3"}, {"fill", "none"}});
    for (int l = 0; l < static_cast<int>(m_.links.size()); ++l) {
      if (m_.links[l].is_frame) continue;
      std::vector<Vec> points;
      for (int i = 0; i < static_cast<int>(m_.links[l].points.size()); ++i) points.push_back(view_(Global({l, i}, o.q)));
      const std::vector<Vec> hull = ConvexHull(points);
      if (hull.size() >= 2) svg.Polygon(hull, {{"stroke-width", "1.5"}});
    }
    for (const Joint& joint : m_.joints)
      if (joint.type == JointType::kRevolute)
        svg.Circle(view_(Global({joint.link_a, joint.point_a}, o.q)), 3, {{"fill", "#fff"}, {"stroke-dasharray", "none"}});
    for (const PointLabel& l : labels)
      if (l.needs_mark)
        svg.Circle(l.anchor, kMarkRadius, {{"class", "point-mark"}, {"data-point", l.name}, {"fill", "#8a8a8a"}, {"stroke", "none"}});
    svg.CloseGroup();
  }

  const Mechanism& m_;
  const SchemeScene& scene_;
  ConstraintSystem system_;
  std::vector<std::pair<double, double>> travel_;
  View view_;
  double height_ = 0;
  std::vector<std::vector<PointLabel>> labels_;  // [0] the pose drawn, [1 + i] overlay i
};

}  // namespace

std::string DrawScheme(const Mechanism& mechanism, const SchemeScene& scene) { return SchemeWriter(mechanism, scene).Write(); }

}  // namespace koppel::plot
