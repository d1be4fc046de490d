#include "plot_support.hpp"

#include "koppel/core/angles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace koppel::plot {

double ShownInput(const Mechanism& m, double input) { return m.InputIsAngle() ? RadToDeg(input) : input; }

std::string InputName(const Mechanism& m) { return m.drive.input_name == "phi" ? "φ" : m.drive.input_name; }

std::string InputLabel(const Mechanism& m, const std::string& length_unit) { return InputName(m) + " [" + (m.InputIsAngle() ? "deg" : length_unit) + "]"; }

std::string DerivativeLabel(const Mechanism& m, int output, const std::string& component, int k, const std::string& length_unit) {
  std::string name = m.outputs[output].name + component;
  if (name == "mu") name = "μ";
  if (name == "psi") name = "ψ";
  static const char* kPrimes[] = {"", "'", "''", "'''"};
  name += k <= 3 ? std::string(kPrimes[k]) : "^(" + std::to_string(k) + ")";
  const std::string in = m.InputIsAngle() ? "rad" : length_unit;
  const std::string out = m.OutputIsAngle(output) ? (k == 0 ? "deg" : "rad") : length_unit;
  if (k == 0) return name + " [" + out + "]";
  const std::string power = k == 1 ? "" : k == 2 ? "²" : k == 3 ? "³" : "^" + std::to_string(k);
  return name + " [" + out + "/" + in + power + "]";
}

double ShownOutput(const Mechanism& m, int output, int k, double value) {
  return k == 0 && m.OutputIsAngle(output) ? RadToDeg(value) : value;
}

std::vector<std::vector<Eigen::Vector2d>> InputRuns(const Mechanism& m, const SampledRun& run, int column, int output, int k) {
  std::vector<std::vector<Eigen::Vector2d>> runs;
  for (const Stretch& s : run.stretches) {
    runs.emplace_back();
    for (int i = s.begin; i < s.end; ++i)
      runs.back().emplace_back(ShownInput(m, run.inputs[i]), ShownOutput(m, output, k, run.outputs(i, column)));
  }
  return runs;
}

bool YRange(const std::vector<std::vector<Eigen::Vector2d>>& runs, double* low, double* high) {
  *low = std::numeric_limits<double>::infinity();
  *high = -*low;
  for (const auto& r : runs)
    for (const auto& p : r) {
      *low = std::min(*low, p.y());
      *high = std::max(*high, p.y());
    }
  return *low <= *high;
}

bool RangeIsValid(const SweepOptions& range, int max_samples, std::string* why) {
  if (!std::isfinite(range.from) || !std::isfinite(range.to) || !std::isfinite(range.step) || range.step == 0) {
    *why = "the input range needs finite from/to and a non-zero step";
    return false;
  }
  if (SampleCount(range.from, range.to, range.step) > max_samples) {
    char count[32];
    std::snprintf(count, sizeof count, "%.6g", SampleCount(range.from, range.to, range.step));
    *why = std::string("the input range (--from/--to/--step, else the file's sweep) asks for ") + count + " samples, more than " +
           std::to_string(max_samples - 1) + ": use a larger --step";
    return false;
  }
  return true;
}

void MarkGaps(const Mechanism& m, const SampledRun& run, Panel& panel, bool label) {
  for (const InputGap& g : run.gaps) {
    const double a = ShownInput(m, g.from), b = ShownInput(m, g.to);
    panel.shaded.emplace_back(std::min(a, b), std::max(a, b));
  }
  for (double s : run.singular) panel.rules.push_back({ShownInput(m, s), label ? "singular" : "", "singular"});
}

std::vector<Eigen::Vector2d> ConvexHull(std::vector<Eigen::Vector2d> p) {
  using Vec = Eigen::Vector2d;
  std::sort(p.begin(), p.end(), [](const Vec& a, const Vec& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end(), [](const Vec& a, const Vec& b) { return (a - b).norm() < 1e-12; }), p.end());
  if (p.size() < 3) return p;
  auto cross = [](const Vec& o, const Vec& a, const Vec& b) { return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x(); };
  std::vector<Vec> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// The template with {{NAME}} replaced in one pass (so a value never gets substituted into).
std::string Fill(const std::string& page, const std::vector<std::pair<std::string, std::string>>& values) {
  std::string out;
  size_t at = 0;
  while (true) {
    const size_t open = page.find("{{", at);
    if (open == std::string::npos) break;
    const size_t close = page.find("}}", open);
    if (close == std::string::npos) break;  // "{{" with no "}}": the rest as it is
    out += page.substr(at, open - at);
    const std::string key = page.substr(open + 2, close - open - 2);
    bool found = false;
    for (const auto& [name, value] : values)
      if (name == key) out += value, found = true;
    if (!found) out += "{{" + key + "}}";
    at = close + 2;
  }
  return out + page.substr(at);
}

// In JSON text <, > and & stand only inside strings, where \u003c, \u003e and \u0026 mean the
// same; U+2028 and U+2029 (bytes E2 80 A8/A9) likewise become \u2028 and \u2029.
std::string ScriptSafe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xE2' && i + 2 < json.size() && json[i + 1] == '\x80' && (json[i + 2] == '\xA8' || json[i + 2] == '\xA9')) {
      out += json[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace koppel::plot
