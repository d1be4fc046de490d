// The editor page's mechanism JSON both ways and the points it draws
// (tools/api/src/editor_mechanism.cpp). References: the round trip (every catalog entry's JSON
// read back and written again is the same JSON); a slide axis as a direction (normalised: [7, 0]
// is [1, 0], [3, 4] is [0.6, 0.8]); seed 000's closed form of the slider-crank (A = A0 +
// l1 (sin phi, -cos phi), B = (s, 0), tests/support/closed_forms) for the drawn points, with the
// frame listed between moving links; the P drive's definition for the hydraulic cylinder (its
// pin-to-pin length is the input) and the boom's lengths.
// tests/tools/api/editor_test.cpp has the sweep of the JSON's model and the refusals of a null
// number, a missing link, a zero axis and text that is no JSON.
#include "koppel/api/editor.hpp"

#include "koppel/api/model.hpp"
#include "support/closed_forms.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace koppel::editor_mechanism_test {
namespace {

using nlohmann::json;

// [length] a solved pose against the closed form: the solver's convergence (1e-12 of the scale)
constexpr double kSolved = 1e-10;

// seed 000's slider-crank with its frame listed second (links: crank, frame, coupler, slider):
// a moving link before the frame and two after it
std::string FrameSecondSliderCrank() {
  std::string t = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  const std::string frame = "  frame:\n    frame: true\n    points: {A0: [0, -e], F: [0, 0]}\n";
  const std::string crank = "  crank:\n    points: {A0: [0, 0], A: [0, -l1]}\n";
  t = test::Replace(t, frame, "");
  return test::Replace(t, crank, crank + frame);
}

// where link `link`'s point `point` starts in a sample of EditorFrames::points
std::map<std::string, size_t> PointOffsets(const Mechanism& m) {
  std::map<std::string, size_t> at;
  size_t k = 0;
  for (const Link& l : m.links)
    for (const NamedPoint& p : l.points) at[l.name + "." + p.name] = 2 * k++;
  return at;
}

}  // namespace

TEST_CASE("every catalog entry's mechanism JSON reads back to the same JSON", "[api][editor-mechanism]") {
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(KOPPEL_CATALOG_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    INFO(e.path().filename().string());
    const json first = json::parse(EditorMechanismJson(Model::Load(e.path().string())));
    const json again = json::parse(EditorMechanismJson(ModelFromEditorJson(first.dump())));
    CHECK(again == first);
    ++entries;
  }
  CHECK(entries >= 30);
}

TEST_CASE("a slide axis is read as a direction, an R joint's axis as it is", "[api][editor-mechanism]") {
  const Model model = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  json j = json::parse(EditorMechanismJson(model));
  REQUIRE(j["joints"][3]["type"] == "P");
  j["joints"][3]["axis"] = {7, 0};
  const Model seven = ModelFromEditorJson(j.dump());
  CHECK(seven.mechanism().joints[3].axis == Eigen::Vector2d(1, 0));
  // the same direction, the same mechanism: the same sweep, number for number
  const SweepTable a = model.Sweep(0, 360, 15, 2), b = seven.Sweep(0, 360, 15, 2);
  REQUIRE(a.values.size() == b.values.size());
  for (size_t i = 0; i < a.values.size(); ++i) CHECK(a.values[i] == b.values[i]);
  j["joints"][3]["axis"] = {3, 4};
  const Eigen::Vector2d tilted = ModelFromEditorJson(j.dump()).mechanism().joints[3].axis;
  CHECK_THAT(tilted.x(), Catch::Matchers::WithinAbs(0.6, 1e-16));
  CHECK_THAT(tilted.y(), Catch::Matchers::WithinAbs(0.8, 1e-16));
  j["joints"][0]["axis"] = {2, 5};  // an R joint: not a direction, kept
  CHECK(ModelFromEditorJson(j.dump()).mechanism().joints[0].axis == Eigen::Vector2d(2, 5));
}

TEST_CASE("the drawn points of the slider-crank, frame listed second, against seed 000's closed form", "[api][editor-mechanism]") {
  const double l1 = 1, l2 = 2.6, e = 0.8;  // the entry's parameters
  const Model model = ModelFromEditorJson(EditorMechanismJson(Model::Parse(FrameSecondSliderCrank(), "frame-second.yaml")));
  REQUIRE(model.mechanism().FrameLink() == 1);
  const EditorFrames f = EditorPoints(model, 0, 360, 10);
  CHECK(f.status == "complete");
  REQUIRE(f.inputs.size() == 37);  // 0, 10, ..., 360
  const size_t per_sample = f.points.size() / f.inputs.size();
  REQUIRE(per_sample == 2 * 7);    // crank A0 A, frame A0 F, coupler A B, slider B
  const std::map<std::string, size_t> at = PointOffsets(model.mechanism());
  for (size_t i = 0; i < f.inputs.size(); ++i) {
    CHECK_THAT(f.inputs[i], Catch::Matchers::WithinAbs(10.0 * i, 1e-12));  // degrees through radians and back: a few ulps
    const double phi = f.inputs[i] * M_PI / 180;
    const double s = test::SliderCrank(l1, l2, e, phi).s;
    const std::map<std::string, Eigen::Vector2d> expected = {
        {"crank.A0", {0, -e}}, {"crank.A", {l1 * std::sin(phi), -e - l1 * std::cos(phi)}},
        {"coupler.A", {l1 * std::sin(phi), -e - l1 * std::cos(phi)}}, {"coupler.B", {s, 0}},
        {"slider.B", {s, 0}},  {"frame.A0", {0, -e}}, {"frame.F", {0, 0}}};
    for (const auto& [name, point] : expected) {
      INFO(name << " at " << f.inputs[i] << " deg");
      const double* xy = &f.points[i * per_sample + at.at(name)];
      CHECK_THAT(xy[0], Catch::Matchers::WithinAbs(point.x(), kSolved));
      CHECK_THAT(xy[1], Catch::Matchers::WithinAbs(point.y(), kSolved));
    }
    CHECK(f.singular[i] == 0);  // this crank turns round: no dead centre of the drive
  }
}

