// What `koppel forces` computes, in the API's units (model.hpp): the drive torque (force) and the
// joint reactions over a sweep, statics or kinetostatics at a constant drive speed, with the
// virtual-work check and the reduced moment of inertia. The theory, the signs and the frames:
// koppel/analysis/forces.hpp; the masses and loads: README.md, 'Masses and loads'.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/api/model.hpp"
#include "koppel/core/loads.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct ForcesRequest {
  // [deg | length]; unset: the file's sweep (Model::Span)
  std::optional<double> from, to, step;
  // the constant drive speed [rpm for an R drive, length units/s for a P drive]; unset: statics
  std::optional<double> speed;
  AtBranchPoint at_branch_point = AtBranchPoint::kContinue;
  // false with the reason when the range cannot be swept or the speed is not finite
  bool IsValid(const Model& model, std::string* why) const;
};

// The table of `koppel forces`: columns the input [deg | length]; torque [N m] (force [N] for a P
// drive) from the joint reactions; torque_vw, the same by virtual work; J_red [kg m^2] and J_red_d1
// [kg m^2/rad] (m_red [kg], m_red_d1 [kg/m] for a P drive); per joint J: J_x, J_y [N], the force
// its first link exerts on the second, global frame, and for a P joint J_N [N] along the slide's
// normal and J_M [N m] across the slide; singular (1 at a singular pose). A cell is empty where
// it cannot be computed (a singular pose), and the status is then not complete.
struct ForcesTable {
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  // the file's loads do not fit its mechanism, or the range cannot be swept: nothing computed
  bool bad_input = false;
  bool kinetostatic = false;  // a speed was given
  std::vector<std::string> notes;  // e.g. a file without masses and loads, where every force is zero
  std::vector<std::string> columns, units;
  std::vector<std::vector<std::optional<double>>> rows;  // one per computed sample, in sweep order
  double worst_disagreement = 0;  // max |torque - torque_vw| / the loads' size over the rows
  SweepRecord sweep;               // what the sweep underneath met
  bool complete() const { return status == AnalysisStatus::kComplete; }
};

// The forces over the request's sweep. InputError when !request.IsValid(model).
ForcesTable AnalyseForces(const Model& model, const ForcesRequest& request);

}  // namespace koppel
