// The editor page's WebAssembly module: koppel's kernel, analysis and API (Model::Sweep, the
// dead centres, the drivable ranges, Model::ToYaml) behind a few C functions that take and give
// JSON text. The page (editor.js) calls them through emscripten's ccall; one model at a time.
#include "koppel/api/editor.hpp"
#include "koppel/api/model.hpp"
#include "koppel/catalog/document_splice.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <exception>
#include <optional>
#include <string>

namespace {

using nlohmann::json;

std::optional<koppel::Model> current;  // the model the page edits: the last one that loaded
std::string answer;                    // the text the last call returns (valid until the next call)

const char* Answer(const json& j) {
  answer = j.dump();
  return answer.c_str();
}

// A call's failure as the page shows it: bad input (InputError) with its message, never a number.
const char* Failure(const std::exception& e) { return Answer({{"ok", false}, {"message", e.what()}}); }

json Number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json Singular(const std::vector<koppel::SingularPosition>& points) {
  json out = json::array();
  for (const auto& p : points) out.push_back({{"kind", p.kind}, {"input", p.input}, {"joints", p.joints}, {"action", p.action}});
  return out;
}

json Gaps(const std::vector<koppel::InputGap>& gaps) {
  json out = json::array();
  for (const auto& g : gaps) out.push_back({g.from, g.to});
  return out;
}

const char* NoModel() { return Answer({{"ok", false}, {"message", "no mechanism is loaded"}}); }

}  // namespace

extern "C" {

// Loads a mechanism in the editor's JSON (koppel/api/editor.hpp): {"ok", "notes"} or {"ok": false,
// "message"}; on failure the model loaded before stays current.
const char* koppel_load(const char* mechanism_json) {
  try {
    current = koppel::ModelFromEditorJson(mechanism_json);
    return Answer({{"ok", true}, {"notes", current->notes()}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

// The table of `koppel analyze --format json`: columns, rows (a NaN cell null, singular 0/1),
// and what the sweep met (notes: where the assembly was not the hint's, in the CLI's words);
// `at_branch_point` as --at-branch-point ("": continue).
const char* koppel_sweep(double from, double to, double step, int order, const char* at_branch_point) {
  if (!current) return NoModel();
  try {
    const koppel::SweepTable t = current->Sweep(from, to, step, order, koppel::ParseAtBranchPoint(at_branch_point));
    json rows = json::array();
    const size_t width = t.columns.size();
    for (int r = 0; r < t.rows; ++r) {
      json row = json::array();
      row.push_back(t.At(r, 0));
      for (size_t c = 1; c + 1 < width; ++c) row.push_back(Number(t.At(r, static_cast<int>(c))));
      row.push_back(t.At(r, static_cast<int>(width - 1)) != 0 ? 1 : 0);
      rows.push_back(std::move(row));
    }
    return Answer({{"ok", true}, {"columns", t.columns}, {"units", t.units}, {"rows", rows}, {"complete", t.status == koppel::AnalysisStatus::kComplete},
                   {"status", t.sweep_status}, {"message", t.message}, {"notes", t.notes}, {"singular_points", Singular(t.singular_points)}, {"gaps", Gaps(t.gaps)}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

// Every link point's global position along the same walk, for drawing.
const char* koppel_points(double from, double to, double step, const char* at_branch_point) {
  if (!current) return NoModel();
  try {
    const koppel::EditorFrames f = koppel::EditorPoints(*current, from, to, step, koppel::ParseAtBranchPoint(at_branch_point));
    return Answer({{"ok", true}, {"status", f.status}, {"message", f.message}, {"inputs", f.inputs}, {"points", f.points}, {"singular", f.singular}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

// The dead centres of the first scalar output and its extremes (koppel deadcentres).
const char* koppel_dead_centres(double from, double to) {
  if (!current) return NoModel();
  try {
    const koppel::DeadCentres d = current->FindDeadCentres("", from, to, 1.0);
    json points = json::array();
    for (const auto& p : d.points) points.push_back({{"kind", p.kind}, {"input", p.input}, {"value", p.value}});
    return Answer({{"ok", true}, {"output", d.output}, {"points", points}, {"message", d.message},
                   {"singular_points", Singular(d.singular_points)}, {"gaps", Gaps(d.gaps)}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

// The drivable interval of every branch koppel finds (koppel range --all).
const char* koppel_ranges() {
  if (!current) return NoModel();
  try {
    const koppel::Ranges r = current->DrivableRanges(true);
    json branches = json::array();
    for (const auto& b : r.branches)
      branches.push_back({{"branch", b.branch}, {"from", b.from}, {"to", b.to}, {"from_kind", b.from_kind}, {"to_kind", b.to_kind},
                          {"period", b.period}, {"singular_points", Singular(b.singular_points)}});
    return Answer({{"ok", true}, {"branches", branches}, {"message", r.message}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

// The user's text with the page's changes written in place (SpliceScalars, the rule of `--set`
// and `synth fit -o`): {"text", "file", "edits": [{"begin", "end", "quote", "formula" | "number",
// "what"}]} -> {"ok", "text"} or {"ok": false, "message"}. A number is written as NumberText.
const char* koppel_splice(const char* request_json) {
  try {
    const json request = json::parse(request_json);
    std::vector<koppel::ScalarEdit> edits;
    for (const json& e : request.at("edits")) {
      koppel::ScalarEdit edit;
      edit.place.span = {e.at("begin").get<std::size_t>(), e.at("end").get<std::size_t>()};
      const std::string quote = e.at("quote").get<std::string>();
      edit.place.quote = quote.empty() ? '\0' : quote[0];
      edit.formula = e.contains("number") ? koppel::NumberText(e.at("number").get<double>()) : e.at("formula").get<std::string>();
      edit.what = e.at("what").get<std::string>();
      edits.push_back(std::move(edit));
    }
    return Answer({{"ok", true}, {"text", koppel::SpliceScalars(request.at("text"), request.at("file"), std::move(edits))}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

// The mechanism as a mechanism file (Model::ToYaml) the CLI reads back: the page's export of a
// mechanism that came from no file.
const char* koppel_yaml() {
  if (!current) return NoModel();
  try {
    return Answer({{"ok", true}, {"yaml", current->ToYaml()}});
  } catch (const std::exception& e) {
    return Failure(e);
  }
}

}  // extern "C"
