// Tolerance stack-up and joint clearance of one output over the drive input: how far the output
// moves when the parts are made to tolerance and the pins have play.
//
// Linear (first order, exact sensitivities by the implicit-function theorem, sensitivity.hpp):
// s_j = dy/dp_j at the nominal pose; worst_case = sum |s_j| T_j; rss = sqrt(sum (s_j T_j)^2) (the
// statistical stack-up of the tolerances T_j); a revolute joint whose pin is free within a circle
// of radius c moves y by at most c |dy/d delta| (delta the pin's offset in its hole), and
// clearance_worst_case sums that over the joints given. linear_std is the standard deviation the
// linear model predicts for the distribution: sqrt(sum s_j^2 sigma_j^2 + sum |dy/d delta|^2 c^2 / 4)
// with sigma_j = T_j / sqrt(3) (uniform) or T_j / 3 (normal), c^2 / 4 the variance of one
// component of a point uniform in a disc of radius c. share_j = s_j^2 sigma_j^2 / linear_std^2, a
// clearance's share |dy/d delta|^2 c^2 / 4 / linear_std^2: each term's part of that variance,
// which dimension to tighten first.
//
// Play (sensitivity.hpp, DisplacePin and OutputOnLinks): the pin off its hole's centre opens the
// joint by delta, every link keeps its geometry and the output is read off the links it names, in
// the gradient and in the samples alike, for every output (a transmission angle from the
// coupler's and the output link's directions).
//
// Monte Carlo (exact): `samples` mechanisms, each with every parameter p_j + T_j u (u uniform in
// [-1, 1], or normal with T_j = 3 sigma) and each clearance joint's pin displaced in its hole by a
// vector uniform in the circle of radius c (fixed to link_b of the joint: the pin sits somewhere
// in the hole for the whole run), solved by Newton from the nominal pose at every input. Sample k
// draws from its own generator seeded by (seed, k), so the result does not depend on the number
// of threads. Angles in radians, lengths in the file's unit; an angle output's samples are taken
// as nominal + the wrapped difference.
#pragma once

#include "koppel/analysis/sensitivity.hpp"
#include "koppel/analysis/status.hpp"
#include "koppel/core/expected.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace koppel {

// What a tolerance T or a clearance c may be: positive, and within kMaxCoordinate (a tolerance
// beyond the largest coordinate a mechanism file may hold describes no part).
bool IsToleranceSize(double value);
inline constexpr const char* kToleranceSizeRule = "a positive number up to 1e9 (kMaxCoordinate)";

enum class ToleranceDistribution { kUniform, kNormal };
const char* ToString(ToleranceDistribution distribution);  // "uniform", "normal"

struct ToleranceOptions {
  // the output and its component (0, or 1 for a point's y)
  int output = 0;
  int component = 0;
  std::vector<double> inputs;        // [rad | length], in walking order from the assembly
  std::vector<double> tolerances;    // T_j > 0 of the builder's parameters, in their order
  std::vector<int> clearance_joints; // revolute joints with play
  std::vector<double> clearances;    // their radius c > 0 [length]
  long samples = 0;                  // Monte Carlo samples; 0: the linear analysis only (kMaxToleranceSamples,
                                     // and samples x inputs at most kMaxToleranceValues: core/limits.hpp)
  std::uint64_t seed = 1;
  ToleranceDistribution distribution = ToleranceDistribution::kUniform;
  int threads = 0;                   // 0: every core; at most kMaxThreads (fewer run when no more can be had)
  // Called on the caller's thread about ten times a second while the samples run: (done, total).
  std::function<void(long done, long total)> progress;
  std::vector<double> quantile_levels = {0.001, 0.01, 0.5, 0.99, 0.999};

  bool IsValid(const Mechanism& nominal, std::string* why) const;
};

struct ToleranceRow {
  double input = 0;                      // [rad | length]
  bool ok = false;                       // false: the nominal pose was not reached (message)
  std::string message;
  double nominal = 0;                    // y at the nominal parameters
  std::vector<double> sensitivity;       // dy/dp_j
  std::vector<double> clearance_gain;    // |dy/d delta| per clearance joint
  double worst_case = 0, rss = 0, clearance_worst_case = 0;
  std::vector<double> share;             // of linear_std^2: tolerances, then clearances; sum 1 (all 0 when nothing moves y)
  double linear_std = 0;
  // Monte Carlo (samples > 0)
  long mc_samples = 0, mc_failed = 0;    // mc_failed: samples whose mechanism did not reach this input
  double mc_min = 0, mc_max = 0, mc_mean = 0, mc_std = 0;
  std::vector<double> quantiles;         // at quantile_levels
};

struct ToleranceReport {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: some rows or samples failed (message)
  std::string message;
  std::vector<ToleranceRow> rows;
};

// The memory a run holds its samples' values in [bytes], and whether that fits in half of
// `usable_bytes` (koppel/core/memory.hpp's UsableMemory, named by `source` in the message): a run
// that cannot hold them ends before it starts, with the figures, not with std::bad_alloc.
std::uint64_t ToleranceValueBytes(const ToleranceOptions& options);
Outcome CheckToleranceMemory(const ToleranceOptions& options, std::uint64_t usable_bytes, const std::string& source);

// `builder` rebuilds the mechanism from the toleranced parameters' values; `nominal` are their
// nominal values. Bad options: status failed with the reason (the CLI checks them first).
ToleranceReport AnalyseTolerances(const MechanismBuilder& builder, const std::vector<double>& nominal, const ToleranceOptions& options);

}  // namespace koppel
