// The two exits of koppel to other programs, one call each for the CLI: the DXF of the parts at
// one pose with the coupler curves (koppel export --dxf), and the animated GIF of one cycle
// (koppel animate). The geometry is tools/plot's (workshop.hpp, animation.hpp); the files are
// written by dxf.hpp and gif.hpp.
#pragma once

#include "koppel/export/dxf.hpp"
#include "koppel/export/gif.hpp"
#include "koppel/plot/animation.hpp"
#include "koppel/plot/workshop.hpp"

#include <string>

namespace koppel::plot {

struct ExportResult {
  PlotStatus status = PlotStatus::kComplete;  // kPartial: the file holds what was computed; kFailed: no file
  std::string message;
  std::string bytes;  // the file; empty when kFailed
};

// The DXF with $INSUNITS `insunits` (DxfUnits). Throws std::invalid_argument for invalid options.
ExportResult ExportDxf(const Mechanism& mechanism, const WorkshopOptions& options, int insunits);

// The GIF. Throws std::invalid_argument for invalid options (AnimationOptions, GifOptions).
ExportResult AnimateGif(const Mechanism& mechanism, const AnimationOptions& options, const GifOptions& gif);

}  // namespace koppel::plot
