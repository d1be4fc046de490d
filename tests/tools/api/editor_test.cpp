// The editor page's document and mechanism JSON (tools/api/src/editor_document.cpp,
// editor_mechanism.cpp): the formulas point at the fields they make, the mechanism comes back
// from its JSON to the same sweep, and a mechanism the page got wrong is refused, never solved.
// The page itself (WebAssembly, math.js) is tested against the CLI in tests/tools/edit.
#include "koppel/api/editor.hpp"
#include "koppel/api/model.hpp"
#include "koppel/catalog/document_edit.hpp"
#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

using namespace koppel;
using nlohmann::json;

namespace editor_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

const std::string kSliderCrank = std::string(KOPPEL_CATALOG_DIR) + "/slider-crank-offset.yaml";

// A formula of the document by its key path (the first when a path fills several targets).
json FormulaAt(const json& doc, const std::string& path) {
  for (const json& f : doc["formulas"])
    if (f["path"] == path) return f;
  FAIL("no formula at " + path);
  return {};
}

// The value at a JSON pointer of the mechanism JSON.
double At(const json& mechanism, const std::string& pointer) { return mechanism.at(json::json_pointer(pointer)).get<double>(); }

TEST_CASE("editor document: each formula of the file names the field its value goes to", "[editor]") {
  const Model model = Model::Load(kSliderCrank, {{"e", "0.3"}});
  const json doc = json::parse(EditorDocumentJson(model));
  // the parameters in file order, an override as given
  REQUIRE(doc["parameters"].size() == 3);
  CHECK(doc["parameters"][2]["name"] == "e");
  CHECK(doc["parameters"][2]["formula"] == "0.3");
  CHECK(doc["parameters"][2]["value"].get<double>() == 0.3);
  // frame: {A0: [0, -e]}: the frame is link 0, A0 its point 0
  const json a0 = FormulaAt(doc, "links.frame.points.A0[1]");
  CHECK(a0["formula"] == "-e");
  CHECK(a0["target"] == "/links/0/points/0/y");
  CHECK(a0["value"].get<double>() == -0.3);
  CHECK(At(doc["mechanism"], "/links/0/points/0/y") == -0.3);
  // coupler: {B: [l2, 0]}
  CHECK(FormulaAt(doc, "links.coupler.points.B[0]")["target"] == "/links/2/points/1/x");
  // the assembly hint: its input in degrees becomes radians (scale pi/180), B: [2, 0] goes to
  // every link that has a point B (coupler and slider)
  const json input = FormulaAt(doc, "assembly.input");
  CHECK(input["target"] == "/hint/input");
  CHECK(input["scale"].get<double>() == DegToRad(1.0));
  int hint_b = 0;
  for (const json& f : doc["formulas"]) hint_b += f["path"] == "assembly.points.B[0]";
  CHECK(hint_b == 2);
  // every formula's value, scaled, is the number at its target (the axis aside: normalised)
  for (const json& f : doc["formulas"]) {
    INFO(f.dump());
    if (f["target"].get<std::string>().find("/axis/") != std::string::npos) continue;
    CHECK(At(doc["mechanism"], f["target"]) == f["value"].get<double>() * f["scale"].get<double>());
  }
  CHECK(doc["unfollowed"].empty());
  CHECK(doc["input"]["angle"] == true);
}

TEST_CASE("editor mechanism: from its JSON to the same sweep", "[editor]") {
  const Model model = Model::Load(kSliderCrank);
  const Model back = ModelFromEditorJson(EditorMechanismJson(model));
  const SweepTable a = model.Sweep(0, 360, 5, 2), b = back.Sweep(0, 360, 5, 2);
  REQUIRE(a.columns == b.columns);
  REQUIRE(a.rows == b.rows);
  // the same mechanism, the same Newton path: the same numbers
  for (size_t i = 0; i < a.values.size(); ++i) CHECK(a.values[i] == b.values[i]);
  // and the points the page draws walk the same samples: A0 of the frame stays at (0, -e)
  const EditorFrames f = EditorPoints(back, 0, 360, 5);
  REQUIRE(f.inputs.size() == static_cast<size_t>(a.rows));
  CHECK(f.status == "complete");
  CHECK(f.points[1] == -0.8);
  // the slider's B (link 3, the 7th point) is on the slide line y = 0 at every sample
  const size_t per_sample = f.points.size() / f.inputs.size();
  for (size_t i = 0; i < f.inputs.size(); ++i) CHECK_THAT(f.points[i * per_sample + 13], Catch::Matchers::WithinAbs(0.0, 1e-12));
}

