#include "koppel/api/catalog.hpp"

#include "catalog_query.hpp"
#include "display.hpp"

#include "admission.hpp"
#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/classes.hpp"
#include "koppel/catalog/figure_quantities.hpp"

namespace koppel {

namespace {

int CountOf(const std::map<std::string, int>& m, const std::string& key) {
  const auto it = m.find(key);
  return it == m.end() ? 0 : it->second;
}

std::optional<CountRange> Range(const char* field, const std::optional<std::string>& text) {
  if (!text) return std::nullopt;
  const std::optional<CountRange> range = CountRange::Parse(*text);
  if (!range) api_detail::BadInput("catalog query", field, "expected a count or a range such as 4, 4..6, ..6 or 4.., found '" + *text + "'");
  return range;
}

}  // namespace

std::string CatalogDirectory() { return DefaultCatalogDirectory(); }

FeatureQuery ToFeatureQuery(const CatalogQuery& q) {
  FeatureQuery query;
  query.links = Range("links", q.links);
  query.binary = Range("binary", q.binary);
  query.ternary = Range("ternary", q.ternary);
  query.quaternary = Range("quaternary", q.quaternary);
  query.joints = Range("joints", q.joints);
  query.revolute = Range("revolute", q.revolute);
  query.prismatic = Range("prismatic", q.prismatic);
  query.drives = Range("drives", q.drives);
  query.drives_at_frame = Range("drives_at_frame", q.drives_at_frame);
  query.outputs = Range("outputs", q.outputs);
  query.outputs_at_frame = Range("outputs_at_frame", q.outputs_at_frame);
  if (q.kind == "transfer") {
    query.kind = CardKind::kTransfer;
  } else if (q.kind == "guidance") {
    query.kind = CardKind::kGuidance;
  } else if (!q.kind.empty()) {
    api_detail::BadInput("catalog query", "kind", "expected transfer or guidance, found '" + q.kind + "'");
  }
  if (!q.klass.empty() && !IsCatalogClass(q.klass)) {
    // the classes that hold the word (straight-line: straight-line-approximate and -exact), else
    // the one a few edits away (quick-retrun), before the whole list
    std::string names;
    std::vector<std::string> all, near;
    for (const CatalogClass& c : CatalogClasses()) {
      names += std::string(names.empty() ? "" : ", ") + c.name;
      all.push_back(c.name);
      if (std::string(c.name).find(q.klass) != std::string::npos) near.push_back(c.name);
    }
    if (near.empty())
      if (const std::string nearest = NearestCatalogId(q.klass, all); !nearest.empty()) near.push_back(nearest);
    std::string hint;
    for (size_t i = 0; i < near.size(); ++i) hint += (i == 0 ? "did you mean '" : i + 1 == near.size() ? "' or '" : "', '") + near[i];
    if (!hint.empty()) hint += "'?; ";
    api_detail::BadInput("catalog query", "class", "unknown class '" + q.klass + "' (" + hint + "classes: " + names + ")");
  }
  query.klass = q.klass;
  query.motion = q.motion;
  query.text = q.text;
  if (!q.like.empty()) query.like = ReadAdmittedMechanism(q.like, {}).file.mechanism;
  return query;
}

namespace api_detail {

CatalogHit HitOf(const CatalogEntry& e) {
  CatalogHit h;
  h.id = e.file.id;
  h.title_en = e.file.card->title_en;
  h.title_de = e.file.card->title_de;
  h.path = e.file.path;
  h.kind = ToString(e.file.card->kind);
  h.classes = e.classes;
  h.links = e.features.links;
  h.joints = e.features.joints;
  h.revolute = CountOf(e.features.joints_by_type, "D");
  h.prismatic = CountOf(e.features.joints_by_type, "S");
  h.motion = e.file.card->motion;
  const AccessFeatures& f = e.features;
  h.features = {f.drive_joints, f.drive_joints_at_frame, f.output_links, f.output_links_at_frame, f.links, f.joints,
                f.links_by_degree, f.joints_by_type};
  for (const SearchField& field : SearchFieldsOf(e)) h.search_fields.emplace_back(field.text, field.weight);
  return h;
}

}  // namespace api_detail

std::vector<CatalogHit> FindInCatalog(const CatalogQuery& q, const std::string& directory) {
  const FeatureQuery query = ToFeatureQuery(q);
  const Catalog catalog = Catalog::Load(directory.empty() ? DefaultCatalogDirectory() : directory);
  std::vector<CatalogHit> hits;
  for (const CatalogEntry* e : FindEntries(catalog, query)) hits.push_back(api_detail::HitOf(*e));
  return hits;
}

std::vector<CatalogTerm> CatalogClassTerms() {
  std::vector<CatalogTerm> terms;
  for (const CatalogClass& c : CatalogClasses()) terms.push_back({c.name, c.meaning});
  return terms;
}

std::vector<CatalogTerm> FigureQuantityTerms() {
  std::vector<CatalogTerm> terms;
  for (const FigureQuantityInfo& q : FigureQuantities()) terms.push_back({q.name, q.meaning});
  return terms;
}

}  // namespace koppel
