// The catalog page's search box: the catalog library's own SearchScore (text_search.hpp) compiled
// by em++, so that the page finds, offline, what `koppel catalog find --text` finds and ranks it
// the same way: one search, not a second one written in JavaScript.
#include "koppel/catalog/text_search.hpp"

#include <emscripten/emscripten.h>

#include <cstdlib>
#include <string>
#include <vector>

// `fields`: an entry's search fields, one a line, "<weight>\t<text>" (CatalogHit::search_fields,
// written by the page without tabs or line breaks in the text). The score as SearchScore: 0 when
// a word of `query` occurs in no field.
extern "C" EMSCRIPTEN_KEEPALIVE int koppel_search_score(const char* fields, const char* query) {
  std::vector<koppel::SearchField> parsed;
  const std::string all(fields);
  size_t start = 0;
  while (start < all.size()) {
    size_t end = all.find('\n', start);
    if (end == std::string::npos) end = all.size();
    const size_t tab = all.find('\t', start);
    if (tab != std::string::npos && tab < end)
      parsed.push_back({all.substr(tab + 1, end - tab - 1), static_cast<int>(std::strtol(all.c_str() + start, nullptr, 10))});
    start = end + 1;
  }
  return koppel::SearchScore(parsed, query);
}
