// The offline editor page of `koppel edit` (tools/edit): what the CLI hands the page, and what
// the page's WebAssembly module (koppel's kernel, analysis and this API compiled with emscripten)
// rebuilds a Model from after every edit.
//
// The page has neither yaml-cpp nor muparser, so the CLI hands it the evaluated mechanism as JSON
// (internal units: radians, lengths in the file's unit; links, points, joints by index) together
// with every formula the file's model part was read from: its text, the key path it was read at,
// the value muparser gave it (in the file's units), and where it goes in the mechanism JSON (a
// JSON pointer and a scale: pi/180 for an angle given in degrees, else 1). After a parameter
// changes, the page evaluates the parameters in file order and then these formulas, writes the
// values to their targets and hands the mechanism back here (ModelFromEditorJson), which checks
// and admits it as Model::Load does. The document says which formulas it cannot follow (masses
// and loads: the page does not compute forces).
#pragma once

#include "koppel/api/model.hpp"

#include <string>
#include <vector>

namespace koppel {

// The page's document as JSON text: {"title", "file", "input": {"name", "angle", "unit"},
// "parameters": [{"name", "formula", "value"}], "formulas": [{"path", "formula", "value",
// "target", "scale"}], "unfollowed": [key paths], "has_loads", "mechanism": EditorMechanismJson,
// (a parameter no formula reads also has "unread": the message that refuses setting it, as --set),
// "source": {"text", "file", "places": {key path: [begin, end, quote]}} or null}: the user's text
// (with the parameters set so far written in) and where each parameter and followed formula is
// written in it (koppel/catalog/document_splice.hpp), so that the page's export changes those
// values in place and keeps every other byte; a value written over several lines has no place.
std::string EditorDocumentJson(const Model& model);

// The mechanism as the page holds it: {"name", "title", "units": {"given", "name", "metres"} (the file's length
// unit, koppel/core/loads.hpp), "sweep": {from, to, step}
// [deg | length], "parameters": [[name, value]], "links": [{"name", "frame", "points": [{"name",
// "x", "y"}]}], "joints": [{"name", "type": "R"|"P", "link_a", "link_b", "point_a", "point_b",
// "axis": [x, y], "angle"}], "drive": {"joint", "zero", "input_name"}, "outputs": [{"name",
// "kind", "joint", "link", "p": [link, point], "q": [link, point], "offset"}], "hint": {"input",
// "points": [{"link", "point", "x", "y"}]}}; angles in radians.
std::string EditorMechanismJson(const Model& model);

// The model of a mechanism in that form: a P joint's axis is normalised as the reader does, the
// mechanism checked (CheckConsistency) and admitted (one drive, mobility 1). InputError naming
// the field when the JSON is malformed, the mechanism inconsistent or not admitted.
Model ModelFromEditorJson(const std::string& mechanism_json);

// Global positions of every link point at the samples of a sweep over from..to by step [deg |
// length], walked as Model::Sweep walks it (through branch points as `at_branch_point` says):
// `points` holds per sample, link after link in mechanism order, each point's x, y. `status` is
// the sweep's word ("complete", "partial", "not assemblable", ...).
struct EditorFrames {
  std::string status, message;
  std::vector<double> inputs;  // [deg | length]
  std::vector<double> points;  // inputs.size() x (2 * total points)
  std::vector<int> singular;   // 1 at a singular pose
};
EditorFrames EditorPoints(const Model& model, double from, double to, double step,
                          AtBranchPoint at_branch_point = AtBranchPoint::kContinue);

}  // namespace koppel
