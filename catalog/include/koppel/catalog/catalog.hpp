// The catalog: every mechanism file with a catalog card in one directory, looked up by id, by
// access features (Zugriffsmerkmale), by kind and by free text over the titles.
#pragma once

#include "koppel/catalog/card.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/text_search.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct CatalogEntry {
  MechanismFile file;       // file.card is set
  AccessFeatures features;  // as declared, completed by the computed ones where not declared
  std::vector<std::string> classes;  // as declared, plus the structural ones the graph shows
};

class Catalog {
 public:
  // Reads every *.yaml in `directory` (sorted by file name). Bad files throw one InputError
  // with the diagnostics of all of them; a file without a catalog section is an error too.
  // An entry's file is named by its id (<id>.yaml): another name is an error too, so that an id
  // names its file without reading the catalog (ResolveMechanismName).
  static Catalog Load(const std::string& directory);

  const std::vector<CatalogEntry>& entries() const { return entries_; }
  const CatalogEntry* Find(const std::string& id) const;

 private:
  std::vector<CatalogEntry> entries_;
};

// An inclusive integer range; "4" or "4..6" (either end may be open: "..6", "4..").
struct CountRange {
  int lo = 0;
  int hi = 1 << 30;
  bool Contains(int value) const { return value >= lo && value <= hi; }
  static std::optional<CountRange> Parse(const std::string& text);
};

struct FeatureQuery {
  std::optional<CountRange> links, binary, ternary, quaternary, joints, revolute, prismatic;
  std::optional<CountRange> drives, drives_at_frame, outputs, outputs_at_frame;
  std::optional<CardKind> kind;   // any when not set
  std::string klass;              // one of CatalogClasses(); empty: any
  std::string motion;             // MotionMatches query, e.g. "rotation -> translation"; empty: any
  std::string text;               // words in the id, titles, classes, keywords, motion or applications (TextScore); empty: any
  std::optional<Mechanism> like;  // entries whose kinematic chain is isomorphic to this one's
};

bool Matches(const CatalogEntry& entry, const FeatureQuery& query);
// True when every word of `needle` occurs in `haystack` as text_search.hpp compares them (case,
// hyphens, spaces, punctuation and umlauts ignored; synonyms found): "straight line",
// "Straight-Line", "straightline" and "Geradführung" all find "straight-line".
bool TextMatches(const std::string& haystack, const std::string& needle);
// The rank of `entry` for the words of `query` (SearchScore over its id, titles, classes,
// keywords, motion and applications); 0 when a word occurs nowhere.
int TextScore(const CatalogEntry& entry, const std::string& query);
// The fields TextScore searches, with their weights: the catalog page hands them to the same
// SearchScore compiled for the browser, so that its search box finds what `find --text` finds.
std::vector<SearchField> SearchFieldsOf(const CatalogEntry& entry);
// The entries that match, in the catalog's order; with query.text, the highest TextScore first.
std::vector<const CatalogEntry*> FindEntries(const Catalog& catalog, const FeatureQuery& query);

// True when the kinematic chains are isomorphic: a one-to-one map of the links that takes the
// frame to the frame and every joint to a joint of the same type (R or P) between the mapped
// links. Link names, joint names, dimensions, the drive and the outputs do not matter.
bool SameKinematicChain(const Mechanism& a, const Mechanism& b);

// The default catalog directory: $KOPPEL_CATALOG if set; else, for an installed koppel, the
// entries installed with it (<prefix>/share/koppel/catalog, found relative to the library);
// else the source tree's catalog/entries the build was made from.
std::string DefaultCatalogDirectory();

// A mechanism named where a file is expected (every command, a fit problem's `mechanism`, the
// API; ReadMechanismFile applies it): `name` itself when it is an existing file or does not look
// like an id (letters, digits, '-', '_'); else the catalog entry <directory>/<name>.yaml when it
// exists (`directory` empty: DefaultCatalogDirectory()); else `name`, for the reader to report.
std::string ResolveMechanismName(const std::string& name, const std::string& directory = "");
// The file of the catalog entry `id` (<directory>/<id>.yaml), empty when `id` is no id or there
// is no such entry. ResolveMechanismName's second half, for a name relative to another file.
std::string CatalogEntryFile(const std::string& id, const std::string& directory = "");

// The ids of the entries in `directory` (the names of its *.yaml files), sorted; empty when the
// directory cannot be read. Cheaper than Catalog::Load: no file is read.
std::vector<std::string> CatalogIds(const std::string& directory);

// For "did you mean": the id of `ids` nearest to `id` (fewer than three edits, case ignored),
// empty when none is near.
std::string NearestCatalogId(const std::string& id, const std::vector<std::string>& ids);

// "no catalog entry 'ID' (did you mean 'NEAR'?)", or "no catalog entry 'ID' in DIRECTORY
// (`koppel catalog list` lists them)" when no id is near.
std::string UnknownCatalogId(const std::string& id, const std::vector<std::string>& ids, const std::string& directory);

}  // namespace koppel
