#include "frame_painter.hpp"

#include "koppel/core/angles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace koppel::plot {
namespace {

using Vec = Eigen::Vector2d;

struct Rgb {
  double r, g, b;
};
// the colours of the SVG scheme (scheme.cpp): ink, link fill, trace; a light grey frame
constexpr Rgb kInk{0x1d / 255.0, 0x2b / 255.0, 0x3a / 255.0};
constexpr Rgb kLinkFill{0xd3 / 255.0, 0xe2 / 255.0, 0xf1 / 255.0};
constexpr Rgb kTrace{0xc0 / 255.0, 0x39 / 255.0, 0x2b / 255.0};
constexpr Rgb kFrameFill{0xe6 / 255.0, 0xe6 / 255.0, 0xe6 / 255.0};
constexpr Rgb kWhite{1, 1, 1};

// Sizes in px at a 480 px picture (scaled with it): the margin, the caption's line, the ground
// symbol under a frame pivot.
constexpr double kMargin = 18, kCaption = 22, kFontSize = 13, kPivotHeight = 13, kPivotHalfWidth = 9, kHatch = 5;
constexpr double kReferenceSide = 480;

void SetColour(cairo_t* cr, const Rgb& c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

}  // namespace

FramePainter::FramePainter(const AnimationScene& scene, int width, int height) : scene_(scene), width_(width), height_(height) {
  surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cairo cannot make a " + std::to_string(width) + "x" + std::to_string(height) + " picture");
  }
  cr_ = cairo_create(surface_);
  px_ = std::max(1.0, std::min(width, height) / kReferenceSide);
  FitView();
}

FramePainter::~FramePainter() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void FramePainter::FitView() {
  Vec low = Vec::Constant(std::numeric_limits<double>::infinity()), high = -low;
  auto add = [&](const Vec& p, double r) {
    low = low.cwiseMin(p - Vec::Constant(r));
    high = high.cwiseMax(p + Vec::Constant(r));
  };
  auto add_contour = [&](const Contour& c) {
    for (const Arc& a : c.arcs) add(a.centre, a.radius);
  };
  for (const AnimationFrame& f : scene_.frames)
    for (const Part& p : f.parts) {
      add_contour(p.outline);
      for (const Hole& h : p.holes) add(h.centre, h.diameter / 2);
      for (const Slot& s : p.slots) add_contour(s.outline);
    }
  for (const TracedCurve& c : scene_.curves)
    for (const auto& run : c.runs)
      for (const Vec& p : run) add(p, 0);
  const Vec size = (high - low).cwiseMax(Vec::Constant(1e-12 * std::max(1.0, high.cwiseAbs().maxCoeff())));
  // room for the ground symbols below the pivots and the caption above
  const double usable_x = width_ - 2 * kMargin * px_, usable_y = height_ - (2 * kMargin + kCaption + kPivotHeight) * px_;
  scale_ = std::max(1e-300, std::min(usable_x / size.x(), usable_y / size.y()));
  ox_ = width_ / 2.0 - scale_ * (low.x() + high.x()) / 2;
  oy_ = (kMargin + kCaption) * px_ + usable_y / 2 + scale_ * (low.y() + high.y()) / 2;
}

void FramePainter::MoveTo(const Vec& w) const { cairo_move_to(cr_, ox_ + scale_ * w.x(), oy_ - scale_ * w.y()); }
void FramePainter::LineTo(const Vec& w) const { cairo_line_to(cr_, ox_ + scale_ * w.x(), oy_ - scale_ * w.y()); }

// The contour's path in device space: built in world coordinates (y up), kept after the
// transform is undone, so that line widths stay in px.
void FramePainter::ContourPath(const Contour& contour) const {
  cairo_save(cr_);
  cairo_translate(cr_, ox_, oy_);
  cairo_scale(cr_, scale_, -scale_);
  cairo_new_sub_path(cr_);
  for (const Arc& a : contour.arcs) cairo_arc(cr_, a.centre.x(), a.centre.y(), a.radius, a.start, a.start + a.sweep);
  cairo_close_path(cr_);
  cairo_restore(cr_);
}

