// Design charts (Kurventafeln, koppel synth chart): the best dead-centre design at every point of
// a grid of requests, each re-analysed by the solver (koppel/api/synthesis.hpp's syntheses, on
// every core). Angles in degrees; lengths for a frame of 1 (crank-rocker) or a stroke of 1
// (slider-crank).
//
// Failure behaviour: a malformed chart (an unknown type or rocker sense, an empty or reversed
// range, more cells than kMaxChartCells, a request no synthesis accepts) throws InputError; a
// grid point without a design is a row with its status word and empty numbers.
#pragma once

#include "koppel/synthesis/design_space.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

// from, from + step, ... up to `to` (reached when it lies within 1e-9 step of a sample) [deg].
struct ChartRange {
  double from = 0, to = 0, step = 1;
  // How many values, counted in double so that an absurd range is refused before anything is
  // allocated; InputError naming `field` for a step <= 0, to < from or a number that is not finite.
  double Count(const std::string& field) const;
  std::vector<double> Values(const std::string& field) const;
};

struct ChartSpec {
  std::string type = "crank-rocker";  // or "slider-crank"
  ChartRange phi0, psi0;              // psi0: crank-rocker only
  std::string rocker_sense = "same";  // crank-rocker: "same", "opposite" or "both"
  int threads = 0;                    // 0: one per core
  // crank-rocker: each cell the best mu_min inside it (BestCrankRockerInSpace; status none when
  // no member of the family lies inside); InputError for a slider-crank chart with a space
  DesignSpace space;
};
// The chart of `type` over its default ranges: crank-rocker phi0 150..210 by 2, psi0 20..100 by
// 2; slider-crank phi0 90..180 by 2. InputError for another type.
ChartSpec DefaultChart(const std::string& type);

// A cell: a number, a word (a rocker sense, a status), or empty (no design there).
struct ChartCell {
  std::optional<double> number;
  std::string word;
};

// Columns, crank-rocker: phi0, psi0, rocker_sense, status, beta, mu_min, l1, l2, l3, l4, beta_L,
// beta_E (the best beta, its mu_min, the lengths for A0B0 = 1 and the arc LE); slider-crank:
// phi0, status, e_s0, l1_s0, l2_s0, mu_min, beta (the best offset and lengths over the stroke).
// status: ok; none (no such mechanism exists); boundary (mu_min grows towards a degenerate end:
// no best design); failed (the re-analysis refused it). The numbers are empty unless ok. Rows in
// the order phi0, rocker sense, psi0.
struct DesignChart {
  std::vector<std::string> columns;
  std::vector<std::vector<ChartCell>> rows;
  int designs = 0;  // how many designs were run
};
DesignChart SynthesiseChart(const ChartSpec& spec);

}  // namespace koppel
