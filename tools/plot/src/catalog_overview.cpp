#include "koppel/plot/catalog_overview.hpp"

#include "koppel/plot/scheme_drawing.hpp"
#include "koppel/plot/svg.hpp"
#include "plot_support.hpp"

#include <nlohmann/json.hpp>

#include <string>

#ifndef KOPPEL_CATALOG_SEARCH
#define KOPPEL_CATALOG_SEARCH 0
#endif

namespace koppel::plot {
namespace catalog_assets {
extern const char* const k_template;
extern const char* const k_script;
#if KOPPEL_CATALOG_SEARCH
extern const char* const k_module;
#endif
}  // namespace catalog_assets

namespace {

// the scheme at the assembly's input over the file's sweep; empty and a problem when it cannot be drawn
std::string SchemeOf(const CatalogHit& hit, std::string* problem) {
  try {
    const SchemeDrawing drawing = DrawSchemeOf(hit.Load(), SchemeRequest{});
    if (drawing.status == PlotStatus::kFailed) *problem = drawing.message;
    return drawing.svg;
  } catch (const InputError& error) {
    *problem = error.what();
    return "";
  }
}

std::string Card(const CatalogHit& hit, const std::string& scheme, const std::string& problem) {
  std::string classes;
  for (const std::string& c : hit.classes) classes += (classes.empty() ? "" : ", ") + c;
  return "<section class=\"entry\" id=\"" + EscapeXml(hit.id) + "\"><h2>" + EscapeXml(hit.title_en) + "</h2><h3>" + EscapeXml(hit.title_de) +
         "</h3>" + scheme + (problem.empty() ? "" : "<p class=\"problem\">No scheme: " + EscapeXml(problem) + "</p>") +
         "<div class=\"id\">" + EscapeXml(hit.id) + "</div><div class=\"classes\">" + EscapeXml(classes) + "</div><div class=\"motion\">" +
         EscapeXml(hit.motion) + "</div></section>\n";
}

// the fields as JSON inside a script element: "</" written as "<\/" so that no text closes it
std::string FieldsJson(const std::vector<CatalogHit>& entries) {
  nlohmann::json all = nlohmann::json::array();
  for (const CatalogHit& hit : entries) {
    nlohmann::json fields = nlohmann::json::array();
    for (auto [text, weight] : hit.search_fields) {
      for (char& c : text) {
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';  // the module reads a field a line, weight and text split by a tab
      }
      fields.push_back({text, weight});
    }
    all.push_back(fields);
  }
  std::string text = all.dump();
  for (size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) text.replace(at, 2, "<\\/");
  return text;
}

}  // namespace

bool CatalogSearchAvailable() { return KOPPEL_CATALOG_SEARCH != 0; }

CatalogOverview CatalogOverviewPage(const std::vector<CatalogHit>& entries) {
  CatalogOverview page;
  std::string cards;
  for (const CatalogHit& hit : entries) {
    std::string problem;
    const std::string scheme = SchemeOf(hit, &problem);
    if (!problem.empty()) page.problems.push_back(hit.id + ": " + problem);
    cards += Card(hit, scheme, problem);
  }
  const std::string summary = std::to_string(entries.size()) +
                              " documented mechanisms, each drawn at its assembly's input. The search finds words in the id, the titles "
                              "(English or German), the classes, keywords, motion and applications, as koppel catalog find --text does.";
#if KOPPEL_CATALOG_SEARCH
  const std::string module = catalog_assets::k_module;
#else
  const std::string module;
#endif
  page.html = Fill(catalog_assets::k_template,
                   {{"SUMMARY", EscapeXml(summary)}, {"ENTRIES", cards}, {"FIELDS", FieldsJson(entries)}, {"MODULE", module}, {"SCRIPT", catalog_assets::k_script}});
  return page;
}

}  // namespace koppel::plot
