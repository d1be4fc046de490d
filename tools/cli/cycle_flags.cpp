#include "cycle_flags.hpp"

#include "common.hpp"

#include <fmt/format.h>

namespace koppel::cli {

void AddCycleFlags(CLI::App* command, CycleFlags& flags) {
  command->add_option("--trace", flags.trace,
                      "Trace this point's coupler curve (K, link.point); repeat for more (default: the file's point outputs)");
  command->add_option("--plate", flags.plate,
                      "Plate width W of the links [length unit] (default: 1/4 of the shortest distance between two joints of a link)");
  command->add_option("--pin", flags.pin, "Hole diameter D at the joints, slot width [length unit], less than W (default: W/2)");
}

plot::CycleOptions ReadCycleFlags(const Model& model, const CycleFlags& flags) {
  const Mechanism& m = model.mechanism();
  plot::CycleOptions options = plot::CycleOptionsOf(model);
  if (!flags.trace.empty()) options.traced.clear();
  for (const std::string& text : flags.trace) options.traced.push_back({ResolvePoint(m, text, "--trace"), text});
  if (!flags.plate.empty()) options.sizes.plate_width = ParseNumberFlag("--plate", flags.plate);
  if (!flags.pin.empty()) options.sizes.pin_diameter = ParseNumberFlag("--pin", flags.pin);
  else if (!flags.plate.empty()) options.sizes.pin_diameter = options.sizes.plate_width / 2;
  std::string why;
  if (!options.IsValid(&why)) {
    Complain(fmt::format("--pin/--plate: {} (D = {:g}, W = {:g})", why, options.sizes.pin_diameter, options.sizes.plate_width));
    throw Exit{kExitBadInput};
  }
  return options;
}

void WriteExportResult(const std::string& file, const std::string& out, const plot::ExportResult& result) {
  if (result.status == plot::PlotStatus::kFailed) {
    Complain(file + ": " + result.message);
    throw Exit{kExitFailed};
  }
  WriteOutput(out, result.bytes);
  if (!result.message.empty()) Complain(file + ": " + result.message);
  if (result.status == plot::PlotStatus::kPartial) throw Exit{kExitFailed};
}

}  // namespace koppel::cli
