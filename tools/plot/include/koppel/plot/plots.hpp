// The documents' figures as SVG, drawn from the solver's numbers of the same run:
// transfer functions of 0th..nth order with the dead centres (seed 000/001 "Bild 2"), the
// transmission angle with μ_min (seed 000 "Bild 4"), the coupler curve with the straight-line
// stretch and its band (seed 003 "Bild 1a/2"), and the design charts of `koppel synth chart`
// (seed 002 Kurventafeln). Inputs are shown in degrees for an R drive; gaps of the computed
// range are shaded and never bridged by a line.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/plot/figure.hpp"
#include "koppel/solver/sweep.hpp"

#include <optional>
#include <string>

namespace koppel::plot {

enum class PlotStatus {
  kComplete,   // every requested sample and mark computed
  kPartial,    // the picture shows what was computed; the message says what is missing
  kFailed,     // nothing to draw (the mechanism does not assemble, no such quantity, ...)
};
const char* ToString(PlotStatus status);

struct PlotResult {
  PlotStatus status = PlotStatus::kComplete;
  std::string message;
  std::string svg;  // empty when kFailed
  std::string Brief() const;
};

struct TransferPlotOptions {
  int output = -1;    // index into mechanism.outputs
  int order = 2;      // panels for the 0th..order-th transfer function (0..kMaxOrder)
  SweepOptions range;  // radians (R drive) or length; its step is the sample spacing
  std::string length_unit = "length";  // the file's length unit, for the axes' labels ("mm")
  bool IsValid(const Mechanism& mechanism, std::string* why) const;
};
// One panel per order, sharing the input axis; dead centres of a scalar output as rules and
// markers (φ_a, φ_i for an extended/folded pair).
PlotResult TransferPlot(const Mechanism& mechanism, const TransferPlotOptions& options);

struct MuPlotOptions {
  int output = -1;  // a transmission-angle output
  SweepOptions range;
  std::string length_unit = "length";  // the file's length unit, for the input axis's label
  bool IsValid(const Mechanism& mechanism, std::string* why) const;
};
// μ over the input, μ_min marked (the least sample or a refined stationary minimum, whichever
// is smaller).
PlotResult MuPlot(const Mechanism& mechanism, const MuPlotOptions& options);

struct CurvePlotOptions {
  PointRef point;
  SweepOptions range;
  bool straight = false;                 // add the straight-line analysis of seed 003
  double qg = 0.005;                     // allowed Q_G for the stretch
  std::optional<double> reference;       // input of K_I (radians); default the flattest point
  double resolution = 0.02 * kPi / 180;  // search resolution [rad]
  bool IsValid(const Mechanism& mechanism, std::string* why) const;
};
// The coupler curve to scale (equal aspect); with `straight` the stretch K_A..K_E, K_I, the
// tangent g, and a second panel: the stretch in coordinates along and across g with its band Δy.
PlotResult CurvePlot(const Mechanism& mechanism, const CurvePlotOptions& options);

// The numbers of a tolerance analysis (koppel tolerance, koppel/api/tolerance.hpp) over a range
// of inputs, as the picture needs them: per row the nominal output, the half-width of the linear
// band (worst case of the tolerances plus that of the clearances), the Monte Carlo extremes (empty
// without samples), each tolerance's and clearance's share; rows not reached have ok = false.
struct ToleranceBand {
  std::string mechanism, output, output_unit, input_label;
  bool input_degrees = true;
  std::vector<double> inputs, nominal, worst_case, mc_min, mc_max;
  std::vector<bool> ok;
  std::vector<std::string> names;           // "l1", ..., "clearance A"
  std::vector<std::vector<double>> shares;  // per name, per row
};
// Three panels over the input: the nominal output; its deviation from nominal in the filled
// worst-case band with the Monte Carlo min and max dashed; the shares of the variance (the
// dimension to tighten first is the highest curve).
PlotResult TolerancePlot(const ToleranceBand& band);

// A design chart: the CSV that `koppel synth chart` writes (crank-rocker: phi0, psi0, beta,
// mu_min, ...; slider-crank: phi0, e_s0, l1_s0, l2_s0, mu_min, beta), as curve families over φ0
// with their parameter labelled. kFailed with a message naming the line for any other table.
PlotResult ChartPlot(const std::string& csv_text, const std::string& file_name);

}  // namespace koppel::plot
