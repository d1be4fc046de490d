#include "koppel/catalog/text_search.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace koppel {
namespace {

// The folded vowel of a two-byte UTF-8 umlaut (C3 xx), or 0.
char FoldedUmlaut(unsigned char second) {
  switch (second) {
    case 0xA4: case 0x84: return 'a';  // ä Ä
    case 0xB6: case 0x96: return 'o';  // ö Ö
    case 0xBC: case 0x9C: return 'u';  // ü Ü
    default: return 0;
  }
}

// One term of a query: the words it may be found as (folded), any of them.
using Term = std::vector<std::string>;

// The synonym group holding `folded`, folded; or `folded` alone.
Term Alternatives(const std::string& folded) {
  for (const std::vector<std::string>& group : SearchSynonyms()) {
    Term term;
    for (const std::string& name : group) term.push_back(FoldForSearch(name));
    if (std::find(term.begin(), term.end(), folded) != term.end()) return term;
  }
  return {folded};
}

// The query's terms: its words, where two or three adjacent words that name a synonym together
// ("dead center", "quick return") one term.
std::vector<Term> Terms(const std::string& query) {
  std::vector<std::string> words;
  std::istringstream in(query);
  for (std::string w; in >> w;)
    if (!FoldForSearch(w).empty()) words.push_back(w);
  std::vector<Term> terms;
  for (size_t i = 0; i < words.size();) {
    size_t span = 1;
    for (size_t n = std::min<size_t>(3, words.size() - i); n > 1 && span == 1; --n) {
      std::string joined;
      for (size_t k = i; k < i + n; ++k) joined += words[k];
      if (Alternatives(FoldForSearch(joined)).size() > 1) span = n;
    }
    std::string joined;
    for (size_t k = i; k < i + span; ++k) joined += words[k];
    terms.push_back(Alternatives(FoldForSearch(joined)));
    i += span;
  }
  return terms;
}

}  // namespace

std::string FoldForSearch(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = text[i];
    if (c == 0xC3 && i + 1 < text.size()) {
      const unsigned char second = text[i + 1];
      if (const char vowel = FoldedUmlaut(second)) {
        out += vowel;
        ++i;
        continue;
      }
      if (second == 0x9F) {  // ß
        out += "ss";
        ++i;
        continue;
      }
    }
    if (c >= 0x80) out += static_cast<char>(c);
    else if (std::isalnum(c)) out += static_cast<char>(std::tolower(c));
  }
  // ae, oe, ue: the umlaut written without its dots, folded as the umlaut is
  std::string folded;
  for (size_t i = 0; i < out.size(); ++i) {
    folded += out[i];
    if (i + 1 < out.size() && out[i + 1] == 'e' && (out[i] == 'a' || out[i] == 'o' || out[i] == 'u')) ++i;
  }
  return folded;
}

const std::vector<std::vector<std::string>>& SearchSynonyms() {
  static const std::vector<std::vector<std::string>> groups = {
      {"dwell", "Rast", "Rastgetriebe", "Stillstand"},
      {"quick return", "quick-return", "Eilrücklauf"},
      {"straight line", "straight-line", "Geradführung"},
      {"toggle", "Kniehebel"},
      {"dead centre", "dead center", "dead point", "Totlage", "deadcentre"},
      {"centre", "center"},
      {"coupler curve", "Koppelkurve"},
      {"function generator", "function generation", "Funktionsgetriebe"},
      {"motion generation", "rigid-body guidance", "Führungsgetriebe"},
      {"inversion", "Umkehrung"},
      {"crank-rocker", "Kurbelschwinge"},
      {"double-rocker", "Doppelschwinge"},
      {"double crank", "Doppelkurbel", "drag link"},
      {"slider-crank", "Schubkurbel"},
      {"slotted link", "Kurbelschleife", "Schleife"},
      {"swinging block", "Schwingschleife"},
      {"coupler", "Koppel"},
      {"crank", "Kurbel"},
      {"rocker", "Schwinge"},
      {"slider", "Schieber"},
      {"frame", "Gestell"},
      {"wiper", "Scheibenwischer"},
      {"steering", "Lenkung", "Lenkgetriebe"},
      {"hydraulic", "hydraulisch", "Hydraulik"},
      {"pump", "Pumpe"},
      {"press", "Presse"},
      {"engine", "Motor"},
      {"walking", "Laufmaschine", "Schreitwerk"},
      {"shaper", "shaping machine", "Stoßmaschine"},
      {"parallel guidance", "Parallelführung"},
      {"transmission angle", "Übertragungswinkel"},
  };
  return groups;
}

int SearchScore(const std::vector<SearchField>& fields, const std::string& query) {
  const std::vector<Term> terms = Terms(query);
  if (terms.empty()) return 1;
  std::vector<std::string> folded;
  for (const SearchField& f : fields) folded.push_back(FoldForSearch(f.text));
  int score = 0;
  for (const Term& term : terms) {
    int best = 0;
    for (size_t f = 0; f < fields.size(); ++f)
      for (const std::string& word : term)
        if (folded[f].find(word) != std::string::npos) best = std::max(best, fields[f].weight);
    if (best == 0) return 0;
    score += best;
  }
  return score;
}

}  // namespace koppel
