// The points file of `koppel synth path` (POINTS.csv): the header `x,y`, then one point a line,
// in order along the path; or the header `x,y,phi` with each point's crank angle in degrees, from
// the frame line A0 -> B0, counter-clockwise positive, rising (or falling) from line to line;
// blank lines are skipped, a UTF-8 byte-order mark and CR line ends are
// allowed. Every bad line is reported (InputError with file:line:column, mechanism_file.hpp), at
// most 20 of them.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

struct TimedPathPoints {
  std::vector<Eigen::Vector2d> points;
  std::vector<double> phi;  // radians, one per point; empty without the phi column
};

// Reads the file within kMaxInputBytes (koppel/core/input_file.hpp). Throws InputError.
TimedPathPoints ReadTimedPathPoints(const std::string& path);
// The same for the text of a file named `path`.
TimedPathPoints ParseTimedPathPoints(const std::string& text, const std::string& path);

}  // namespace koppel
