// The slider-crank's stroke through the installed library, from the installed catalog (found
// without naming a directory), checked against the closed form
//   stroke = sqrt((l1 + l2)^2 - e^2) - sqrt((l2 - l1)^2 - e^2)
// (seed 000: the slider's distances from the foot point in the extended and folded dead centre).
#include <koppel/koppel.hpp>

#include <cmath>
#include <cstdio>
#include <string>

int main() {
  if (std::string(koppel::Version()) != EXPECTED_VERSION) {
    std::fprintf(stderr, "version %s, the package says %s\n", koppel::Version(), EXPECTED_VERSION);
    return 1;
  }
  koppel::CatalogQuery query;
  query.text = "slider-crank-offset";
  const std::vector<koppel::CatalogHit> hits = koppel::FindInCatalog(query);
  if (hits.size() != 1) {
    std::fprintf(stderr, "the installed catalog (%s) has %zu entries called slider-crank-offset\n",
                 koppel::CatalogDirectory().c_str(), hits.size());
    return 1;
  }
  const koppel::Model m = hits[0].Load({{"e", "0.8"}});
  const koppel::DeadCentres d = m.FindDeadCentres("s");
  double l1 = 0, l2 = 0, e = 0;
  for (const auto& [name, value] : m.parameters()) {
    if (name == "l1") l1 = value;
    if (name == "l2") l2 = value;
    if (name == "e") e = value;
  }
  const double expected = std::sqrt((l1 + l2) * (l1 + l2) - e * e) - std::sqrt((l2 - l1) * (l2 - l1) - e * e);
  std::printf("koppel %s, catalog %s\nstroke %.12f, closed form %.12f\n", koppel::Version(), koppel::CatalogDirectory().c_str(),
              d.stroke, expected);
  return d.status == koppel::AnalysisStatus::kComplete && std::abs(d.stroke - expected) < 1e-9 ? 0 : 1;
}
