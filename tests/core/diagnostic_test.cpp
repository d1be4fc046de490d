// Diagnostic's one-line form (file:line:column: message (key path)) and InputError's what(),
// which every front door prints: the reference is the format the README's error examples show.
#include "koppel/core/diagnostic.hpp"

#include <catch2/catch.hpp>

namespace koppel::diagnostic_test {

TEST_CASE("A diagnostic names the file, line, column and key path it knows", "[diagnostic]") {
  CHECK(Diagnostic{"mech.yaml", 12, 7, "joints.A.links[1]", "joint 'A' names unknown link 'crank2'"}.ToString() ==
        "mech.yaml:12:7: joint 'A' names unknown link 'crank2' (joints.A.links[1])");
  // no column: file:line; no line: the file alone (a column without a line means nothing)
  CHECK(Diagnostic{"mech.yaml", 3, 0, "", "missing"}.ToString() == "mech.yaml:3: missing");
  CHECK(Diagnostic{"mech.yaml", 0, 5, "", "unreadable"}.ToString() == "mech.yaml: unreadable");
}

TEST_CASE("A diagnostic never sends a control character to the terminal", "[diagnostic]") {
  // a name with ESC (a colour change) and BEL, in the message and in the key path: shown escaped;
  // the message's own line breaks stay
  const Diagnostic d{"mech.yaml", 4, 3, "links.crank\x1b[31m", "link 'crank\x1b[31m\x07' is bad\nsecond line"};
  CHECK(d.ToString() == "mech.yaml:4:3: link 'crank\\x1B[31m\\x07' is bad\nsecond line (links.crank\\x1B[31m)");
  // bytes that are not UTF-8 (a name in Latin-1) are escaped too; UTF-8 letters stay
  CHECK(Diagnostic{"m.yaml", 1, 1, "", "Gr\xfc\xdf" "e, Grüße"}.ToString() == "m.yaml:1:1: Gr\\xFC\\xDFe, Grüße");
}

TEST_CASE("An input error keeps every diagnostic and says them one a line", "[diagnostic]") {
  const InputError e({{"a.yaml", 1, 2, "x", "first"}, {"a.yaml", 3, 4, "", "second"}});
  REQUIRE(e.diagnostics().size() == 2);
  CHECK(e.diagnostics()[1].message == "second");
  CHECK(std::string(e.what()) == "a.yaml:1:2: first (x)\na.yaml:3:4: second");
}

}  // namespace koppel::diagnostic_test
