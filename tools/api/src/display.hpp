// The API's units (model.hpp) from the solver's: private to the API.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/api/sweep_layout.hpp"
#include "koppel/solver/singular.hpp"
#include "koppel/solver/sweep.hpp"

#include <string>
#include <vector>

namespace koppel::api_detail {

// One row in the API's units from the solver's: the input, `width` outputs laid out by
// PositionSolver::OutputDerivatives, the valid order and the singular flag. Orders above
// `valid_order` become NaN.
void DisplayRow(const Mechanism& mechanism, const SweepColumns& layout, double input, const double* outputs, int valid_order,
                bool singular, double* row);

double InputShown(const Mechanism& mechanism, double input);     // deg for an R drive
double InputInternal(const Mechanism& mechanism, double input);  // rad for an R drive
std::vector<SingularPosition> Shown(const Mechanism& mechanism, const std::vector<SingularPoint>& points);
std::vector<InputGap> Shown(const Mechanism& mechanism, const std::vector<InputInterval>& gaps);

// The sweep's outcome: complete, partial (gaps), not run; failed for the rest.
AnalysisStatus FromSweep(SweepStatus status);
// What a sweep met, in the API's units.
SweepRecord Shown(const Mechanism& mechanism, const SweepEvents& events);

// InputError naming the model's file and `field`.
[[noreturn]] void BadInput(const std::string& file, const std::string& field, const std::string& message);

}  // namespace koppel::api_detail
