// The catalog's free-text search (catalog find --text, the Python module's catalog_find): one query
// over an entry's id, titles (German, English), classes, keywords, motion and applications.
// Case, hyphens, spaces and other punctuation are ignored, and so are umlauts: ä, ae and a are one
// letter (ö, ü alike), ß is ss; "Geradfuehrung", "geradführung" and "Geradfuhrung" are one word.
// Every word of a query must occur, each in any field; a word or phrase of the bilingual synonym
// table also finds its other names ("Rast" finds "dwell", "dead center" finds "Totlage" and
// "deadcentre"). Entries are ranked by where their words occur (SearchScore).
#pragma once

#include <string>
#include <vector>

namespace koppel {

// The form query and text are compared in: lower case, umlauts and ae/oe/ue folded to their
// vowel, ß to ss, every ASCII character that is neither letter nor digit dropped.
std::string FoldForSearch(const std::string& text);

// The synonym table: each group names one concept, in English and German (a few spellings).
const std::vector<std::vector<std::string>>& SearchSynonyms();

struct SearchField {
  std::string text;
  int weight = 1;  // what a word found here adds to the rank
};

// 0 when a word of `query` occurs in no field; else, summed over the query's words, the weight of
// the heaviest field holding it (or one of its synonyms). An empty query scores 1.
int SearchScore(const std::vector<SearchField>& fields, const std::string& query);

}  // namespace koppel
