#include "koppel/api/coupler_curve.hpp"

#include "display.hpp"

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/core/angles.hpp"

#include <cmath>

namespace koppel {
namespace {

SweepOptions CurveSweepOf(const Model& model, const CouplerCurveRequest& request) {
  const Mechanism& m = model.mechanism();
  const SweepSpan span = model.Span(request.from, request.to, request.step);
  SweepOptions range;
  range.continuation.at_branch_point = request.at_branch_point;
  range.from = api_detail::InputInternal(m, span.from);
  range.to = api_detail::InputInternal(m, span.to);
  range.step = api_detail::InputInternal(m, span.step);
  return range;
}

Point2 ToPoint2(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }

}  // namespace

bool CouplerCurveRequest::IsValid(const Model& model, std::string* why) const { return CurveSweepOf(model, *this).IsValid(why); }

CouplerCurveTable TraceCouplerCurve(const Model& model, const CouplerCurveRequest& request) {
  const Mechanism& m = model.mechanism();
  const SweepOptions range = CurveSweepOf(model, request);
  if (std::string why; !range.IsValid(&why)) api_detail::BadInput(model.path(), "from/to/step", why);
  const CouplerCurve c = TraceCurve(m, request.point, range);
  CouplerCurveTable t;
  t.status = c.status;
  t.message = c.message;
  t.point = m.links[request.point.link].name + "." + m.links[request.point.link].points[request.point.point].name;
  for (size_t i = 0; i < c.inputs.size(); ++i) {
    t.inputs.push_back(api_detail::InputShown(m, c.inputs[i]));
    t.points.push_back(ToPoint2(c.points[i]));
    t.d1.push_back(ToPoint2(c.d1[i]));
    t.arc_length.push_back(c.arc_length[i]);
    t.curvature.push_back(c.curvature[i]);
    t.singular.push_back(c.singular[i] != 0);
  }
  t.sweep = api_detail::Shown(m, c.sweep);
  return t;
}

bool StraightStretchIsValid(double a, double e, std::string* why) { return StretchIsValid(DegToRad(a), DegToRad(e), why); }

bool StraightLineRequest::IsValid(const Model& model, std::string* why) const {
  std::string problem;
  if (!model.input_is_angle()) problem = "straight-line guidance needs a rotating drive (an R joint)";
  else if (!(resolution > 0)) problem = "the resolution must be positive";
  else if (stretch_a.has_value() != stretch_e.has_value()) problem = "a stretch needs both its ends";
  else if (stretch_a && !at) problem = "a stretch needs a reference point (at)";
  else if (stretch_a) StraightStretchIsValid(*stretch_a, *stretch_e, &problem);
  else if (!(qg > 0)) problem = "Q_G must be positive";
  if (why) *why = problem;
  return problem.empty();
}

StraightLine FindStraightLine(const Model& model, const StraightLineRequest& request) {
  if (std::string why; !request.IsValid(model, &why)) api_detail::BadInput(model.path(), "straight", why);
  const Mechanism& m = model.mechanism();
  ContinuationOptions continuation;
  continuation.at_branch_point = request.at_branch_point;
  const double resolution = DegToRad(request.resolution);
  std::optional<double> reference;
  if (request.at) reference = DegToRad(*request.at);
  const StraightStretch s =
      request.stretch_a
          ? StretchBand(m, request.point, *reference, DegToRad(*request.stretch_a), DegToRad(*request.stretch_e), resolution, continuation)
          : LongestStraightStretch(m, request.point, request.qg, reference, kPi, resolution, continuation);
  StraightLine r;
  r.status = s.status;
  r.message = s.message;
  r.reference = RadToDeg(s.reference);
  r.reference_point = ToPoint2(s.reference_point);
  r.tangent_angle = RadToDeg(std::atan2(s.tangent.y(), s.tangent.x()));
  r.phi_a = RadToDeg(s.phi_a);
  r.phi_e = RadToDeg(s.phi_e);
  r.phi_g = RadToDeg(s.phi_g);
  r.length = s.length;
  r.band = s.band;
  r.qg = s.qg;
  return r;
}

}  // namespace koppel
