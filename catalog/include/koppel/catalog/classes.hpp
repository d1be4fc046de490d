// The words a catalog card describes its mechanism with, so that lookups find what a designer
// looks for: the classes (four-bar, crank-rocker, quick-return, Watt six-bar ...) and the
// motion "<input motion> -> <output motion>". Classes that follow from the joint graph alone
// (four-bar, slider-crank, double-slider, the six-bar chains, a slider between moving links) are
// computed, and a declared one that the graph contradicts fails `catalog check`; so does a
// declared Grashof type (crank-rocker ... change-point) that the four-bar's lengths contradict.
// The others (quick-return, toggle, ...) are proved by the entry's figures.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <string>
#include <vector>

namespace koppel {

struct CatalogClass {
  const char* name;
  const char* meaning;
};

const std::vector<CatalogClass>& CatalogClasses();
bool IsCatalogClass(const std::string& name);

// The structural classes the graph shows (a subset of CatalogClasses()).
std::vector<std::string> StructuralClasses(const Mechanism& mechanism);
// What koppel computes of an entry, added to its declared classes: the structural classes and,
// for a four-bar, its Grashof type (crank-rocker ... change-point, classification.hpp).
std::vector<std::string> ComputedClasses(const Mechanism& mechanism);
// Declared classes the graph contradicts, one message each.
std::vector<std::string> ClassProblems(const Mechanism& mechanism, const std::vector<std::string>& declared);

// Motion words: a card's motion is "<input> -> <output>[ anything]" with <input> one of
// InputMotions() and the output part starting with one of OutputMotions().
const std::vector<std::string>& InputMotions();
const std::vector<std::string>& OutputMotions();
// Empty when `motion` has that form, else what is wrong.
std::string MotionProblem(const std::string& motion);

// "full rotation -> oscillating translation" matches a query "rotation -> translation": each
// side of the query is a case-insensitive part of the same side of the motion; a query without
// "->" is a part of either side.
bool MotionMatches(const std::string& motion, const std::string& query);

}  // namespace koppel
