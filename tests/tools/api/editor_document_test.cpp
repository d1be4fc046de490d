// The editor page's document (tools/api/src/editor_document.cpp) for a P-driven file in mm, with
// formulas at every kind of key the page follows (drive zero, assembly input and points, sweep,
// link points, a slide's axis and angle, an output's zero) and one it does not (a mass); and the
// document of a model made in code. References: the values of the formulas worked by hand, the
// scale of each field from the file format (degrees -> pi/180 for angles, 1 for lengths and for a
// P drive's input), the hint entries a bare point name makes (one per link with that point, in
// link order: mechanism_file's rule) and the file's own text at each place (the formula as written).
// tests/tools/api/editor_test.cpp has the seed 000 slider-crank's document and the catalog's places.
#include "koppel/api/editor.hpp"

#include "koppel/api/model.hpp"
#include "support/mechanisms.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace koppel::editor_document_test {
namespace {

using nlohmann::json;

// the catalog's hydraulic boom (P drive s: the cylinder's length) with formulas at the page's keys
std::string CylinderText() {
  std::string t = test::ReadText(test::CatalogEntryPath("hydraulic-boom-cylinder"));
  t = test::Replace(t, "title: Boom luffed by a hydraulic cylinder\n", "title: Boom luffed by a hydraulic cylinder\nunits: {length: mm}\n");
  t = test::Replace(t, "  smax: 3.4      # cylinder extended (stroke 1.5)\n", "  smax: 3.4\n  dz: 0.5\n  tilt: 30\n  spare: 7\n");
  t = test::Replace(t, "axis: [1, 0]}", "axis: [b, 0], angle: tilt}");
  t = test::Replace(t, "drive: {joint: S, name: s}", "drive: {joint: S, name: s, zero: dz}");
  t = test::Replace(t, "theta: {link: boom}", "theta: {link: boom, zero: tilt}");
  t = test::Replace(t, "  input: 2.55\n", "  input: 2.55 - dz\n");
  t = test::Replace(t, "points: {boom.T: [5.88, 1.2], rod.B: [2.156, 0.439], E: [1.62, 0.68]}",
                    "points: {B: [2.156, 0.439], boom.T: [5.88, 1.2], E: [1.62, 0.68]}");
  t = test::Replace(t, "sweep: {from: smin, to: smax, step: 0.01}\ncatalog",
                    "sweep: {from: smin - dz, to: smax - dz, step: 0.01}\ncatalog");
  return test::Replace(t, "  rod:\n    points: {B: [0, 0]}\n", "  rod:\n    points: {B: [0, 0]}\n    mass: 2*b\n    cg: B\n");
}

// every formula of the document at `path` (one per target)
std::vector<json> FormulasAt(const json& doc, const std::string& path) {
  std::vector<json> found;
  for (const json& f : doc["formulas"])
    if (f["path"] == path) found.push_back(f);
  return found;
}

}  // namespace

