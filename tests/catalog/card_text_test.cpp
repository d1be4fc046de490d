// The card blanked out of a mechanism file's text (card_text.hpp) on hand-written texts: the
// lines kept are the file's, in their places, `catalog:` among them; where the card's extent is not plain from the
// characters, nothing is blanked (the reading of the whole text decides).
#include "card_text.hpp"

#include <catch2/catch.hpp>

namespace koppel::card_text_test {

TEST_CASE("a card's lines are emptied, every other line kept in its place", "[card]") {
  const std::string text = "name: m\ncatalog:  # the card\n  title: {en: \"it's\", de: 'l''x'}\n\n# a note\n  kind: transfer\nsweep: {to: 90}\n";
  const std::optional<BlankedCard> b = BlankCard(text);
  REQUIRE(b);
  CHECK(b->text == "name: m\ncatalog:  # the card\n\n\n\n\nsweep: {to: 90}\n");
  CHECK(b->key_line == 2);
  CHECK(b->next_line == 7);
  // a card that ends the text; an apostrophe in a scalar (x'') and a '#' in a word open nothing
  const std::optional<BlankedCard> last = BlankCard("name: m\ncatalog:\n  motion: Grashof's C# [1] x'' (x)'\n");
  REQUIRE(last);
  CHECK(last->text == "name: m\ncatalog:\n\n");
  CHECK(last->next_line == 0);
}

TEST_CASE("a card whose extent is not plain from the characters is not blanked", "[card]") {
  CHECK_FALSE(BlankCard("name: m\nsweep: {to: 90}\n"));                                  // no card
  CHECK_FALSE(BlankCard("catalog: {kind: transfer}\nname: m\n"));                         // not a block
  CHECK_FALSE(BlankCard("catalog:\n  a: 1\ncatalog:\n  b: 2\nname: m\n"));                // two
  CHECK_FALSE(BlankCard("catalog:\n  note: \"runs\nname: on\"\nname: m\n"));              // a quote open at the line's end
  CHECK_FALSE(BlankCard("catalog:\n  note: 'runs\nname: on'\n"));
  CHECK_FALSE(BlankCard("catalog:\n  note: \"a \\\" b\nname: m\n"));                      // an escaped quote closes nothing
  CHECK_FALSE(BlankCard("catalog:\n  list: [1,\nname: 2]\n"));                            // a flow collection open
  CHECK_FALSE(BlankCard("catalog:\n  list: [1]'x\nname: m\n"));                           // a quote after a bracket opens
  CHECK_FALSE(BlankCard("catalog:\n  a: {b:'x\nname: m\n"));
  CHECK_FALSE(BlankCard("catalog:\n  a: !!str\"x\nname: m\"\n"));                        // after a tag (yaml-cpp reads "x..." on)
  CHECK_FALSE(BlankCard("catalog:\n  a: \"x\"'y\nname: m\n"));                           // right after a quoted scalar
  CHECK_FALSE(BlankCard("catalog:\n  see: x]\nname: m\n"));                               // a bracket closed before it opens
  CHECK_FALSE(BlankCard("catalog:\n\tkind: transfer\nname: m\n"));                        // a tab where yaml-cpp's end is unsure
  CHECK_FALSE(BlankCard("catalog:\n  kind: transfer\n---\nname: m\n"));                   // a document marker after it
  CHECK_FALSE(BlankCard("catalog:#x\n  kind: transfer\n"));                               // the key `catalog:#x`
  // a comment may hold anything
  CHECK(BlankCard("catalog:\n  kind: transfer  # \"it's [\nname: m\n"));
}

}  // namespace koppel::card_text_test
