// The admission rule of every front door (tools/api/src/admission.cpp): one drive needs mobility
// 1. References: the Grübler–Kutzbach count by hand for each file, and the motion itself (a
// five-bar with one drive does not move determinately; a parallelogram with a third parallel
// crank moves although the count says 0).
#include "admission.hpp"

#include "koppel/api/model.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <functional>
#include <sstream>

using namespace koppel;

namespace admission_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

std::string Text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The single diagnostic of a refusal.
Diagnostic Refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    return e.diagnostics()[0];
  }
  FAIL("admitted");
  return {};
}

}  // namespace

TEST_CASE("a five-bar with one drive is refused by every way into a Model, naming the field", "[api][admission]") {
  // five links (n = 5), five R joints: 3 (5 - 1) - 2 * 5 = 2 degrees of freedom, 1 drive
  const std::string path = test::TestDataPath("five-bar.yaml");
  const Diagnostic d = Refusal([&] { (void)ReadAdmittedMechanism(path, {}); });
  CHECK(d.file == path);
  CHECK(d.path == "drive");
  CHECK_THAT(d.message, Catch::Contains("mobility 2") && Catch::Contains("1 drive"));
  CHECK_THAT(Refusal([&] { (void)Model::Load(path); }).message, Catch::Contains("mobility 2"));
  CHECK_THAT(Refusal([&] { (void)Model::Parse(Text(path), "five.yaml"); }).file, Catch::Equals("five.yaml"));
  const MechanismFile file = ReadMechanismFile(path, {});
  CHECK_THAT(Refusal([&] { (void)Model::FromMechanism(file.mechanism); }).message, Catch::Contains("mobility 2"));
}

TEST_CASE("an overconstrained linkage that moves is admitted with a note; a four-bar without one", "[api][admission]") {
  // the parallelogram with a third parallel crank: 3 (5 - 1) - 2 * 6 = 0 by the count, yet the
  // rank of its joint equations leaves one degree of freedom
  const AdmittedFile redundant = ReadAdmittedMechanism(test::TestDataPath("redundant-parallelogram.yaml"), {});
  REQUIRE(redundant.notes.size() == 1);
  CHECK_THAT(redundant.notes[0], Catch::Contains("overconstrained but consistent"));
  CHECK(Model::Load(test::TestDataPath("redundant-parallelogram.yaml")).notes() == redundant.notes);
  CHECK(Model::Load(test::CatalogEntryPath("crank-rocker")).notes().empty());
}

TEST_CASE("Model::With admits the mechanism anew; a refused value leaves the model as it was", "[api][admission]") {
  // the redundant parallelogram with its third crank's length as a parameter: at e = 1 (the
  // crank's length) it moves; at e = 1.2 the coupler point E, which circles E0 at radius 1 while
  // the coupler translates, can never be 1.2 from E0, and the count of 0 stands
  std::string text = Text(test::TestDataPath("redundant-parallelogram.yaml"));
  text.replace(text.find("links:"), 6, "parameters: {e: 1}\nlinks:");
  text.replace(text.find("E: [1, 0]"), 9, "E: [e, 0]");
  const Model m = Model::Parse(text, "third-crank.yaml");
  REQUIRE(m.notes().size() == 1);
  const Diagnostic d = Refusal([&] { (void)m.With("e", "1.2"); });
  CHECK(d.path == "drive");
  CHECK_THAT(d.message, Catch::Contains("mobility 0"));
  CHECK(m.parameters() == std::vector<std::pair<std::string, double>>{{"e", 1.0}});
  CHECK(m.notes().size() == 1);
  REQUIRE_NOTHROW(m.With("e", "2/2"));
}

}  // namespace admission_test
