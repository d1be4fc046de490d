#include "card_text.hpp"

#include <cstring>
#include <vector>

namespace koppel {
namespace {

struct Line {
  size_t begin = 0, end = 0;  // [begin, end) without the '\n'
};

std::vector<Line> Lines(const std::string& text) {
  std::vector<Line> lines;
  for (size_t begin = 0; begin <= text.size();) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    lines.push_back({begin, end});
    begin = end + 1;
  }
  return lines;
}

// `catalog:`, then nothing but spaces and a comment
bool IsCardKey(const std::string& text, const Line& line) {
  static const std::string kKey = "catalog:";
  if (text.compare(line.begin, kKey.size(), kKey) != 0 || line.begin + kKey.size() > line.end) return false;
  for (size_t i = line.begin + kKey.size(); i < line.end; ++i) {
    if (text[i] == '#') return i > line.begin + kKey.size();  // a comment needs a space before it
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\r') return false;
  }
  return true;
}

bool Blank(const std::string& text, const Line& line) {
  for (size_t i = line.begin; i < line.end; ++i) {
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\r') return false;
  }
  return true;
}

// Where yaml-cpp may start a token, a quoted scalar: at the line's start, after a blank or one
// of []{},:, right after a quoted scalar, or right after a tag (`!!str"x"` is a quoted scalar to
// yaml-cpp). Elsewhere a quote is a character of a plain scalar ("Grashof's", x'').
bool TokenStart(const std::string& text, const Line& line, size_t i, size_t after_quoted) {
  static const char* const kBefore = " \t[]{},:";
  if (i == line.begin || i == after_quoted || std::strchr(kBefore, text[i - 1]) != nullptr) return true;
  size_t word = i;  // the run of characters before the quote: a tag when it begins with '!'
  while (word > line.begin && std::strchr(kBefore, text[word - 1]) == nullptr) --word;
  return text[word] == '!';
}

// Every quoted scalar and flow collection the line opens closes on it (see BlankCard).
bool ClosesOnItsLine(const std::string& text, const Line& line) {
  int depth = 0;
  size_t after_quoted = std::string::npos;
  for (size_t i = line.begin; i < line.end; ++i) {
    const char c = text[i];
    const bool token_start = TokenStart(text, line, i, after_quoted);
    if (c == '#' && (i == line.begin || text[i - 1] == ' ' || text[i - 1] == '\t')) break;  // a comment
    if (c == '[' || c == '{') ++depth;
    if ((c == ']' || c == '}') && --depth < 0) return false;
    if ((c == '"' || c == '\'') && token_start) {
      // to its closing quote: "\"" escapes in double quotes, '' stands for ' in single ones
      for (++i;; ++i) {
        if (i >= line.end) return false;
        if (c == '"' && text[i] == '\\') {
          ++i;
        } else if (text[i] == c) {
          if (c == '\'' && i + 1 < line.end && text[i + 1] == '\'') ++i;
          else break;
        }
      }
      after_quoted = i + 1;
    }
  }
  return depth == 0;
}

}  // namespace

std::optional<BlankedCard> BlankCard(const std::string& text) {
  const std::vector<Line> lines = Lines(text);
  size_t key = lines.size();
  for (size_t l = 0; l < lines.size(); ++l) {
    if (!IsCardKey(text, lines[l])) continue;
    if (key != lines.size()) return std::nullopt;  // two cards: the reading of the whole says so
    key = l;
  }
  if (key == lines.size()) return std::nullopt;
  size_t next = key + 1;
  for (; next < lines.size(); ++next) {
    const Line& line = lines[next];
    if (Blank(text, line)) continue;
    const char first = text[line.begin];
    if (first == '\t') return std::nullopt;  // no indentation in YAML: where yaml-cpp ends the card is unsure
    if (first != ' ' && first != '#') break;
    if (first != '#' && !ClosesOnItsLine(text, line)) return std::nullopt;
  }
  if (next < lines.size() && (text.compare(lines[next].begin, 3, "---") == 0 || text.compare(lines[next].begin, 3, "...") == 0))
    return std::nullopt;
  BlankedCard blanked;
  const size_t from = lines[key].end, to = next < lines.size() ? lines[next].begin : text.size();
  blanked.text.reserve(text.size());
  blanked.text.append(text, 0, from);
  for (size_t i = from; i < to; ++i) {
    if (text[i] == '\n') blanked.text += '\n';
  }
  blanked.text.append(text, to, std::string::npos);
  blanked.key_line = static_cast<int>(key) + 1;
  blanked.next_line = next < lines.size() ? static_cast<int>(next) + 1 : 0;
  return blanked;
}

}  // namespace koppel