TEST_CASE("editor mechanism: what the page got wrong is refused", "[editor]") {
  const Model model = Model::Load(kSliderCrank);
  json m = json::parse(EditorMechanismJson(model));
  SECTION("a number that is no number (a formula the page could not evaluate)") {
    m["links"][0]["points"][0]["y"] = nullptr;
    CHECK_THROWS_WITH(ModelFromEditorJson(m.dump()), Catch::Contains("not a number"));
  }
  SECTION("a joint naming a link that is not there") {
    m["joints"][0]["link_b"] = 9;
    CHECK_THROWS_AS(ModelFromEditorJson(m.dump()), InputError);
  }
  SECTION("a slide axis of zero") {
    m["joints"][3]["axis"] = {0, 0};
    CHECK_THROWS_WITH(ModelFromEditorJson(m.dump()), Catch::Contains("slide axis must not be zero"));
  }
  SECTION("not JSON") { CHECK_THROWS_AS(ModelFromEditorJson("{links"), InputError); }
}

// A parameter no formula of the model part reads carries the message that refuses setting it
// (the page's set() says it, as --set and Model::With do); the others carry none.
TEST_CASE("editor document: a parameter no formula reads says so", "[editor]") {
  const Model model = Model::Load(std::string(KOPPEL_CATALOG_DIR) + "/watt-six-bar.yaml");
  const json doc = json::parse(EditorDocumentJson(model));
  int unread = 0;
  for (const json& p : doc["parameters"]) {
    if (!p.contains("unread")) {
      CHECK_NOTHROW(model.With(p["name"].get<std::string>(), p["value"].get<double>()));
      continue;
    }
    ++unread;
    CHECK_THROWS_WITH(model.With(p["name"].get<std::string>(), 1.0), Catch::Contains(p["unread"].get<std::string>()));
  }
  CHECK(unread >= 1);
}

// The page's export: the document hands the page the user's text and the place of each value; a
// change written at those places (SpliceScalars, as the page's module does) is the file that
// Model::With's text gives (EditMechanismText, the CLI's --set written in place), for every
// parameter and every followed formula of every catalog entry. Reference: EditMechanismText.
TEST_CASE("editor document: the places of its values give the library's in-place edit", "[editor]") {
  int entries = 0, edits = 0;
  for (const auto& e : std::filesystem::directory_iterator(KOPPEL_CATALOG_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    const Model model = Model::Load(e.path().string());
    const json doc = json::parse(EditorDocumentJson(model));
    INFO(e.path().string());
    REQUIRE(doc["source"].is_object());
    const std::string text = doc["source"]["text"], file = doc["source"]["file"];
    CHECK(text == model.ToYaml());
    ++entries;
    const auto place = [&](const std::string& path) {
      const json p = doc["source"]["places"].at(path);
      const std::string quote = p[2];
      return ScalarPlace{{p[0].get<size_t>(), p[1].get<size_t>()}, quote.empty() ? '\0' : quote[0]};
    };
    for (const json& p : doc["parameters"]) {
      const std::string name = p["name"];
      DocumentChanges change;
      change.parameters = {{name, "2.5"}};
      CHECK(SpliceScalars(text, file, {{place("parameters." + name), "2.5", name}}) == EditMechanismText(text, file, change));
      ++edits;
    }
    for (const json& f : doc["formulas"]) {
      const std::string path = f["path"];
      DocumentChanges change;
      change.numbers = {{path, -0.125}};
      CHECK(SpliceScalars(text, file, {{place(path), NumberText(-0.125), path}}) == EditMechanismText(text, file, change));
      ++edits;
    }
  }
  CHECK(entries >= 30);
  CHECK(edits > 500);
}

}  // namespace
}  // namespace editor_test
