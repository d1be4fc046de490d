// What koppel::Model::Tolerances takes and returns (koppel tolerance): the linear stack-up with
// exact sensitivities, joint clearance and a Monte Carlo run through the exact solver, in the
// API's units (model.hpp): the output in degrees for an angle (its sensitivities in degrees per
// unit of the parameter), inputs in degrees for an R drive. What each number means:
// koppel/analysis/tolerance.hpp.
#pragma once

#include "koppel/analysis/status.hpp"

#include <optional>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

struct ToleranceRequest {
  std::string output;      // a scalar output, or a point's component "K_x" / "K_y"
  std::vector<double> inputs;  // [deg | length]
  std::vector<std::pair<std::string, double>> tolerances;  // parameter -> T (> 0, the parameter's unit)
  std::vector<std::pair<std::string, double>> clearances;  // revolute joint -> radius c of the pin's play
  long samples = 0;        // Monte Carlo samples (0: none)
  std::uint64_t seed = 1;
  std::string distribution = "uniform";  // or "normal" (T = 3 sigma)
  int threads = 0;         // 0: every core
  std::function<void(long done, long total)> progress;  // on the caller's thread, ~10 times a second
};

struct ToleranceRowReport {
  double input = 0;  // [deg | length]
  bool ok = false;
  std::string message;
  double nominal = 0;
  std::vector<double> sensitivity;     // per tolerance, in the request's order
  std::vector<double> clearance_gain;  // per clearance: |d output / d pin offset|
  double worst_case = 0, rss = 0, clearance_worst_case = 0, linear_std = 0;
  std::vector<double> share;           // each term's part of linear_std^2: tolerances then clearances
  long mc_samples = 0, mc_failed = 0;
  double mc_min = 0, mc_max = 0, mc_mean = 0, mc_std = 0;
  std::vector<double> quantiles;       // at ToleranceResult::quantile_levels
};

struct ToleranceResult {
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  std::string input_name;    // "phi"
  std::string input_unit;    // "deg" or "length"
  std::string output, unit;  // unit: "deg" or "length"
  std::vector<std::string> parameters, joints;
  std::vector<double> tolerances, clearances;
  std::string distribution;
  long samples = 0;
  std::uint64_t seed = 1;
  std::vector<double> quantile_levels;
  std::vector<ToleranceRowReport> rows;
  // The table koppel tolerance prints: input_name, nominal, sens_NAME..., sens_clearance_JOINT...,
  // worst_case, rss, clearance_worst_case, linear_std, share_NAME..., share_clearance_JOINT...,
  // and with samples mc_samples, mc_failed, mc_min, mc_max, mc_mean, mc_std, mc_q<level>...
  std::vector<std::string> Columns() const;
  // Row i in that order; empty cells where the input was not reached or no sample assembled.
  std::vector<std::optional<double>> Row(size_t i) const;
  std::string Brief() const;
};

}  // namespace koppel
