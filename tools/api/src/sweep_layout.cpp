#include "koppel/api/sweep_layout.hpp"

#include <utility>

namespace koppel {
namespace {

// The unit of the k-th derivative of an output.
std::string DerivativeUnit(bool output_is_angle, bool input_is_angle, int k, const std::string& length) {
  if (k == 0) return output_is_angle ? "deg" : length;
  std::string unit = output_is_angle ? "rad/" : length + "/";
  unit += input_is_angle ? "rad" : length;
  if (k > 1) unit.append(1, '^').append(std::to_string(k));
  return unit;
}

}  // namespace

SweepColumns SweepLayout(const Mechanism& m, int order, const std::string& length_unit) {
  SweepColumns t;
  auto add = [&t](std::string name, std::string unit, int k, bool angle) {
    t.names.push_back(std::move(name));
    t.units.push_back(std::move(unit));
    t.order_of_column.push_back(k);
    t.angle_value.push_back(angle);
  };
  add(m.drive.input_name, m.InputIsAngle() ? "deg" : length_unit, -1, false);
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    const Output& out = m.outputs[o];
    const bool angle = m.OutputIsAngle(o);
    for (int c = 0; c < out.Components(); ++c) {
      const std::string base = out.ComponentLabel(c);
      for (int k = 0; k <= order; ++k) {
        std::string name = base;
        if (k > 0) name.append("_d").append(std::to_string(k));
        add(std::move(name), DerivativeUnit(angle, m.InputIsAngle(), k, length_unit), k, k == 0 && angle);
      }
    }
  }
  add("singular", "1", -1, false);
  return t;
}

}  // namespace koppel
