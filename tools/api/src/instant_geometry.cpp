// Model::Curvature, Poles and Centrodes: the analysis library's instantaneous geometry in the
// API's units.
#include "koppel/api/model.hpp"

#include "display.hpp"

#include "koppel/analysis/curvature.hpp"
#include "koppel/analysis/instant_centres.hpp"
#include "koppel/core/limits.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace koppel {

using namespace api_detail;

namespace {

Point2 P(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }

double CheckedInput(const Model& model, double input) {
  if (!std::isfinite(input)) BadInput(model.path(), "input", "the input is not a finite number");
  return InputInternal(model.mechanism(), input);
}

}  // namespace

std::string CurvatureReport::Brief() const {
  return std::string(ToString(status)) + " at " + std::to_string(input) + (message.empty() ? "" : "; " + message);
}
std::vector<NamedValue> CurvatureReport::Quantities() const {
  std::vector<NamedValue> q;
  auto add = [&](const std::string& name, std::optional<double> value, const std::string& unit) { q.push_back({name, value, unit}); };
  auto add_point = [&](const std::string& prefix, const std::optional<Point2>& p, const std::string& unit) {
    add(ComponentName(prefix, 0), p ? std::optional<double>(p->x) : std::nullopt, unit);
    add(ComponentName(prefix, 1), p ? std::optional<double>(p->y) : std::nullopt, unit);
  };
  add(input_name, input, input_unit);
  add_point(point, status == AnalysisStatus::kFailed ? std::nullopt : std::optional<Point2>(position), length_unit);
  add_point("pole", pole, length_unit);
  add_point("pole_direction", pole_direction, "1");
  add_point("inflection", inflection_centre, length_unit);
  add("inflection_diameter", inflection_diameter, length_unit);
  add_point("inflection_pole", inflection_pole, length_unit);
  add_point("ball", ball_point, length_unit);
  add("curvature", curvature, "1/" + length_unit);
  add("rho", rho, length_unit);
  add_point("centre", centre, length_unit);
  return q;
}

std::string PolesReport::Brief() const {
  return std::string(ToString(status)) + ": " + std::to_string(centres.size()) + " instant centres" + (message.empty() ? "" : "; " + message);
}
std::string CentrodesReport::Brief() const {
  return std::string(ToString(status)) + ": " + std::to_string(inputs.size()) + " points" + (message.empty() ? "" : "; " + message);
}

CurvatureReport Model::Curvature(const std::string& point, double input) const {
  const Mechanism& m = mechanism();
  const Expected<PointRef> ref = FindPointByText(m, point);
  if (!ref) BadInput(path(), "point", ref.error());
  const CurvatureResult r = CurvatureAtInput(m, *ref, CheckedInput(*this, input));
  CurvatureReport out;
  out.status = r.status;
  out.message = r.message;
  out.input = input;
  out.input_name = input_name();
  out.length_unit = length_unit();
  out.input_unit = input_is_angle() ? "deg" : out.length_unit;
  out.point = point;
  out.link = m.links[ref->link].name;
  if (r.status == AnalysisStatus::kFailed) return out;
  out.position = P(r.point);
  if (r.has_pole) {
    out.pole = P(r.pole);
    if (r.has_pole_tangent) out.pole_direction = P(r.pole_velocity.normalized());
    out.inflection_centre = P(r.inflection_centre);
    out.inflection_pole = P(r.inflection_pole);
    out.inflection_diameter = r.inflection_diameter;
    if (r.has_ball_point) out.ball_point = P(r.ball_point);
  }
  if (r.has_curvature) {
    out.curvature = r.curvature;
    if (r.rho_finite) {
      out.rho = r.rho;
      out.centre = P(r.centre);
    }
  }
  return out;
}

PolesReport Model::Poles(double input) const {
  const Mechanism& m = mechanism();
  const InstantCentresResult r = InstantCentresAtInput(m, CheckedInput(*this, input));
  PolesReport out;
  out.status = r.status;
  out.message = r.message;
  out.input = input;
  for (const InstantCentre& c : r.centres) {
    InstantCentreEntry e;
    e.link_a = m.links[c.link_a].name;
    e.link_b = m.links[c.link_b].name;
    e.defined = c.defined;
    e.at_infinity = c.at_infinity;
    e.from_acceleration = c.from_acceleration;
    e.position = P(c.position);
    e.direction = P(c.direction);
    out.centres.push_back(e);
  }
  return out;
}

CentrodesReport Model::Centrodes(const std::string& link, const std::string& reference, double from, double to, double step, double at) const {
  const Mechanism& m = mechanism();
  const int moving = m.FindLink(link);
  if (moving < 0) BadInput(path(), "link", "the mechanism has no link '" + link + "'");
  const int fixed = reference.empty() ? m.FrameLink() : m.FindLink(reference);
  if (fixed < 0) BadInput(path(), "reference", "the mechanism has no link '" + reference + "'");
  if (fixed == moving) BadInput(path(), "reference", "a link has no centrode against itself");
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step) || step == 0 || !std::isfinite(at))
    BadInput(path(), "from/to/step/at", "the range needs finite from, to, at and a step that is not 0");
  if (SampleCount(from, to, step) > static_cast<double>(kMaxSweepSamples))
    BadInput(path(), "from/to/step", "more than kMaxSweepSamples (" + std::to_string(kMaxSweepSamples) + ") samples");
  const long n = static_cast<long>(SampleCount(from, to, step));
  const double signed_step = to >= from ? std::abs(step) : -std::abs(step);
  std::vector<double> inputs;
  for (long i = 0; i < n; ++i) inputs.push_back(InputInternal(m, from + i * signed_step));
  const koppel::Centrodes traced = TraceCentrodes(m, moving, fixed, inputs);
  CentrodesReport out;
  out.status = traced.status;
  out.message = traced.message;
  out.link = m.links[moving].name;
  out.reference = m.links[fixed].name;
  // the moving link's pose against the reference at `at`, to carry the moving centrode there
  const koppel::Centrodes pose = TraceCentrodes(m, moving, fixed, {InputInternal(m, at)});
  const bool carried = Usable(pose.status);
  for (const CentrodePoint& p : traced.points) {
    out.inputs.push_back(InputShown(m, p.input));
    out.fixed.push_back(p.finite ? std::optional<Point2>(P(p.fixed)) : std::nullopt);
    out.moving.push_back(p.finite ? std::optional<Point2>(P(p.moving)) : std::nullopt);
    if (p.finite && carried) {
      const CentrodePoint& at_pose = pose.points[0];
      out.moving_at.push_back(P(at_pose.link_origin + Eigen::Rotation2Dd(at_pose.link_angle) * p.moving));
    } else {
      out.moving_at.push_back(std::nullopt);
    }
  }
  if (!carried) out.message += std::string(out.message.empty() ? "" : "; ") + "the pose at " + std::to_string(at) + " was not reached: " + pose.message;
  return out;
}

}  // namespace koppel
