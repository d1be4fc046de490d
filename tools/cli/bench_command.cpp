// koppel bench: the benchmarks of tools/bench (Google Benchmark, in the module libkoppel_bench.so
// that this command alone loads) in this process, each with its baseline measured in the same
// run, so that the ratios hold on any machine and under any load.
#include "commands.hpp"
#include "common.hpp"

#include "bench_module.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <thread>

namespace koppel::cli {
namespace bench_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct BenchArgs {
  std::string filter;
  std::string format = "table";
  double min_time = 0.5;
};

struct Row {
  std::string name, per, clock, baseline_name, note;
  double ns = 0.0;
  double baseline_ns = 0.0;  // 0: none
  double ratio = 0.0;        // 0: none
  bool measured = false;
};

std::string Number(double v, int digits) { return fmt::format("{:.{}g}", v, digits); }

// 3 significant digits in ns, us, ms or s, for the terminal
std::string Duration(double ns) {
  const char* units[] = {"ns", "us", "ms", "s"};
  int u = 0;
  for (; u < 3 && ns >= 1000.0; ++u) ns /= 1000.0;
  return fmt::format("{:.3g} {}", ns, units[u]);
}

// The benchmarks --filter names, and the baselines their ratios need. Exit{2} when none matches.
std::set<std::string> WantedCases(const BenchArgs& args, const std::vector<bench::CaseInfo>& cases) {
  std::regex filter;
  try {
    filter = std::regex(args.filter.empty() ? "." : args.filter, std::regex::extended);
  } catch (const std::regex_error& e) {
    Complain("--filter: not a regular expression: '" + args.filter + "' (" + e.what() + ")");
    throw Exit{kExitBadInput};
  }
  std::set<std::string> wanted;
  for (const bench::CaseInfo& c : cases) {
    if (!std::regex_search(c.name, filter)) continue;
    wanted.insert(c.name);
    if (!c.baseline.empty()) wanted.insert(c.baseline);
  }
  if (wanted.empty()) {
    std::string names;
    for (const bench::CaseInfo& c : cases) names += (names.empty() ? "" : ", ") + c.name;
    Complain("--filter '" + args.filter + "' matches no benchmark; there are: " + names);
    throw Exit{kExitBadInput};
  }
  return wanted;
}

// `koppel analyze ARGS...` in this process, for the benchmark that times it (analyze_bench.cpp).
std::string AnalyzeHere(const std::vector<std::string>& args) {
  CLI::App app;
  AddAnalyzeCommand(app);
  std::vector<std::string> reversed = {"analyze"};
  reversed.insert(reversed.end(), args.begin(), args.end());
  std::reverse(reversed.begin(), reversed.end());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const Exit& e) {
    return "koppel analyze exited with " + std::to_string(e.code);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// One row per wanted case: its time per step (or run) and its ratio to its baseline or budget.
std::vector<Row> RowsOf(const std::vector<bench::CaseInfo>& cases, const std::set<std::string>& wanted, std::map<std::string, bench::Measured>& measured,
                        bool* failed) {
  std::map<std::string, double> ns_of;
  for (const bench::CaseInfo& c : cases) {
    const bench::Measured& m = measured[c.name];
    const double ns = c.threaded ? m.wall_ns : m.cpu_ns;
    if (m.ran && m.error.empty()) ns_of[c.name] = c.per == bench::Per::kRun ? ns : ns / c.steps_per_iteration;
  }
  std::vector<Row> rows;
  for (const bench::CaseInfo& c : cases) {
    if (!wanted.count(c.name)) continue;
    Row row;
    row.name = c.name;
    row.per = c.per == bench::Per::kStep ? "step" : c.per == bench::Per::kCurve ? "curve" : "run";
    row.clock = c.threaded ? "wall" : "cpu";
    row.note = c.note;
    const bench::Measured& m = measured[c.name];
    if (!c.skipped && !m.error.empty()) {
      row.note = "failed: " + m.error;
      *failed = true;
    }
    if (ns_of.count(c.name)) {
      row.measured = true;
      row.ns = ns_of[c.name];
      if (!c.baseline.empty() && ns_of.count(c.baseline)) {
        row.baseline_name = c.baseline_factor == 1.0 ? c.baseline : fmt::format("{} x {}", c.baseline, Number(c.baseline_factor, 6));
        row.baseline_ns = ns_of[c.baseline] * c.baseline_factor;
      } else if (c.budget_ns > 0.0) {
        row.baseline_name = "budget";
        row.baseline_ns = c.budget_ns;
      } else if (!c.baseline.empty()) {
        row.baseline_name = c.baseline + " (not measured)";
      }
      if (row.baseline_ns > 0.0) row.ratio = row.ns / row.baseline_ns;
    }
    rows.push_back(row);
  }
  return rows;
}

void PrintJson(const std::vector<Row>& rows, unsigned cores, bool have_load, double load) {
  nlohmann::json list = nlohmann::json::array();
  for (const Row& r : rows) {
    nlohmann::json j = {{"name", r.name}, {"per", r.per}, {"clock", r.clock}};
    j["ns_per_step"] = r.measured ? nlohmann::json(r.ns) : nlohmann::json(nullptr);
    j["baseline"] = r.baseline_ns > 0.0 ? nlohmann::json(r.baseline_ns) : nlohmann::json(nullptr);
    j["ratio"] = r.ratio > 0.0 ? nlohmann::json(r.ratio) : nlohmann::json(nullptr);
    j["baseline_name"] = r.baseline_name;
    if (!r.note.empty()) j["note"] = r.note;
    list.push_back(j);
  }
  nlohmann::json out = {{"benchmarks", list}, {"cores", cores}};
  if (have_load) out["load_average"] = load;
  std::cout << JsonText(out);
}

void PrintCsv(const std::vector<Row>& rows) {
  std::string text = "name,per,clock,ns_per_step,baseline,ratio,baseline_name,note\n";
  for (const Row& r : rows) {
    text += fmt::format("{},{},{},{},{},{},{},\"{}\"\n", r.name, r.per, r.clock, r.measured ? Number(r.ns, 6) : "",
                        r.baseline_ns > 0 ? Number(r.baseline_ns, 6) : "", r.ratio > 0 ? Number(r.ratio, 4) : "", r.baseline_name,
                        r.note);
  }
  std::cout << text;
}

void PrintTable(const std::vector<Row>& rows, unsigned cores, bool have_load, double load) {
  std::cout << fmt::format("{:<24} {:>14} {:>14} {:>8}  {}\n", "name", "time", "baseline", "ratio", "baseline is");
  for (const Row& r : rows) {
    auto time = [&](double ns) { return Duration(ns) + "/" + r.per; };
    std::cout << fmt::format("{:<24} {:>14} {:>14} {:>8}  {}{}\n", r.name, r.measured ? time(r.ns) : "-",
                             r.baseline_ns > 0 ? time(r.baseline_ns) : "-", r.ratio > 0 ? Number(r.ratio, 3) : "-", r.baseline_name,
                             r.note.empty() ? "" : (r.baseline_name.empty() ? "" : "; ") + r.note);
  }
  std::string wall;
  for (const Row& r : rows) {
    if (r.clock == "wall") wall += (wall.empty() ? "" : ", ") + r.name;
  }
  std::cout << fmt::format("(CPU time of this process{}; {} cores, load average {} at the start)\n",
                           wall.empty() ? "" : "; wall time for " + wall, cores, have_load ? Number(load, 3) : "unknown");
}

void RunBench(const BenchArgs& args) {
  if (args.format != "table" && args.format != "csv" && args.format != "json") {
    Complain("--format must be table, csv or json, found '" + args.format + "'");
    throw Exit{kExitBadInput};
  }
  if (!(args.min_time > 0.0 && args.min_time <= 60.0)) {
    Complain("--min-time must lie in (0, 60] seconds");
    throw Exit{kExitBadInput};
  }
  const bench::BenchModuleTable& module = bench::BenchModule();
  const std::vector<bench::CaseInfo> cases = module.cases();
  const std::set<std::string> wanted = WantedCases(args, cases);
  double load[1] = {0.0};
  const bool have_load = getloadavg(load, 1) == 1;
  bench::Host host;
  host.analyze = AnalyzeHere;
  // one line per benchmark on stderr as it finishes
  host.done = [](const std::string& name) { std::cerr << fmt::format("koppel bench: {} done\n", name); };
  std::map<std::string, bench::Measured> measured = module.run(wanted, args.min_time, host);
  bool failed = false;
  const std::vector<Row> rows = RowsOf(cases, wanted, measured, &failed);
  const unsigned cores = std::thread::hardware_concurrency();
  if (args.format == "json") {
    PrintJson(rows, cores, have_load, load[0]);
  } else if (args.format == "csv") {
    PrintCsv(rows);
  } else {
    PrintTable(rows, cores, have_load, load[0]);
  }
  if (failed) throw Exit{kExitFailed};
}

}  // namespace
}  // namespace bench_command

