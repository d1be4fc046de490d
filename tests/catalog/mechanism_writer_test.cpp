// The YAML writer: for every catalog entry, write -> read gives the same mechanism (links,
// points, joints, drive, outputs, assembly hint) and the same motion (a sweep of both agrees
// to rounding). Reference: the entry as the reader reads it from the catalog. Names that YAML
// would misread (quotes, commas, markup, null, numbers) come back as they were.
#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

namespace koppel::mechanism_writer_test {
namespace {

// Coordinates go through 17 significant digits, angles through degrees: a few ulps.
constexpr double kRoundTrip = 1e-13;

void SameMechanism(const Mechanism& a, const Mechanism& b) {
  CHECK(a.name == b.name);
  REQUIRE(a.links.size() == b.links.size());
  for (size_t l = 0; l < a.links.size(); ++l) {
    INFO("link " << a.links[l].name);
    CHECK(a.links[l].name == b.links[l].name);
    CHECK(a.links[l].is_frame == b.links[l].is_frame);
    REQUIRE(a.links[l].points.size() == b.links[l].points.size());
    for (size_t p = 0; p < a.links[l].points.size(); ++p) {
      CHECK(a.links[l].points[p].name == b.links[l].points[p].name);
      CHECK((a.links[l].points[p].local - b.links[l].points[p].local).norm() <= kRoundTrip * (1 + a.links[l].points[p].local.norm()));
    }
  }
  REQUIRE(a.joints.size() == b.joints.size());
  for (size_t j = 0; j < a.joints.size(); ++j) {
    INFO("joint " << a.joints[j].name);
    const Joint &x = a.joints[j], &y = b.joints[j];
    CHECK(x.name == y.name);
    CHECK(x.type == y.type);
    CHECK(x.link_a == y.link_a);
    CHECK(x.link_b == y.link_b);
    CHECK(x.point_a == y.point_a);
    CHECK(x.point_b == y.point_b);
    CHECK((x.axis - y.axis).norm() <= kRoundTrip);
    CHECK(std::abs(x.angle - y.angle) <= kRoundTrip);
  }
  CHECK(a.drive.joint == b.drive.joint);
  CHECK(std::abs(a.drive.zero - b.drive.zero) <= kRoundTrip);
  CHECK(a.drive.input_name == b.drive.input_name);
  REQUIRE(a.outputs.size() == b.outputs.size());
  for (size_t o = 0; o < a.outputs.size(); ++o) {
    INFO("output " << a.outputs[o].name);
    const Output &x = a.outputs[o], &y = b.outputs[o];
    CHECK(x.name == y.name);
    CHECK(x.kind == y.kind);
    CHECK(x.joint == y.joint);
    CHECK(x.link == y.link);
    CHECK((x.p.link == y.p.link && x.p.point == y.p.point && x.q.link == y.q.link && x.q.point == y.q.point));
    CHECK(std::abs(x.offset - y.offset) <= kRoundTrip);
  }
  CHECK(std::abs(a.hint.input - b.hint.input) <= kRoundTrip);
  REQUIRE(a.hint.points.size() == b.hint.points.size());
  for (size_t h = 0; h < a.hint.points.size(); ++h) {
    CHECK(a.hint.points[h].point.link == b.hint.points[h].point.link);
    CHECK(a.hint.points[h].point.point == b.hint.points[h].point.point);
    CHECK((a.hint.points[h].global - b.hint.points[h].global).norm() <= kRoundTrip * (1 + a.hint.points[h].global.norm()));
  }
}

}  // namespace

TEST_CASE("write -> read gives the same mechanism for every catalog entry", "[catalog][writer]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  REQUIRE(catalog.entries().size() >= 5);
  for (const CatalogEntry& e : catalog.entries()) {
    INFO(e.file.id);
    const MechanismFile& original = e.file;
    const std::string yaml = WriteMechanismYaml(original.mechanism, "round trip of " + original.id, original.sweep,
                                                original.parameters.Values());
    const MechanismFile copy = ParseMechanismText(yaml, original.id + ".yaml");
    SameMechanism(original.mechanism, copy.mechanism);
    CHECK(copy.sweep.from == original.sweep.from);
    CHECK(copy.sweep.to == original.sweep.to);
    CHECK(copy.sweep.step == original.sweep.step);
    for (const auto& [name, value] : original.parameters.Values()) CHECK(copy.parameters.Value(name) == value);
    CHECK_FALSE(copy.card.has_value());  // the writer writes the mechanism, not the card

    // the same motion: a sweep over the card's range of both
    const CatalogCard& card = *original.card;
    const bool angle = original.mechanism.InputIsAngle();
    SweepOptions options;
    options.from = angle ? DegToRad(card.from) : card.from;
    options.to = angle ? DegToRad(card.to) : card.to;
    options.step = (angle ? DegToRad(card.step) : card.step) * 10;
    options.order = 1;
    const SweepResult a = Sweep(original.mechanism, options), b = Sweep(copy.mechanism, options);
    REQUIRE(a.complete());
    REQUIRE(b.complete());
    CHECK((a.outputs - b.outputs).cwiseAbs().maxCoeff() <= 1e-9);
  }
}

TEST_CASE("names with quotes, commas, colons, markup and formulas are quoted and read back as they were", "[catalog][writer]") {
  // reference: the reader's reading of tests/data/hostile-names.yaml
  const MechanismFile original = ReadMechanismFile(std::string(KOPPEL_TEST_DATA_DIR) + "/hostile-names.yaml");
  const std::string yaml = WriteMechanismYaml(original.mechanism, "hostile names", original.sweep, original.parameters.Values());
  SameMechanism(original.mechanism, ParseMechanismText(yaml, "copy.yaml").mechanism);
  // names YAML would take for something else: null, a truth value, a number, a comment, a map
  Mechanism m = original.mechanism;
  m.links[1].name = "null";
  m.links[2].name = "yes";
  m.links[3].name = "# not a comment: {a: 1}";
  m.joints[0].name = "1.5";
  m.outputs[0].name = "~";
  SameMechanism(m, ParseMechanismText(WriteMechanismYaml(m, "", original.sweep, original.parameters.Values()), "copy.yaml").mechanism);
  // a name the reader refuses (a control character, from the API) is written readable: U+FFFD
  m.outputs[0].name = "s\x1b[31m";
  const Mechanism read = ParseMechanismText(WriteMechanismYaml(m, "", original.sweep, original.parameters.Values()), "copy.yaml").mechanism;
  CHECK(read.outputs[0].name == "s\uFFFD[31m");
}

}  // namespace koppel::mechanism_writer_test
