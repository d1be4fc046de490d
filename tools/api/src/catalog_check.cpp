#include "koppel/api/catalog_check.hpp"

#include "catalog_query.hpp"

#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/check.hpp"
#include "koppel/catalog/figure_quantities.hpp"
#include "koppel/core/structure.hpp"

namespace koppel {

namespace {

// the catalog library's enums and the API's, value for value (the words are the library's)
CheckKind LibraryKind(CatalogCheckKind kind) {
  switch (kind) {
    case CatalogCheckKind::kFeatures: return CheckKind::kFeatures;
    case CatalogCheckKind::kEquation: return CheckKind::kEquation;
    case CatalogCheckKind::kFigure: return CheckKind::kFigure;
  }
  return CheckKind::kFeatures;
}
CatalogCheckKind KindShown(CheckKind kind) {
  switch (kind) {
    case CheckKind::kFeatures: return CatalogCheckKind::kFeatures;
    case CheckKind::kEquation: return CatalogCheckKind::kEquation;
    case CheckKind::kFigure: return CatalogCheckKind::kFigure;
  }
  return CatalogCheckKind::kFeatures;
}
CheckStatus LibraryStatus(CatalogCheckStatus status) {
  switch (status) {
    case CatalogCheckStatus::kNotRun: return CheckStatus::kNotRun;
    case CatalogCheckStatus::kPassed: return CheckStatus::kPassed;
    case CatalogCheckStatus::kFailed: return CheckStatus::kFailed;
    case CatalogCheckStatus::kNotComputed: return CheckStatus::kNotComputed;
  }
  return CheckStatus::kNotRun;
}
CatalogCheckStatus StatusShown(CheckStatus status) {
  switch (status) {
    case CheckStatus::kNotRun: return CatalogCheckStatus::kNotRun;
    case CheckStatus::kPassed: return CatalogCheckStatus::kPassed;
    case CheckStatus::kFailed: return CatalogCheckStatus::kFailed;
    case CheckStatus::kNotComputed: return CatalogCheckStatus::kNotComputed;
  }
  return CatalogCheckStatus::kNotRun;
}

CatalogCheck CheckShown(const CheckOutcome& c) {
  CatalogCheck s;
  s.variant = c.variant;
  s.name = c.name;
  s.kind = KindShown(c.kind);
  s.status = StatusShown(c.status);
  s.worst = c.worst;
  s.tolerance = c.tolerance;
  s.ratio = c.Ratio();
  s.value = c.value;
  s.where = c.where;
  s.detail = c.detail;
  return s;
}

CatalogCheckReport ReportShown(const EntryReport& r) {
  CatalogCheckReport s;
  s.id = r.id;
  for (const CheckOutcome& c : r.checks) s.checks.push_back(CheckShown(c));
  s.passed = r.passed();
  s.passed_checks = r.Count(CheckStatus::kPassed);
  if (const CheckOutcome* w = r.Worst()) s.worst = static_cast<int>(w - r.checks.data());
  s.brief = r.Brief();
  return s;
}

// The entries of `ids` (empty: all); the first id the catalog lacks goes to *refused.
std::vector<const CatalogEntry*> EntriesOf(const Catalog& catalog, const std::vector<std::string>& ids, const std::string& directory,
                                           std::string* refused) {
  std::vector<const CatalogEntry*> entries;
  if (ids.empty()) {
    for (const CatalogEntry& e : catalog.entries()) entries.push_back(&e);
  }
  for (const std::string& id : ids) {
    if (const CatalogEntry* e = catalog.Find(id)) {
      entries.push_back(e);
      continue;
    }
    std::vector<std::string> known;
    for (const CatalogEntry& c : catalog.entries()) known.push_back(c.file.id);
    *refused = UnknownCatalogId(id, known, directory);
    return {};
  }
  return entries;
}

// "P_x", "P_y" for a point output's components, the name otherwise
std::string OutputShown(const Mechanism& m, const std::string& output, int component) {
  const int o = m.FindOutput(output);
  return o < 0 ? output : m.outputs[o].ComponentLabel(component);
}

void CardTexts(const CatalogEntry& e, CatalogPage* page) {
  const CatalogCard& c = *e.file.card;
  const Mechanism& m = e.file.mechanism;
  for (const CheckVariant& v : c.variants) page->variants.push_back({v.name, v.overrides});
  page->where = c.where;
  for (const EquationCheck& q : c.equations)
    page->equations.push_back({q.name, q.output, OutputShown(m, q.output, q.component), q.order, q.formula, q.printed, q.note, q.tolerance});
  for (const FigureCheck& f : c.figures)
    page->figures.push_back({f.name, QuantityInfo(f.quantity).name, f.output, f.output.empty() ? "" : OutputShown(m, f.output, f.component),
                             f.args, f.expected, f.degrees, f.tolerance, f.printed, f.note, f.variant});
}

void EntryTexts(const CatalogEntry& e, CatalogPage* page) {
  const CatalogCard& c = *e.file.card;
  const Mechanism& m = e.file.mechanism;
  page->entry = api_detail::HitOf(e);
  page->applications = c.applications;
  page->literature = c.literature;
  page->outputs = c.outputs;
  page->document = c.document;
  page->author = c.author;
  const StructureSummary s = AnalyseStructure(m);
  page->structure = s.formula;
  page->gruebler_mobility = s.gruebler_mobility;
  for (const std::string& o : c.outputs) {
    const int link = OutputLink(m, m.outputs[m.FindOutput(o)]);
    if (link >= 0) page->output_links.emplace_back(o, m.links[link].name);
  }
  page->parameters = e.file.parameters.Values();
  page->input_name = m.drive.input_name;
  page->drive_joint = m.joints[m.drive.joint].name;
  page->input_is_angle = m.InputIsAngle();
  page->from = c.from;
  page->to = c.to;
  page->step = c.step;
  page->mechanism = m;
  page->length_unit = e.file.loads.LengthUnit();
}

}  // namespace

const char* ToString(CatalogCheckKind kind) { return ToString(LibraryKind(kind)); }
const char* ToString(CatalogCheckStatus status) { return ToString(LibraryStatus(status)); }

CatalogChecks CheckCatalog(const std::vector<std::string>& ids, const std::string& directory) {
  const std::string dir = directory.empty() ? DefaultCatalogDirectory() : directory;
  const Catalog catalog = Catalog::Load(dir);
  CatalogChecks out;
  for (const CatalogEntry* e : EntriesOf(catalog, ids, dir, &out.refused)) out.reports.push_back(ReportShown(CheckEntry(e->file.path)));
  return out;
}

CatalogPage ShowCatalogEntry(const std::string& id, const std::string& directory) {
  const std::string dir = directory.empty() ? DefaultCatalogDirectory() : directory;
  const Catalog catalog = Catalog::Load(dir);
  CatalogPage page;
  const std::vector<const CatalogEntry*> found = EntriesOf(catalog, {id}, dir, &page.refused);
  if (found.empty()) return page;
  page.report = ReportShown(CheckEntry(found.front()->file.path));
  EntryTexts(*found.front(), &page);
  CardTexts(*found.front(), &page);
  return page;
}

}  // namespace koppel
