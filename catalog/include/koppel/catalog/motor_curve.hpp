// A motor characteristic file of `koppel simulate --motor FILE`: one `speed,torque` line per
// point (speeds ascending), a first line that starts with a letter is a header, lines starting
// with '#' are comments; each value is a number or a formula ("1500", "2*pi"). Every bad line is
// reported (InputError with file:line:column, mechanism_file.hpp), at most 20 of them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace koppel {

// In the file's units: speeds in rpm (length units/s for a P drive), torques in N m (N).
struct MotorCurveFile {
  std::vector<double> speeds, torques;
};

// At most this many points: far beyond any measured characteristic.
inline constexpr std::size_t kMaxMotorCurvePoints = 100'000;

// Reads the file within kMaxInputBytes (koppel/core/input_file.hpp). Throws InputError.
MotorCurveFile ReadMotorCurve(const std::string& path);
// The same for the text of a file named `path`.
MotorCurveFile ParseMotorCurveText(const std::string& text, const std::string& path);

}  // namespace koppel