void AddBenchCommand(CLI::App& app) {
  using namespace bench_command;
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Time koppel's solver and commands (Google Benchmark), each against a baseline measured in the same run:\n"
      "walk steps (positions, 1st and 2nd order of every output) against hand-written closed forms doing the\n"
      "same work, chains of N four-bar loops against the 4-loop chain per loop, the four-bar's positions\n"
      "against SolveSpace's libslvs, synthesis, charts, fits, analyze and the atlas build (per curve, on one\n"
      "core: 100 000 curves/s is 10 us a curve) against their time budgets, and the start-up of koppel itself\n"
      "(--version against 10 ms, analyze of a small file against twice that).\n"
      "ratio = time / baseline. Times are the CPU time of this process, wall-clock time for the cases that run\n"
      "threads or processes of their own (chart, fit, start-up); on a loaded machine compare the ratios.\n"
      "Example: koppel bench --filter 'fourbar|chain' --format json");
  cmd->add_option("--filter", args->filter, "Run the benchmarks whose name matches this regular expression (and their baselines)");
  cmd->add_option("--format", args->format, "table (default), csv or json");
  cmd->add_option("--min-time", args->min_time, "Seconds each benchmark runs at least (default 0.5)");
  cmd->callback([args] { RunBench(*args); });
}

}  // namespace koppel::cli