TEST_CASE("a P drive's points: the cylinder is as long as the input, the boom keeps its lengths", "[api][editor-mechanism]") {
  const Model model = Model::Load(test::CatalogEntryPath("hydraulic-boom-cylinder"));  // b = 2.2, L = 6
  const EditorFrames f = EditorPoints(model, 1.9, 3.4, 0.1);
  CHECK(f.status == "complete");
  REQUIRE(f.inputs.size() == 16);
  const size_t per_sample = f.points.size() / f.inputs.size();
  const std::map<std::string, size_t> at = PointOffsets(model.mechanism());
  for (size_t i = 0; i < f.inputs.size(); ++i) {
    INFO("s = " << f.inputs[i]);
    CHECK_THAT(f.inputs[i], Catch::Matchers::WithinAbs(1.9 + 0.1 * i, 1e-12));
    const auto point = [&](const std::string& name) {
      const double* xy = &f.points[i * per_sample + at.at(name)];
      return Eigen::Vector2d(xy[0], xy[1]);
    };
    CHECK_THAT((point("rod.B") - point("frame.C0")).norm(), Catch::Matchers::WithinAbs(f.inputs[i], kSolved));
    CHECK_THAT((point("boom.B") - point("rod.B")).norm(), Catch::Matchers::WithinAbs(0.0, kSolved));
    CHECK_THAT((point("boom.B") - point("frame.O")).norm(), Catch::Matchers::WithinAbs(2.2, kSolved));
    CHECK_THAT((point("boom.T") - point("frame.O")).norm(), Catch::Matchers::WithinAbs(6.0, kSolved));
  }
}

TEST_CASE("the page's malformed mechanism is refused at its field", "[api][editor-mechanism]") {
  const json good = json::parse(EditorMechanismJson(Model::Load(test::CatalogEntryPath("slider-crank-offset"))));
  const auto refusal = [](const json& j) -> Diagnostic {
    try {
      ModelFromEditorJson(j.dump());
    } catch (const InputError& e) {
      REQUIRE_FALSE(e.diagnostics().empty());
      return e.diagnostics()[0];
    }
    FAIL("not refused: " << j.dump());
    return {};
  };
  json j = good;
  j["outputs"][0]["kind"] = "speed";
  CHECK(refusal(j).path == "outputs[0].kind");
  CHECK_THAT(refusal(j).message, Catch::Contains("unknown output kind 'speed'"));
  j = good;
  j["outputs"][0]["p"] = {0, 1, 2};
  CHECK(refusal(j).path == "outputs[0].p");
  j = good;
  j["joints"][1]["axis"] = {1, 0, 0};
  CHECK(refusal(j).path == "joints[1].axis");
  j = good;
  j["links"][2]["name"] = 5;
  CHECK(refusal(j).path == "links[2].name");
  CHECK_THAT(refusal(j).message, Catch::Contains("wrong type"));
  // a joint type the file format does not have, a fractional index and a point's bad field, each at its path
  j = good;
  j["joints"][0]["type"] = "p";
  CHECK(refusal(j).path == "joints[0].type");
  CHECK_THAT(refusal(j).message, Catch::Contains("expected R or P, found 'p'"));
  j = good;
  j["joints"][0]["link_a"] = 1.7;
  CHECK(refusal(j).path == "joints[0].link_a");
  CHECK_THAT(refusal(j).message, Catch::Contains("not a whole number"));
  j = good;
  j["links"][1]["points"][1]["x"] = "1";
  CHECK(refusal(j).path == "links[1].points[1].x");
  j = good;
  j.erase("hint");
  CHECK(refusal(j).file == "editor JSON");
  CHECK_THROWS_AS(ModelFromEditorJson("[1, 2]"), InputError);  // JSON, not an object
  // a range EditorPoints cannot sample
  CHECK_THROWS_AS(EditorPoints(ModelFromEditorJson(good.dump()), 0, 360, 0), InputError);
}

}  // namespace koppel::editor_mechanism_test
