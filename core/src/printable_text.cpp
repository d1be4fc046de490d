#include "koppel/core/printable_text.hpp"

#include <cstdio>

namespace koppel {
namespace {

struct Decoded {
  std::uint32_t code_point;
  std::size_t length;  // 0: the byte at the start is not valid UTF-8
};

// One UTF-8 sequence at `at`, by the table of well-formed sequences (Unicode 15, table 3-7).
Decoded Decode(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[at + i]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80) return {lead, 1};
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
  std::uint32_t cp = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2, cp = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3, cp = lead & 0x0F;
    if (lead == 0xE0) low = 0xA0;   // no overlong form
    if (lead == 0xED) high = 0x9F;  // no surrogate
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4, cp = lead & 0x07;
    if (lead == 0xF0) low = 0x90;   // no overlong form
    if (lead == 0xF4) high = 0x8F;  // nothing above U+10FFFF
  } else {
    return {lead, 0};
  }
  if (at + length > text.size()) return {lead, 0};
  for (std::size_t i = 1; i < length; ++i) {
    const unsigned char b = byte(i);
    if (b < (i == 1 ? low : 0x80) || b > (i == 1 ? high : 0xBF)) return {lead, 0};
    cp = cp << 6 | (b & 0x3F);
  }
  return {cp, length};
}

bool IsControlOrNonCharacter(std::uint32_t cp) { return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0xFFFE || cp == 0xFFFF; }

// The unprintable character at `at`, if it is one; `decoded` is its decoding.
std::optional<Unprintable> UnprintableAt(std::size_t at, const Decoded& decoded, std::string_view keep) {
  if (decoded.length == 0) return Unprintable{at, 1, decoded.code_point, false};
  if (!IsControlOrNonCharacter(decoded.code_point)) return std::nullopt;
  if (decoded.code_point < 0x80 && keep.find(static_cast<char>(decoded.code_point)) != std::string_view::npos) return std::nullopt;
  return Unprintable{at, decoded.length, decoded.code_point, true};
}

std::string Escaped(const Unprintable& u) {
  char buffer[16];
  if (!u.valid_utf8 || u.code_point < 0x80) {
    std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(u.code_point));
  } else {
    std::snprintf(buffer, sizeof buffer, "\\u%04X", static_cast<unsigned>(u.code_point));
  }
  return buffer;
}

}  // namespace

std::string Unprintable::Describe() const {
  char buffer[40];
  if (valid_utf8) {
    std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(code_point));
  } else {
    std::snprintf(buffer, sizeof buffer, "the byte 0x%02X (not UTF-8)", static_cast<unsigned>(code_point));
  }
  return buffer;
}

std::optional<Unprintable> FirstUnprintable(std::string_view text, std::string_view keep) {
  for (std::size_t at = 0; at < text.size();) {
    const Decoded decoded = Decode(text, at);
    if (auto u = UnprintableAt(at, decoded, keep)) return u;
    at += decoded.length;
  }
  return std::nullopt;
}

std::string PrintableText(std::string_view text, Replacement replacement, std::string_view keep) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const Decoded decoded = Decode(text, at);
    const std::optional<Unprintable> u = UnprintableAt(at, decoded, keep);
    if (!u) {
      out.append(text.substr(at, decoded.length));
    } else {
      out += replacement == Replacement::kEscape ? Escaped(*u) : "\xEF\xBF\xBD";  // U+FFFD
    }
    at += u ? u->length : decoded.length;
  }
  return out;
}

}  // namespace koppel
