// The catalog of documented mechanisms (koppel catalog find): its entries by access features
// (Zugriffsmerkmale), kind, class and text. Every entry is a mechanism file that Model::Load
// reads.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/catalog/catalog.hpp"  // FeatureQuery

#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct CatalogHit {
  std::string id, title_en, title_de, path, kind;
  std::vector<std::string> classes;
  int links = 0, joints = 0, revolute = 0, prismatic = 0;
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

// The catalog library's query for `query`: every count parsed, the kind and the class checked, the
// `like` mechanism read and admitted (ReadAdmittedMechanism). InputError naming the field (as
// spelt in CatalogQuery) otherwise. The one place where a query's text becomes a query.
FeatureQuery ToFeatureQuery(const CatalogQuery& query);

// The default catalog: $KOPPEL_CATALOG, else the one installed with koppel (share/koppel/catalog),
// else the source tree's. InputError for an unreadable catalog or a malformed query.
std::vector<CatalogHit> FindInCatalog(const CatalogQuery& query, const std::string& directory = "");
std::string CatalogDirectory();

}  // namespace koppel
