// The catalog of documented mechanisms (koppel catalog find): its entries by access features
// (Zugriffsmerkmale), kind, class and text. Every entry is a mechanism file that Model::Load
// reads.
#pragma once

#include "koppel/api/model.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

// An entry's access features (Zugriffsmerkmale): as its card declares them, completed by those
// its joint graph shows.
struct CatalogFeatures {
  int drive_joints = 0, drive_joints_at_frame = 0, output_links = 0, output_links_at_frame = 0;
  int links = 0, joints = 0;
  std::map<int, int> links_by_degree;         // joints per link (2 binary, 3 ternary ...) -> links
  std::map<std::string, int> joints_by_type;  // "D" revolute, "S" prismatic ... -> joints
};

struct CatalogHit {
  std::string id, title_en, title_de, path, kind;
  std::vector<std::string> classes;
  int links = 0, joints = 0, revolute = 0, prismatic = 0;
  std::string motion;  // "<input motion> -> <output motion>", as the card says
  CatalogFeatures features;
  // what the text search reads, with the weight a word found there adds to the rank: the id and
  // titles 4, classes and keywords 3, the motion 2, the applications 1 (the catalog page's search
  // box scores these with the same code as `find --text`)
  std::vector<std::pair<std::string, int>> search_fields;
  Model Load(const ParameterValues& set = {}) const { return Model::Load(path, set); }
};

// Counts are ranges as at the CLI: "4", "4..6", "..6", "4..".
struct CatalogQuery {
  std::optional<std::string> links, binary, ternary, quaternary, joints, revolute, prismatic, drives, outputs;
  std::optional<std::string> drives_at_frame, outputs_at_frame;
  std::string kind;    // "transfer", "guidance", ...; empty: any
  std::string klass;   // a class such as "slider-crank"; empty: any
  std::string motion;  // e.g. "rotation -> translation"; empty: any
  std::string text;    // case-insensitive part of the id or a title; empty: any
  std::string like;    // a mechanism file or catalog id: entries with its kinematic chain; empty: any
};

// The entries of the catalog in `directory` that match every field of `query`, in file order.
// The query is checked first (tools/api/src/catalog_query.hpp: ToFeatureQuery): a malformed field
// is an InputError whose diagnostic has the file "catalog query" and the field's name (as spelt
// in CatalogQuery) as its path; the `like` mechanism's own problems keep their file. Then the
// catalog is read: InputError with every bad file's diagnostics.
// The default catalog: $KOPPEL_CATALOG, else the one installed with koppel (share/koppel/catalog),
// else the source tree's.
std::vector<CatalogHit> FindInCatalog(const CatalogQuery& query, const std::string& directory = "");
std::string CatalogDirectory();

// A word of the catalog's vocabulary and what it means (for --help and the README).
struct CatalogTerm {
  std::string name, meaning;
};
std::vector<CatalogTerm> CatalogClassTerms();     // the classes an entry may have (--class)
std::vector<CatalogTerm> FigureQuantityTerms();   // the quantities a card's figures may use

}  // namespace koppel
