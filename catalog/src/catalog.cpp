#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/text_search.hpp"
#include "koppel/core/module.hpp"

#include "koppel/catalog/check.hpp"
#include "koppel/catalog/classes.hpp"

#include "yaml_reader.hpp"
#include "lower_case.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>


#ifndef KOPPEL_CATALOG_DIR
#define KOPPEL_CATALOG_DIR "catalog/entries"
#endif
#ifndef KOPPEL_INSTALLED_CATALOG
#define KOPPEL_INSTALLED_CATALOG "../share/koppel/catalog"
#endif
#ifndef KOPPEL_INSTALL_PREFIX_CATALOG
#define KOPPEL_INSTALL_PREFIX_CATALOG "/usr/local/share/koppel/catalog"
#endif

namespace koppel {
namespace {

// Declared values win (they are what the document lists, and `check` proves them equal to the
// computed ones); computed values fill what the card leaves out.
AccessFeatures Merge(const AccessFeatures& declared, const AccessFeatures& computed) {
  AccessFeatures f = computed;
  auto take = [](int d, int& c) { if (d >= 0) c = d; };
  take(declared.drive_joints, f.drive_joints);
  take(declared.drive_joints_at_frame, f.drive_joints_at_frame);
  take(declared.output_links, f.output_links);
  take(declared.output_links_at_frame, f.output_links_at_frame);
  take(declared.links, f.links);
  take(declared.joints, f.joints);
  if (!declared.links_by_degree.empty()) f.links_by_degree = declared.links_by_degree;
  if (!declared.joints_by_type.empty()) f.joints_by_type = declared.joints_by_type;
  return f;
}

int CountOf(const std::map<int, int>& m, int key) {
  const auto it = m.find(key);
  return it == m.end() ? 0 : it->second;
}
int CountOf(const std::map<std::string, int>& m, const std::string& key) {
  const auto it = m.find(key);
  return it == m.end() ? 0 : it->second;
}

}  // namespace

namespace {

// The catalog installed with this library (cmake --install): DATADIR/koppel/catalog under the
// nearest of InstallRoots() that has one (koppel/core/module.hpp: from the file that holds this
// code upwards, then the prefix of a program built against the installed tree), so that an
// installed koppel, the Python module and any program built against the installed tree find it
// wherever the tree was installed or moved to. Empty in a build tree.
std::string InstalledCatalogDirectory() {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const std::string& root : InstallRoots()) {
    const fs::path catalog = fs::path(root) / KOPPEL_INSTALLED_CATALOG;
    if (fs::is_directory(catalog, ec)) return catalog.lexically_normal().string();
  }
  return {};
}

}  // namespace

std::string DefaultCatalogDirectory() {
  if (const char* env = std::getenv("KOPPEL_CATALOG"); env && *env) return env;
  if (std::string installed = InstalledCatalogDirectory(); !installed.empty()) return installed;
  // a build tree: the source tree it was built from; a koppel whose libraries were copied away
  // from their data (neither found): the data under the install prefix it was configured for
  std::error_code ec;
  if (!std::filesystem::is_directory(KOPPEL_CATALOG_DIR, ec) && std::filesystem::is_directory(KOPPEL_INSTALL_PREFIX_CATALOG, ec))
    return KOPPEL_INSTALL_PREFIX_CATALOG;
  return KOPPEL_CATALOG_DIR;
}

namespace {

bool LooksLikeId(const std::string& name) {
  if (name.empty() || name.size() > 200) return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '-' || c == '_'; });
}

}  // namespace

std::string CatalogEntryFile(const std::string& id, const std::string& directory) {
  namespace fs = std::filesystem;
  if (!LooksLikeId(id)) return "";
  std::error_code ec;
  const fs::path entry = fs::path(directory.empty() ? DefaultCatalogDirectory() : directory) / (id + ".yaml");
  return fs::is_regular_file(entry, ec) ? entry.string() : "";
}

std::string ResolveMechanismName(const std::string& name, const std::string& directory) {
  std::error_code ec;
  if (!LooksLikeId(name) || std::filesystem::exists(name, ec)) return name;
  const std::string entry = CatalogEntryFile(name, directory);
  return entry.empty() ? name : entry;
}

std::vector<std::string> CatalogIds(const std::string& directory) {
  namespace fs = std::filesystem;
  std::vector<std::string> ids;
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".yaml") ids.push_back(it->path().stem().string());
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::string NearestCatalogId(const std::string& id, const std::vector<std::string>& ids) {
  std::vector<std::string> lower;
  for (const std::string& i : ids) lower.push_back(Lower(i));
  const std::string nearest = Nearest(Lower(id), lower);
  if (nearest.empty()) return "";
  return ids[std::find(lower.begin(), lower.end(), nearest) - lower.begin()];
}

std::string UnknownCatalogId(const std::string& id, const std::vector<std::string>& ids, const std::string& directory) {
  if (const std::string near = NearestCatalogId(id, ids); !near.empty())
    return "no catalog entry '" + id + "' (did you mean '" + near + "'?)";
  return "no catalog entry '" + id + "' in " + directory + " (`koppel catalog list` lists them)";
}

