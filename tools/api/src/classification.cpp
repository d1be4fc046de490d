#include "koppel/api/classification.hpp"

#include "koppel/analysis/classification.hpp"
#include "koppel/api/model.hpp"

namespace koppel {

ModelClassification ClassifyModel(const Model& model) {
  const Mechanism& m = model.mechanism();
  const Classification c = Classify(m);
  ModelClassification r;
  r.mobility = c.mobility;
  r.assembled = c.assembled;
  r.rank_mobility = c.assembled ? c.rank_mobility : -1;
  // a P drive never "comes round": only a turning R drive is full
  r.drive_rotation = m.InputIsAngle() && c.drive_turns_fully ? "full" : "limited";
  if (c.grashof != GrashofType::kNotApplicable) {
    r.grashof = ToString(c.grashof);
    r.lengths = c.lengths;
    r.rule = c.rule;
  }
  r.notes = c.notes;
  return r;
}

}  // namespace koppel
