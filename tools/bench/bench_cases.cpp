#include "bench.hpp"

namespace koppel::bench {

std::vector<Case> AllCases() {
  std::vector<Case> all;
  for (std::vector<Case> part : {WalkCases(), SlvsCases(), SynthesisCases(), AnalyzeCases(), AtlasBuildCases(), StartupCases()}) {
    for (Case& c : part) all.push_back(std::move(c));
  }
  return all;
}

}  // namespace koppel::bench