Catalog Catalog::Load(const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(directory, ec))
    throw InputError({Diagnostic{directory, 0, 0, "", "catalog directory does not exist"}});
  std::vector<std::string> paths;
  for (const auto& item : fs::directory_iterator(directory, ec)) {
    if (item.is_regular_file() && item.path().extension() == ".yaml") paths.push_back(item.path().string());
  }
  std::sort(paths.begin(), paths.end());
  Catalog catalog;
  std::vector<Diagnostic> problems;
  for (const std::string& path : paths) {
    try {
      MechanismFile file = ReadMechanismFile(path);
      if (!file.card) {
        problems.push_back({path, 1, 1, "catalog", "catalog entry has no 'catalog' section"});
        continue;
      }
      if (const std::string stem = fs::path(path).stem().string(); file.id != stem) {
        problems.push_back({path, 1, 1, "name",
                            "the id '" + file.id + "' is not the file's name '" + stem + "' (an entry's file is named by its id: " + file.id + ".yaml)"});
        continue;
      }
      if (catalog.Find(file.id)) {
        problems.push_back({path, 1, 1, "name", "id '" + file.id + "' is used by another entry"});
        continue;
      }
      const AccessFeatures computed = ComputeFeatures(file.mechanism, file.card->outputs);
      AccessFeatures merged = Merge(file.card->declared, computed);
      std::vector<std::string> classes = file.card->classes;
      for (const std::string& c : ComputedClasses(file.mechanism)) {
        if (std::find(classes.begin(), classes.end(), c) == classes.end()) classes.push_back(c);
      }
      catalog.entries_.push_back({std::move(file), std::move(merged), std::move(classes)});
    } catch (const InputError& e) {
      problems.insert(problems.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
  }
  if (!problems.empty()) throw InputError(problems);
  return catalog;
}

const CatalogEntry* Catalog::Find(const std::string& id) const {
  for (const CatalogEntry& e : entries_) {
    if (e.file.id == id) return &e;
  }
  return nullptr;
}

std::optional<CountRange> CountRange::Parse(const std::string& text) {
  auto number = [](const std::string& s, int& out) {
    if (s.empty() || s.size() > 6 || !std::all_of(s.begin(), s.end(), ::isdigit)) return false;
    out = std::stoi(s);
    return true;
  };
  CountRange r;
  const auto dots = text.find("..");
  if (dots == std::string::npos) {
    if (!number(text, r.lo)) return std::nullopt;
    r.hi = r.lo;
    return r;
  }
  const std::string lo = text.substr(0, dots), hi = text.substr(dots + 2);
  if (lo.empty() && hi.empty()) return std::nullopt;
  if (!lo.empty() && !number(lo, r.lo)) return std::nullopt;
  if (!hi.empty() && !number(hi, r.hi)) return std::nullopt;
  if (r.lo > r.hi) return std::nullopt;
  return r;
}

bool Matches(const CatalogEntry& entry, const FeatureQuery& q) {
  const AccessFeatures& f = entry.features;
  auto ok = [](const std::optional<CountRange>& r, int value) { return !r || r->Contains(value); };
  if (!ok(q.links, f.links) || !ok(q.joints, f.joints)) return false;
  if (!ok(q.binary, CountOf(f.links_by_degree, 2)) || !ok(q.ternary, CountOf(f.links_by_degree, 3)) ||
      !ok(q.quaternary, CountOf(f.links_by_degree, 4)))
    return false;
  if (!ok(q.revolute, CountOf(f.joints_by_type, "D")) || !ok(q.prismatic, CountOf(f.joints_by_type, "S"))) return false;
  if (!ok(q.drives, f.drive_joints) || !ok(q.drives_at_frame, f.drive_joints_at_frame)) return false;
  if (!ok(q.outputs, f.output_links) || !ok(q.outputs_at_frame, f.output_links_at_frame)) return false;
  const CatalogCard& card = *entry.file.card;
  if (q.kind && card.kind != *q.kind) return false;
  if (!q.klass.empty() && std::find(entry.classes.begin(), entry.classes.end(), q.klass) == entry.classes.end()) return false;
  if (!q.motion.empty() && !MotionMatches(card.motion, q.motion)) return false;
  if (!q.text.empty() && TextScore(entry, q.text) == 0) return false;
  if (q.like && !SameKinematicChain(entry.file.mechanism, *q.like)) return false;
  return true;
}

bool TextMatches(const std::string& haystack, const std::string& needle) { return SearchScore({{haystack, 1}}, needle) > 0; }

std::vector<SearchField> SearchFieldsOf(const CatalogEntry& entry) {
  const CatalogCard& card = *entry.file.card;
  // a word in the id or a title ranks an entry first, then in a class or keyword, the motion, the applications
  std::vector<SearchField> fields = {{entry.file.id, 4}, {card.title_de, 4}, {card.title_en, 4}, {entry.file.title, 4}, {card.motion, 2}};
  for (const std::string& c : entry.classes) fields.push_back({c, 3});
  for (const std::string& k : card.keywords) fields.push_back({k, 3});
  for (const std::string& a : card.applications) fields.push_back({a, 1});
  return fields;
}

int TextScore(const CatalogEntry& entry, const std::string& query) { return SearchScore(SearchFieldsOf(entry), query); }

std::vector<const CatalogEntry*> FindEntries(const Catalog& catalog, const FeatureQuery& query) {
  std::vector<const CatalogEntry*> found;
  for (const CatalogEntry& e : catalog.entries()) {
    if (Matches(e, query)) found.push_back(&e);
  }
  // ranked by where the words occur; entries of one rank stay in the catalog's (id) order
  if (!query.text.empty())
    std::stable_sort(found.begin(), found.end(), [&](const CatalogEntry* a, const CatalogEntry* b) { return TextScore(*a, query.text) > TextScore(*b, query.text); });
  return found;
}

}  // namespace koppel
