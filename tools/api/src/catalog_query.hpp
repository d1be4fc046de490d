// The catalog search's private halves, shared by the API's catalog sources (catalog_search.cpp
// defines them; catalog_check.cpp uses HitOf): private to the API.
#pragma once

#include "koppel/api/catalog.hpp"
#include "koppel/catalog/catalog.hpp"

namespace koppel {

// The catalog library's query for `query`: every count parsed, the kind and the class checked, the
// `like` mechanism read and admitted (ReadAdmittedMechanism). InputError naming the field (as
// spelt in CatalogQuery) otherwise. The one place where a query's text becomes a query.
FeatureQuery ToFeatureQuery(const CatalogQuery& query);

namespace api_detail {
// The entry as the API shows it: titles, kind, classes, motion, features.
CatalogHit HitOf(const CatalogEntry& entry);
}  // namespace api_detail

}  // namespace koppel
