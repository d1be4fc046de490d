// The points file of `koppel synth path` (POINTS.csv): the header `x,y`, then one point a line,
// in order along the path; blank lines are skipped, a UTF-8 byte-order mark and CR line ends are
// allowed. Every bad line is reported (InputError with file:line:column, mechanism_file.hpp), at
// most 20 of them.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

// Reads the file within kMaxInputBytes (koppel/core/input_file.hpp). Throws InputError.
std::vector<Eigen::Vector2d> ReadPathPoints(const std::string& path);
// The same for the text of a file named `path`.
std::vector<Eigen::Vector2d> ParsePathPoints(const std::string& text, const std::string& path);

}  // namespace koppel
