// Draws the frames of an AnimationScene with cairo into an RGB image surface: one view that fits
// every frame (to scale, y up), the same in each frame so that only the mechanism moves.
#pragma once

#include "koppel/plot/animation.hpp"

#include <cairo.h>

namespace koppel::plot {

class FramePainter {
 public:
  // Fits the view to every frame's parts and the whole curves. Throws std::runtime_error when
  // cairo cannot make the surface.
  FramePainter(const AnimationScene& scene, int width, int height);
  ~FramePainter();
  FramePainter(const FramePainter&) = delete;
  FramePainter& operator=(const FramePainter&) = delete;

  // Draws frame `index`; the pixels are then in surface() (CAIRO_FORMAT_RGB24, flushed).
  void Paint(int index);
  cairo_surface_t* surface() const { return surface_; }

 private:
  void FitView();
  void MoveTo(const Eigen::Vector2d& world) const;
  void LineTo(const Eigen::Vector2d& world) const;
  void ContourPath(const Contour& contour) const;
  void Pivot(const Hole& hole) const;
  void FrameSlots(const Part& part) const;
  void MovingPart(const Part& part) const;
  void Curves(double up_to) const;

  const AnimationScene& scene_;
  int width_, height_;
  double px_ = 1;  // one line width unit: 1 px at 480 px, more for bigger pictures
  double scale_ = 1, ox_ = 0, oy_ = 0;  // device = (ox + scale x, oy - scale y)
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace koppel::plot
