// ASCII lower case for the catalog's word matching (classes, ids): bytes of UTF-8 letters are
// left as they are, so "Schwinge" and "schwinge" match and "ü" stays "ü". Private to the catalog.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace koppel {

inline std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace koppel
