// `catalog check`: every entry proves itself; mutated copies of real entries show that the
// checks can fail — a wrong declared feature, the printed (OCR) formula instead of the
// corrected one, a wrong sign — and that malformed cards are rejected with their line.
#include "koppel/catalog/check.hpp"

#include "koppel/catalog/catalog.hpp"

#include "support/seeds.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

namespace koppel::check_test {
namespace {

// [deg] a figure recomputed by the solver (Newton to 1e-13 of the size) and converted to degrees: 1e-8 deg
// leaves room for the stationary-point search and the conversion, far below the document's digits
constexpr double kPrintedFigure = 1e-8;

using test::LineOf;
using test::Replace;

const CheckOutcome& Find(const EntryReport& r, const std::string& name_part, const std::string& variant = "") {
  for (const CheckOutcome& c : r.checks) {
    if (c.name.find(name_part) != std::string::npos && (variant.empty() || c.variant == variant)) return c;
  }
  FAIL("no check named like '" << name_part << "'");
  throw std::logic_error("unreachable");
}

std::string Messages(const InputError& e) {
  std::string all;
  for (const Diagnostic& d : e.diagnostics()) all += d.ToString() + "\n";
  return all;
}

}  // namespace

TEST_CASE("every catalog entry passes its own checks", "[catalog][check]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  REQUIRE(catalog.entries().size() >= 5);
  for (const CatalogEntry& e : catalog.entries()) {
    const EntryReport r = CheckEntry(e.file.path);
    INFO(e.file.id);
    for (const CheckOutcome& c : r.checks) {
      INFO(c.variant << " " << c.name << ": worst " << c.worst << " tol " << c.tolerance << " " << c.detail);
      CHECK(c.passed());
    }
    CHECK(r.passed());
    // every figure and equation of the card ran (in each variant it belongs to)
    CHECK(r.checks.size() > e.file.card->figures.size());
  }
}

TEST_CASE("a mutated copy of every entry fails: each figure, each equation and each declared feature", "[catalog][check]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  int index = 0;
  for (const CatalogEntry& e : catalog.entries()) {
    if (!test::InCheckedShare(index++)) continue;  // every entry in the Release build, a fifth under the sanitizers
    INFO(e.file.id);
    // every expected value and formula moved by twice its tolerance (and a little more, so that
    // rounding cannot keep it inside): each check must now fail on its own
    CatalogCard moved = *e.file.card;
    for (FigureCheck& f : moved.figures) f.expected = "(" + f.expected + ") + " + std::to_string(2 * f.tolerance + 1e-6);
    for (EquationCheck& q : moved.equations) q.formula = "(" + q.formula + ") + " + std::to_string(2 * q.tolerance + 1e-6);
    const EntryReport r = CheckCard(e.file.path, moved);
    for (const CheckOutcome& c : r.checks) {
      if (c.kind == CheckKind::kFeatures) continue;
      INFO(c.variant << " " << c.name << ": worst " << c.worst << " tol " << c.tolerance);
      CHECK(c.status == CheckStatus::kFailed);
    }
    CHECK_FALSE(r.passed());

    // a declared feature changed (the card without its figures, which the above covers): the
    // links count, then the joints of type D (a dwell keeps its rest and a quick return its time
    // ratio, the figures their classes stand on)
    CatalogCard features_only = *e.file.card;
    std::erase_if(features_only.figures,
                  [](const FigureCheck& f) { return f.quantity != FigureQuantity::kRest && f.quantity != FigureQuantity::kTimeRatio; });
    features_only.equations.clear();
    features_only.variants.clear();
    CHECK(CheckCard(e.file.path, features_only).passed());
    CatalogCard more_links = features_only;
    more_links.declared.links += 1;
    CHECK(CheckCard(e.file.path, more_links).checks.at(0).status == CheckStatus::kFailed);
    CatalogCard other_joints = features_only;
    other_joints.declared.joints_by_type["D"] += 1;
    CHECK(CheckCard(e.file.path, other_joints).checks.at(0).status == CheckStatus::kFailed);
  }
}

TEST_CASE("computed access features equal the documents' Zugriffsmerkmale", "[catalog][check]") {
  const MechanismFile f = ReadMechanismFile(test::CatalogEntryPath("proportional-linkage"));
  const AccessFeatures c = ComputeFeatures(f.mechanism, {"s"});
  // seed 001: 6 links (4 binary, 2 ternary), 7 joints (4 D, 3 S), 1 drive at the frame, 1 output at the frame
  CHECK(c.links == 6);
  CHECK(c.links_by_degree.at(2) == 4);
  CHECK(c.links_by_degree.at(3) == 2);
  CHECK(c.joints == 7);
  CHECK(c.joints_by_type.at("D") == 4);
  CHECK(c.joints_by_type.at("S") == 3);
  CHECK(c.drive_joints_at_frame == 1);
  CHECK(c.output_links_at_frame == 1);
  CHECK(CompareFeatures(f.card->declared, c).empty());
}

TEST_CASE("a declared feature that differs from the graph makes check fail", "[catalog][check]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("proportional-linkage"));
  const std::string path = dir.Write("p.yaml", Replace(text, "links_by_degree: {binary: 4, ternary: 2}", "links_by_degree: {binary: 5, ternary: 1}"));
  const EntryReport r = CheckEntry(path);
  const CheckOutcome& features = Find(r, "access features");
  CHECK(features.status == CheckStatus::kFailed);
  CHECK_THAT(features.detail, Catch::Contains("ternary links: declared 1, computed 2"));
  CHECK_FALSE(r.passed());
}

TEST_CASE("an assembly hint that leaves the branch to the solver makes check fail", "[catalog][check]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("swinging-block"));
  // the hint before: the frame pivot alone. The rod may run from A through B0 (psi = 0 at phi = 0)
  // or away from it (psi = 180 deg): the hint said neither.
  const std::string frame_only = dir.Write("frame-only.yaml", Replace(text, "points: {E: [2*r + d, 0]}", "points: {B0: [3, 0]}"));
  const EntryReport unpinned = CheckEntry(frame_only);
  const CheckOutcome& open = Find(unpinned, "assembly hint");
  CHECK(open.status == CheckStatus::kFailed);
  CHECK_THAT(open.detail, Catch::Contains("leaves the pose of rod to the solver"));
  // the rod's end on the far side of A: a pinned hint, the other branch, and the figures say so
  const std::string reversed = dir.Write("reversed.yaml", Replace(text, "points: {E: [2*r + d, 0]}", "points: {E: [-d - r + r, 0]}"));
  const EntryReport other = CheckEntry(reversed);
  CHECK(Find(other, "assembly hint").status == CheckStatus::kPassed);
  CHECK_FALSE(other.passed());
}

TEST_CASE("quick-return is computed: declared exactly where the time ratio is not 1", "[catalog][check]") {
  test::TempDir dir;
  // Whitworth's time ratio (180 + 2 asin(d/r))/(180 - 2 asin(d/r)) = 2: without the class, the check says so
  const std::string whitworth = test::ReadText(test::CatalogEntryPath("whitworth-quick-return"));
  const std::string undeclared =
      dir.Write("w.yaml", Replace(whitworth, "class: [slotted-link-rotating, quick-return,", "class: [slotted-link-rotating,"));
  const EntryReport without = CheckEntry(undeclared);
  const CheckOutcome& missing = Find(without, "class quick-return");
  CHECK(missing.status == CheckStatus::kFailed);
  CHECK_THAT(missing.detail, Catch::Contains("s's time ratio is 2: declare quick-return"));
  // the centric slider-crank's strokes take 180 deg each: declared, the class fails
  const std::string engine = test::ReadText(test::CatalogEntryPath("engine-slider-crank"));
  const std::string declared = dir.Write("e.yaml", Replace(engine, "class: [slider-crank]", "class: [slider-crank, quick-return]"));
  const EntryReport centric = CheckEntry(declared);
  const CheckOutcome& wrong = Find(centric, "class quick-return");
  CHECK(wrong.status == CheckStatus::kFailed);
  CHECK_THAT(wrong.detail, Catch::Contains("declared, but x's time ratio is 1"));
  // declared and computed, but without a time_ratio figure: the class's number is not stated
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  CatalogCard unstated = *catalog.Find("whitworth-quick-return")->file.card;
  std::erase_if(unstated.figures, [](const FigureCheck& f) { return f.quantity == FigureQuantity::kTimeRatio; });
  const EntryReport silent = CheckCard(test::CatalogEntryPath("whitworth-quick-return"), unstated);
  const CheckOutcome& quiet = Find(silent, "class quick-return");
  CHECK(quiet.status == CheckStatus::kFailed);
  CHECK_THAT(quiet.detail, Catch::Contains("state it as a time_ratio figure"));
}

TEST_CASE("dwell is computed: declared exactly where a rest figure states it, and the rest is checked", "[catalog][check]") {
  test::TempDir dir;
  // the toggle press's ram: y = K_y - sqrt(l2^2 - K_x^2) with K on the circles (A, rod) and (T0, l1)
  // moves 5.72e-4 while the crank turns from -20 to 20 deg (its fourth-order contact at phi = 0)
  const std::string press = test::ReadText(test::CatalogEntryPath("toggle-press"));
  const EntryReport as_is = CheckEntry(test::CatalogEntryPath("toggle-press"));
  CHECK(Find(as_is, "class dwell").status == CheckStatus::kPassed);
  CHECK_THAT(Find(as_is, "dwell: the ram rests").value, Catch::Matchers::WithinAbs(5.72044e-4, 1e-9));
  // the class without the rest figure: no rest is stated
  const std::string no_rest = dir.Write("a.yaml", Replace(press, "quantity: rest", "quantity: stroke"));
  const EntryReport without_rest = CheckEntry(no_rest);  // kept: Find returns a reference into it
  const CheckOutcome& unstated = Find(without_rest, "class dwell");
  CHECK(unstated.status == CheckStatus::kFailed);
  CHECK_THAT(unstated.detail, Catch::Contains("no figure states the rest"));
  // the rest without the class
  const std::string undeclared = dir.Write("b.yaml", Replace(press, "class: [toggle, dwell,", "class: [toggle,"));
  const EntryReport without_class = CheckEntry(undeclared);
  const CheckOutcome& missing = Find(without_class, "class dwell");
  CHECK(missing.status == CheckStatus::kFailed);
  CHECK_THAT(missing.detail, Catch::Contains("declare the class dwell"));
  // a band narrower than the motion: the rest itself fails
  const std::string narrow = dir.Write("c.yaml", Replace(press, "      tolerance: 1e-3\n", "      tolerance: 1e-4\n"));
  const EntryReport tight = CheckEntry(narrow);
  CHECK(Find(tight, "dwell: the ram rests").status == CheckStatus::kFailed);
  CHECK_FALSE(tight.passed());
}

TEST_CASE("a figure named a time ratio is the time_ratio quantity, >= 1", "[catalog][check]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("whitworth-quick-return"));
  const std::string path = dir.Write("w.yaml", Replace(text, "      quantity: time_ratio\n", "      quantity: phase_ratio\n"));
  CHECK_THROWS_WITH(CheckEntry(path), Catch::Contains("a figure named a time ratio is quantity time_ratio"));
}

TEST_CASE("a four-bar's Grashof type is computed into its classes", "[catalog][check]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  auto classes = [&](const std::string& id) { return catalog.Find(id)->classes; };
  auto has = [](const std::vector<std::string>& c, const std::string& name) { return std::find(c.begin(), c.end(), name) != c.end(); };
  // Evans: s + l = 1 + 8.0778 > p + q = 9 (koppel classify), the card declares no Grashof type
  CHECK(has(classes("evans-straight-line"), "triple-rocker"));
  // the dead-centre synthesis' crank-rocker (crank shortest, Grashof), declared only quick-return
  CHECK(has(classes("deadcentre-crank-rocker"), "crank-rocker"));
  CHECK(has(classes("deadcentre-crank-rocker"), "quick-return"));
  CHECK_FALSE(has(classes("engine-slider-crank"), "triple-rocker"));
}

TEST_CASE("check passes only with the corrected phi_i, not the printed 2/3 pi", "[catalog][check]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  const std::string path = dir.Write("s.yaml", Replace(text, "expected: 270 + asin((e/l2)/(1 - l1/l2))/deg", "expected: 120 + asin((e/l2)/(1 - l1/l2))/deg"));
  const EntryReport r = CheckEntry(path);
  const CheckOutcome& phi_i = Find(r, "phi_i", "e=0.8");
  CHECK(phi_i.status == CheckStatus::kFailed);
  CHECK_THAT(phi_i.value, Catch::Matchers::WithinAbs(300.0, kPrintedFigure));  // asin(0.8/1.6) = 30 deg exactly
  CHECK(phi_i.worst > 100.0);
}

TEST_CASE("a deliberately wrong equation makes check fail at the right place", "[catalog][check]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  // the sign of the lambda term of s'' flipped
  const std::string path = dir.Write("s.yaml", Replace(text, "-l1*(sin(phi + psi)/cos_psi + lambda*sin(phi)^2/cos_psi^3)",
                                                      "-l1*(sin(phi + psi)/cos_psi - lambda*sin(phi)^2/cos_psi^3)"));
  const EntryReport r = CheckEntry(path);
  const CheckOutcome& s2 = Find(r, "s''/l1 = -[sin(phi + psi)", "e=0.8");
  CHECK(s2.status == CheckStatus::kFailed);
  CHECK(s2.worst > 0.1);
  CHECK_FALSE(r.passed());
}

TEST_CASE("malformed catalog cards are rejected with their line", "[catalog][check]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));

  SECTION("a missing access feature") {
    const std::string bad = Replace(text, "    links: 4\n", "");
    try {
      ReadMechanismFile(dir.Write("a.yaml", bad));
      FAIL("accepted a card without 'links'");
    } catch (const InputError& e) {
      CHECK_THAT(Messages(e), Catch::Contains("missing access feature 'links'"));
      CHECK(e.diagnostics().at(0).line == LineOf(bad, "  features:") + 1);
    }
  }
  SECTION("a formula naming an unknown parameter") {
    const std::string bad = Replace(text, "formula: l1*cos(phi + psi)/cos_psi", "formula: l7*cos(phi + psi)/cos_psi");
    try {
      ReadMechanismFile(dir.Write("b.yaml", bad));
      FAIL("accepted an unknown parameter");
    } catch (const InputError& e) {
      CHECK_THAT(Messages(e), Catch::Contains("l7"));
      CHECK(e.diagnostics().at(0).line == LineOf(bad, "l7*cos"));
    }
  }
  SECTION("an output the file does not declare") {
    const std::string bad = Replace(text, "  outputs: [s]", "  outputs: [stroke]");
    try {
      ReadMechanismFile(dir.Write("c.yaml", bad));
      FAIL("accepted an undeclared output");
    } catch (const InputError& e) {
      CHECK_THAT(Messages(e), Catch::Contains("does not declare"));
      CHECK(e.diagnostics().at(0).line == LineOf(bad, "  outputs: [stroke]"));
    }
  }
  SECTION("an unknown card key") {
    const std::string bad = Replace(text, "  motion:", "  motoin:");
    try {
      ReadMechanismFile(dir.Write("d.yaml", bad));
      FAIL("accepted an unknown key");
    } catch (const InputError& e) {
      CHECK_THAT(Messages(e), Catch::Contains("did you mean 'motion'"));
      CHECK(e.diagnostics().at(0).line == LineOf(bad, "motoin"));
    }
  }
}

}  // namespace koppel::check_test
