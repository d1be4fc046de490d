// The one definition of a printable character (core/src/printable_text.cpp). The references:
// Unicode 15 table 3-7 (well-formed UTF-8 byte sequences) for what is valid UTF-8, ISO 6429 for
// the control characters C0 (U+0000..U+001F), DEL (U+007F) and C1 (U+0080..U+009F), and XML 1.0
// section 2.2 (Char) for the non-characters U+FFFE and U+FFFF.
#include "koppel/core/printable_text.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace koppel::printable_text_test {

TEST_CASE("Printable text: letters of any script, punctuation and markup characters", "[printable_text]") {
  for (const std::string text : {"crank", "s, mm", "Schieber \xC3\x84", "\xCF\x86 [deg]", "<!--<script>", "=HYPERLINK(\"x\")",
                                 "\xE2\x9C\x93", "\xF0\x9F\x94\xA7", "\xEF\xBF\xBD", "\xE2\x80\xA8", ""}) {
    CAPTURE(text);
    CHECK_FALSE(FirstUnprintable(text).has_value());
    CHECK(PrintableText(text, Replacement::kReplacementCharacter) == text);
    CHECK(PrintableText(text, Replacement::kEscape) == text);
  }
}

TEST_CASE("Control characters are found where they are, with their code point", "[printable_text]") {
  struct Case {
    std::string text;
    std::size_t offset, length;
    std::uint32_t code_point;
  };
  for (const Case& c : {Case{std::string("crank\0", 6), 5, 1, 0x00}, Case{"a\x1b[31m", 1, 1, 0x1B}, Case{"bell\x07", 4, 1, 0x07},
                        Case{"tab\there", 3, 1, 0x09}, Case{"line\nbreak", 4, 1, 0x0A}, Case{"del\x7f", 3, 1, 0x7F},
                        Case{"c1 \xC2\x85", 3, 2, 0x85}, Case{"c1 \xC2\x9F", 3, 2, 0x9F}, Case{"\xEF\xBF\xBE", 0, 3, 0xFFFE},
                        Case{"x\xEF\xBF\xBF", 1, 3, 0xFFFF}}) {
    CAPTURE(c.text);
    const std::optional<Unprintable> u = FirstUnprintable(c.text);
    REQUIRE(u.has_value());
    CHECK(u->offset == c.offset);
    CHECK(u->length == c.length);
    CHECK(u->code_point == c.code_point);
    CHECK(u->valid_utf8);
  }
  CHECK(FirstUnprintable("a\x1b")->Describe() == "U+001B");
  // U+00A0 (no-break space), the first character after C1, is printable
  CHECK_FALSE(FirstUnprintable("\xC2\xA0").has_value());
}

TEST_CASE("Bytes that are not well-formed UTF-8 are unprintable, one byte at a time", "[printable_text]") {
  // Latin-1, a lone continuation byte, overlong forms of '/' and of U+0800, a surrogate (U+D800),
  // above U+10FFFF, and sequences cut short (at the end, and before an ASCII letter)
  for (const std::string text : {"Gr\xFC", "\x80", "\xC0\xAF", "\xE0\x80\x80", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\xF5\x80\x80\x80",
                                 "\xE2\x82", "\xE2\x82x", "\xFF"}) {
    CAPTURE(text);
    const std::optional<Unprintable> u = FirstUnprintable(text);
    REQUIRE(u.has_value());
    CHECK_FALSE(u->valid_utf8);
    CHECK(u->length == 1);
  }
  CHECK(FirstUnprintable("Gr\xFC")->offset == 2);
  CHECK(FirstUnprintable("Gr\xFC")->Describe() == "the byte 0xFC (not UTF-8)");
}

TEST_CASE("PrintableText replaces what is not printable and keeps what it is told", "[printable_text]") {
  CHECK(PrintableText(std::string("crank\0\x1b", 7), Replacement::kEscape) == "crank\\x00\\x1B");
  CHECK(PrintableText("c1 \xC2\x85!", Replacement::kEscape) == "c1 \\u0085!");
  CHECK(PrintableText("Gr\xFC\xDF", Replacement::kEscape) == "Gr\\xFC\\xDF");
  // U+FFFD in UTF-8 for each character, and each byte of a sequence that is not UTF-8
  CHECK(PrintableText("a\x07z\xC2\x85", Replacement::kReplacementCharacter) == "a\xEF\xBF\xBDz\xEF\xBF\xBD");
  CHECK(PrintableText("\xE2\x82x", Replacement::kReplacementCharacter) == "\xEF\xBF\xBD\xEF\xBF\xBDx");
  // kept: only the ASCII characters named
  CHECK(PrintableText("a\tb\nc\rd", Replacement::kEscape, "\t\n") == "a\tb\nc\\x0Dd");
  CHECK_FALSE(FirstUnprintable("a\tb\nc", "\t\n").has_value());
}

}  // namespace koppel::printable_text_test
