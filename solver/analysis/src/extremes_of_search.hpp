// The extremes of an output read off a stationary-point search (extremes.hpp), for the analyses
// that search once and report both (dead_centres.cpp).
#pragma once

#include "stationary_search.hpp"

#include "koppel/analysis/extremes.hpp"

namespace koppel {

OutputExtremes ExtremesOf(const Mechanism& mechanism, int output, const StationarySearch& search);

}  // namespace koppel
