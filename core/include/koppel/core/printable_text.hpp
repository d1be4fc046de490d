// What may be shown of a text that came from a file or a caller: the one definition of a
// printable character, used by the reader's rule for names (catalog) and by every writer that
// must not pass a control character on (diagnostics, CSV, SVG/XML). Printable: valid UTF-8
// (no overlong form, no surrogate, nothing above U+10FFFF) and none of the control characters
// C0 (U+0000..U+001F), DEL (U+007F), C1 (U+0080..U+009F) nor the non-characters U+FFFE, U+FFFF
// (which XML 1.0 forbids too).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace koppel {

// The first character of a text that is not printable: where it starts (bytes), how many bytes
// it takes (1 for a byte that is not valid UTF-8), and its code point (the byte itself when not
// valid UTF-8, with `valid_utf8` false).
struct Unprintable {
  std::size_t offset = 0;
  std::size_t length = 1;
  std::uint32_t code_point = 0;
  bool valid_utf8 = true;
  // "U+001B" for a control character, "the byte 0xFF (not UTF-8)" for an invalid byte
  std::string Describe() const;
};

// Nothing when every character of `text` is printable; ASCII characters in `keep` (e.g. "\n")
// count as printable.
std::optional<Unprintable> FirstUnprintable(std::string_view text, std::string_view keep = {});

// How an unprintable character is written instead.
enum class Replacement {
  kReplacementCharacter,  // U+FFFD (in UTF-8), for text meant to be read back (CSV, SVG)
  kEscape,                // "\x1B", "\u0085", "\xFF" (an invalid byte), for messages to a person
};

// `text` with every unprintable character (each byte of an invalid sequence) replaced; ASCII
// characters in `keep` stay as they are.
std::string PrintableText(std::string_view text, Replacement replacement, std::string_view keep = {});

}  // namespace koppel
