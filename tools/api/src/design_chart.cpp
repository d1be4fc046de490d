// Design charts (design_chart.hpp): the grid of requests and the pool of threads that designs it.
#include "koppel/api/design_chart.hpp"

#include "display.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/diagnostic.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/worker_threads.hpp"
#include "koppel/synthesis/deadcentre_synthesis.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>

namespace koppel {

using api_detail::BadInput;

namespace {

void ChartRequire(bool valid, const std::string& field, const std::string& why) {
  if (!valid) BadInput("design chart", field, why);
}

// Runs design(i) for i < n on `threads` threads (0: one per core): each design is independent
// and proved by its own re-analysis, so the chart's rows come out as if designed one by one.
template <class Design>
std::vector<Design> DesignAll(size_t n, const std::function<Design(size_t)>& design, int threads) {
  std::vector<Design> designs(n);
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < n; i = next++) designs[i] = design(i);
  };
  RunOnThreads(threads, work);
  return designs;
}

std::string ChartStatus(DesignStatus status) {
  switch (status) {
    case DesignStatus::kOk: return "ok";
    case DesignStatus::kBoundaryOptimum: return "boundary";
    case DesignStatus::kReanalysisFailed: return "failed";
    default: return "none";
  }
}

std::vector<ChartCell> ChartRow(std::vector<ChartCell> keys, DesignStatus status, const std::vector<double>& values) {
  keys.push_back({std::nullopt, ChartStatus(status)});
  for (double v : values) keys.push_back(status == DesignStatus::kOk ? ChartCell{v, ""} : ChartCell{});
  return keys;
}

std::vector<RockerSense> ChartSenses(const std::string& word) {
  if (word == "same") return {RockerSense::kSame};
  if (word == "opposite") return {RockerSense::kOpposite};
  if (word == "both") return {RockerSense::kSame, RockerSense::kOpposite};
  BadInput("design chart", "rocker_sense", "expected same, opposite or both, found '" + word + "'");
}

void CheckCells(double cells) {
  ChartRequire(cells <= static_cast<double>(kMaxChartCells), "phi0/psi0",
               fmt::format("{:.3g} cells, more than the limit of {} cells per chart (kMaxChartCells)", cells, kMaxChartCells));
}

DesignChart CrankRockerChart(const ChartSpec& spec) {
  const std::vector<RockerSense> senses = ChartSenses(spec.rocker_sense);
  CheckCells(spec.phi0.Count("phi0") * spec.psi0.Count("psi0") * static_cast<double>(senses.size()));
  std::vector<CrankRockerRequest> requests;
  for (double phi : spec.phi0.Values("phi0")) {
    for (RockerSense sense : senses) {
      for (double psi : spec.psi0.Values("psi0")) {
        CrankRockerRequest request;
        request.phi0 = DegToRad(phi);
        request.psi0 = DegToRad(psi);
        request.rocker_sense = sense;
        std::string why;
        ChartRequire(request.IsValid(&why), "phi0/psi0", why);
        requests.push_back(request);
      }
    }
  }
  DesignChart chart;
  chart.columns = {"phi0", "psi0", "rocker_sense", "status", "beta", "mu_min", "l1", "l2", "l3", "l4", "beta_L", "beta_E"};
  const auto designs = DesignAll<CrankRockerDesign>(requests.size(), [&](size_t i) { return BestCrankRockerInSpace(requests[i], spec.space); }, spec.threads);
  for (const CrankRockerDesign& d : designs) {
    const CrankRockerRequest& r = d.request;
    chart.rows.push_back(ChartRow({{RadToDeg(r.phi0), ""}, {RadToDeg(r.psi0), ""}, {std::nullopt, ToString(r.rocker_sense)}}, d.status,
                                  {RadToDeg(d.beta), RadToDeg(d.mu_min), d.l1, d.l2, d.l3, d.l4, RadToDeg(d.beta_l), RadToDeg(d.beta_e)}));
  }
  chart.designs = static_cast<int>(designs.size());
  return chart;
}

DesignChart SliderCrankChart(const ChartSpec& spec) {
  CheckCells(spec.phi0.Count("phi0"));
  std::vector<SliderCrankRequest> requests;
  for (double phi : spec.phi0.Values("phi0")) {
    SliderCrankRequest request;
    request.phi0 = DegToRad(phi);
    request.stroke = 1.0;
    std::string why;
    ChartRequire(request.IsValid(&why), "phi0", why);
    requests.push_back(request);
  }
  DesignChart chart;
  chart.columns = {"phi0", "status", "e_s0", "l1_s0", "l2_s0", "mu_min", "beta"};
  const auto designs = DesignAll<SliderCrankDesign>(requests.size(), [&](size_t i) { return BestSliderCrank(requests[i]); }, spec.threads);
  for (const SliderCrankDesign& d : designs)
    chart.rows.push_back(ChartRow({{RadToDeg(d.request.phi0), ""}}, d.status, {d.e, d.l1, d.l2, RadToDeg(d.mu_min), RadToDeg(d.beta)}));
  chart.designs = static_cast<int>(designs.size());
  return chart;
}

}  // namespace

double ChartRange::Count(const std::string& field) const {
  ChartRequire(std::isfinite(from) && std::isfinite(to) && std::isfinite(step), field, "the range and its step must be finite numbers");
  ChartRequire(step > 0 && to >= from, field, "needs FROM <= TO and STEP > 0");
  return std::floor((to - from) / step + 1e-9) + 1;
}

std::vector<double> ChartRange::Values(const std::string& field) const {
  CheckCells(Count(field));
  std::vector<double> values;
  for (int i = 0; from + i * step <= to + 1e-9 * step; ++i) values.push_back(from + i * step);
  return values;
}

ChartSpec DefaultChart(const std::string& type) {
  ChartSpec spec;
  spec.type = type;
  if (type == "crank-rocker") {
    spec.phi0 = {150, 210, 2};
    spec.psi0 = {20, 100, 2};
  } else if (type == "slider-crank") {
    spec.phi0 = {90, 180, 2};
  } else {
    BadInput("design chart", "type", "expected crank-rocker or slider-crank, found '" + type + "'");
  }
  return spec;
}

DesignChart SynthesiseChart(const ChartSpec& spec) {
  ChartRequire(spec.threads >= 0 && spec.threads <= kMaxThreads, "threads", fmt::format("must be 0 (one per core) to {}", kMaxThreads));
  if (const std::string why = spec.space.Unsupported("synth chart", false, false); !why.empty()) ChartRequire(false, "design", why);
  if (spec.type == "crank-rocker") return CrankRockerChart(spec);
  if (spec.type == "slider-crank") {
    ChartRequire(spec.space.Empty(), "design", "the design space is for four-bars (crank-rocker charts)");
    return SliderCrankChart(spec);
  }
  BadInput("design chart", "type", "expected crank-rocker or slider-crank, found '" + spec.type + "'");
}

}  // namespace koppel
