// Scalar figures of a catalog card (dead-centre angles, stroke, mu_min, ...), recomputed with
// the solver. Private to the catalog: check.cpp runs them.
#pragma once

#include "koppel/catalog/card.hpp"
#include "koppel/catalog/check.hpp"
#include "koppel/catalog/mechanism_file.hpp"

namespace koppel {

// Column of output `name`, component, derivative order k in a sweep table of order `order`;
// -1 when the mechanism has no such output.
int OutputColumn(const Mechanism& m, const std::string& name, int component, int k, int order);

bool FigureApplies(const FigureCheck& figure, const std::string& variant);

// Evaluates one figure for one parameter variant. Unknown quantity kinds and figures marked
// pending come back pending; a malformed figure throws InputError.
CheckOutcome EvaluateFigure(const MechanismFile& file, const CatalogCard& card, const FigureCheck& figure,
                            const std::string& variant);

}  // namespace koppel