void FramePainter::Pivot(const Hole& hole) const {
  const double x = ox_ + scale_ * hole.centre.x(), y = oy_ - scale_ * hole.centre.y();
  // standing out below the pin's hole however large the parts are drawn
  const double h = std::max(kPivotHeight * px_, 2.2 * scale_ * hole.diameter / 2), b = h * kPivotHalfWidth / kPivotHeight;
  cairo_move_to(cr_, x, y);
  cairo_line_to(cr_, x - b, y + h);
  cairo_line_to(cr_, x + b, y + h);
  cairo_close_path(cr_);
  SetColour(cr_, kFrameFill);
  cairo_fill_preserve(cr_);
  SetColour(cr_, kInk);
  cairo_set_line_width(cr_, 1.4 * px_);
  cairo_stroke(cr_);
  // the ground: a line under the triangle, hatched below it
  const double g = b + 5 * px_;
  cairo_move_to(cr_, x - g, y + h);
  cairo_line_to(cr_, x + g, y + h);
  for (double s = -g + 2 * px_; s <= g; s += kHatch * px_) {
    cairo_move_to(cr_, x + s, y + h);
    cairo_line_to(cr_, x + s - 0.8 * kHatch * px_, y + h + kHatch * px_);
  }
  cairo_set_line_width(cr_, 1.0 * px_);
  cairo_stroke(cr_);
}

void FramePainter::FrameSlots(const Part& part) const {
  for (const Slot& s : part.slots) {
    ContourPath(s.outline);
    SetColour(cr_, kFrameFill);
    cairo_fill_preserve(cr_);
    SetColour(cr_, kInk);
    cairo_set_line_width(cr_, 1.4 * px_);
    cairo_stroke(cr_);
  }
}

void FramePainter::MovingPart(const Part& part) const {
  cairo_set_line_width(cr_, 1.4 * px_);
  ContourPath(part.outline);
  SetColour(cr_, kLinkFill);
  cairo_fill_preserve(cr_);
  SetColour(cr_, kInk);
  cairo_stroke(cr_);
  for (const Slot& s : part.slots) {
    ContourPath(s.outline);
    SetColour(cr_, kWhite);
    cairo_fill_preserve(cr_);
    SetColour(cr_, kInk);
    cairo_stroke(cr_);
  }
  for (const auto& [name, p] : part.marks) {
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, ox_ + scale_ * p.x(), oy_ - scale_ * p.y(), 2.2 * px_, 0, 2 * kPi);
    SetColour(cr_, kInk);
    cairo_fill(cr_);
  }
}

void FramePainter::Curves(double up_to) const {
  cairo_save(cr_);  // the round joins are the curves' own: every frame starts from the same state
  for (const TracedCurve& c : scene_.curves)
    for (const auto& run : c.UpTo(up_to)) {
      MoveTo(run[0]);
      for (size_t i = 1; i < run.size(); ++i) LineTo(run[i]);
    }
  SetColour(cr_, kTrace);
  cairo_set_line_width(cr_, 1.6 * px_);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void FramePainter::Paint(int index) {
  const AnimationFrame& frame = scene_.frames.at(index);
  SetColour(cr_, kWhite);
  cairo_paint(cr_);
  // the frame's guides under the links, its pivots' bearing blocks over them, holding the pins
  for (const Part& p : frame.parts)
    if (p.frame) FrameSlots(p);
  for (const Part& p : frame.parts)
    if (!p.frame) MovingPart(p);
  for (const Part& p : frame.parts)
    if (p.frame)
      for (const Hole& h : p.holes) Pivot(h);
  // holes last, over every plate: a hole on one link shows the pin through the other
  for (const Part& p : frame.parts)
    for (const Hole& h : p.holes) {
      cairo_new_sub_path(cr_);
      cairo_arc(cr_, ox_ + scale_ * h.centre.x(), oy_ - scale_ * h.centre.y(), scale_ * h.diameter / 2, 0, 2 * kPi);
      SetColour(cr_, kWhite);
      cairo_fill_preserve(cr_);
      SetColour(cr_, kInk);
      cairo_set_line_width(cr_, 1.4 * px_);
      cairo_stroke(cr_);
    }
  Curves(frame.traced_up_to);
  cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, kFontSize * px_);
  SetColour(cr_, kInk);
  cairo_move_to(cr_, kMargin * px_, (kMargin + kFontSize * 0.4) * px_);
  cairo_show_text(cr_, frame.caption.c_str());
  cairo_surface_flush(surface_);
}

}  // namespace koppel::plot
