// Evaluating a card's figures for one parameter variant. A FigureContext holds the analyses
// that several figures share (the sweep of the card's range, dead centres per output), so a
// card with twenty figures sweeps once, not twenty times. Private to the catalog.
#pragma once

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/analysis/dead_centres.hpp"
#include "koppel/analysis/ranges.hpp"
#include "koppel/catalog/card.hpp"
#include "koppel/catalog/check.hpp"
#include "koppel/catalog/figure_quantities.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/solver/sweep.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

namespace koppel {

// Column of output `name`, component, derivative order k in a sweep table of order `order`;
// -1 when the mechanism has no such output.
int OutputColumn(const Mechanism& m, const std::string& name, int component, int k, int order);

class FigureContext {
 public:
  FigureContext(const MechanismFile& file, const CatalogCard& card) : file_(file), card_(card) {}

  const MechanismFile& file() const { return file_; }
  const Mechanism& mechanism() const { return file_.mechanism; }
  const CatalogCard& card() const { return card_; }

  // The figure's output (the reader made sure it exists when the quantity needs one).
  int Output(const FigureCheck& figure) const;

  // Argument values. Formulas are evaluated with this variant's parameters; one without a value
  // here (e.g. asin(2) after an override) throws InputError at the figure's line. Inputs come
  // back in internal units (radians for an R drive).
  bool Has(const FigureCheck& figure, const char* argument) const;
  double Input(const FigureCheck& figure, const char* argument) const;
  double Number(const FigureCheck& figure, const char* argument) const;
  int Order(const FigureCheck& figure, const char* argument) const;
  int Joint(const FigureCheck& figure, const char* argument) const;

  // The card's sweep in internal units, order 0.
  SweepOptions CardRange() const;
  // The sweep of the card's range, or of from..to when the figure gives them; cached.
  const SweepResult& RangeSweep(const FigureCheck& figure);
  // Dead centres of an output over the card's range; cached.
  const DeadCentreReport& DeadCentres(int output, int component);
  // The drivable ranges of the mechanism's branches (ranges.hpp); cached.
  const RangeReport& Ranges();

  // The longest straight stretch of a point output with Q_G <= qg around `at` (coupler_curve.hpp);
  // cached, as several figures read one search.
  const StraightStretch& LongestStretch(int output, double qg, std::optional<double> at);

  [[noreturn]] void Fail(const FigureCheck& figure, const std::string& message) const;

 private:
  const MechanismFile& file_;
  const CatalogCard& card_;
  std::map<std::pair<double, double>, std::unique_ptr<SweepResult>> sweeps_;
  std::map<std::pair<int, int>, std::unique_ptr<DeadCentreReport>> dead_centres_;
  std::map<std::tuple<int, double, std::optional<double>>, std::unique_ptr<StraightStretch>> stretches_;
  std::unique_ptr<RangeReport> ranges_;
};

bool FigureApplies(const FigureCheck& figure, const std::string& variant);

// Evaluates one figure and compares it with the document's value (a malformed expected value
// throws InputError).
CheckOutcome EvaluateFigure(FigureContext& context, const FigureCheck& figure, const std::string& variant);

}  // namespace koppel