TEST_CASE("a P-driven file in mm: each formula's value, scale and target", "[api][editor-document]") {
  const Model model = Model::Parse(CylinderText(), "cylinder.yaml");
  const json doc = json::parse(EditorDocumentJson(model));
  CHECK(doc["input"] == json({{"name", "s"}, {"angle", false}, {"unit", "mm"}}));
  CHECK(doc["title"] == "Boom luffed by a hydraulic cylinder");
  const double deg = M_PI / 180;
  // path -> (value in the file's units, scale, target), worked from the text
  const std::map<std::string, std::tuple<double, double, std::string>> expected = {
      {"drive.zero", {0.5, 1.0, "/drive/zero"}},                  // a length: no degrees
      {"assembly.input", {2.05, 1.0, "/hint/input"}},             // 2.55 - dz
      {"joints.S.angle", {30, deg, "/joints/2/angle"}},           // S is the third joint
      {"outputs.theta.zero", {30, deg, "/outputs/0/offset"}},
      {"sweep.from", {1.4, 1.0, "/sweep/from"}},                  // smin - dz
      {"links.boom.points.T[0]", {6, 1.0, "/links/1/points/2/x"}},  // boom: link 1, T its third point
      {"joints.S.axis[0]", {2.2, 1.0, "/joints/2/axis/0"}}};
  for (const auto& [path, want] : expected) {
    INFO(path);
    const std::vector<json> f = FormulasAt(doc, path);
    REQUIRE(f.size() == 1);
    CHECK(f[0]["value"].get<double>() == Approx(std::get<0>(want)).epsilon(1e-15));
    CHECK(f[0]["scale"].get<double>() == Approx(std::get<1>(want)).epsilon(1e-15));
    CHECK(f[0]["target"] == std::get<2>(want));
  }
  // the axis is a direction: the mechanism holds it normalised ([b, 0] -> [1, 0])
  CHECK(doc["mechanism"]["joints"][2]["axis"] == json::array({1.0, 0.0}));
  // the bare name B made one hint entry per link with a point B (boom, then rod), boom.T the
  // third, E (the barrel's only) the fourth: each target's entry is that point
  const json& hint = doc["mechanism"]["hint"]["points"];
  const json& links = doc["mechanism"]["links"];
  const auto point_name = [&](const json& entry) { return links[entry["link"].get<int>()]["points"][entry["point"].get<int>()]["name"]; };
  const std::vector<json> b = FormulasAt(doc, "assembly.points.B[0]");
  REQUIRE(b.size() == 2);
  CHECK(b[0]["target"] == "/hint/points/0/x");
  CHECK(b[1]["target"] == "/hint/points/1/x");
  CHECK(links[hint[0]["link"].get<int>()]["name"] == "boom");
  CHECK(links[hint[1]["link"].get<int>()]["name"] == "rod");
  for (int e : {0, 1}) CHECK(point_name(hint[e]) == "B");
  CHECK(point_name(hint[2]) == "T");
  REQUIRE(FormulasAt(doc, "assembly.points.E[1]").size() == 1);
  CHECK(FormulasAt(doc, "assembly.points.E[1]")[0]["target"] == "/hint/points/3/y");
  CHECK(point_name(hint[3]) == "E");
  // the mass is not followed (the page does not compute forces), and says the file has loads
  CHECK(doc["unfollowed"] == json::array({"links.rod.mass"}));
  CHECK(doc["has_loads"] == true);
  // a parameter no formula reads carries the refusal; dz and tilt are read
  for (const json& p : doc["parameters"]) {
    INFO(p.dump());
    CHECK(p.contains("unread") == (p["name"] == "spare"));
  }
}

TEST_CASE("the source places hold each parameter's and each followed formula's text as written", "[api][editor-document]") {
  const Model model = Model::Parse(CylinderText(), "cylinder.yaml");
  const json doc = json::parse(EditorDocumentJson(model));
  REQUIRE(doc["source"].is_object());
  const std::string text = doc["source"]["text"];
  CHECK(text == CylinderText());  // no parameter set since: the user's text as it is
  const json& places = doc["source"]["places"];
  const auto written = [&](const std::string& path) {
    const json& p = places.at(path);
    CHECK(p[2] == "");  // every value of this file is a plain scalar
    return text.substr(p[0].get<size_t>(), p[1].get<size_t>() - p[0].get<size_t>());
  };
  for (const json& p : doc["parameters"]) CHECK(written("parameters." + p["name"].get<std::string>()) == p["formula"]);
  for (const json& f : doc["formulas"]) CHECK(written(f["path"].get<std::string>()) == f["formula"]);
  CHECK(written("assembly.input") == "2.55 - dz");
  CHECK(written("parameters.tilt") == "30");
}

TEST_CASE("a model made in code: no parameters, no formulas, no source; its title is its name", "[api][editor-document]") {
  const Model model = Model::FromMechanism(test::SliderCrank(1, 2.6, 0.8));
  const json doc = json::parse(EditorDocumentJson(model));
  CHECK(doc["parameters"].empty());
  CHECK(doc["formulas"].empty());
  CHECK(doc["unfollowed"].empty());
  CHECK(doc["source"].is_null());
  CHECK(doc["has_loads"] == false);
  CHECK(doc["title"] == "slider-crank");
  CHECK(doc["input"]["unit"] == "deg");
  CHECK(doc["mechanism"]["links"].size() == 4);
}

}  // namespace koppel::editor_document_test
