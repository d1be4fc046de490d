// koppel as a library: include this, link koppel::koppel (find_package(koppel CONFIG)).
//   koppel::Model m = koppel::Model::Load("slider-crank-offset.yaml", {{"e", "0.8"}});
//   koppel::DeadCentres d = m.FindDeadCentres("s");   // d.stroke, d.points
//   koppel::SweepTable t = m.Sweep(0, 360, 1, 2);      // the table of `koppel analyze`
// Units, frames, signs and failure behaviour: koppel/api/model.hpp. The parts (koppel::analysis,
// koppel::synthesis, ...) have headers of their own under koppel/<part>/.
#pragma once

#include "koppel/api/atlas.hpp"
#include "koppel/api/catalog.hpp"
#include "koppel/api/catalog_check.hpp"
#include "koppel/api/classification.hpp"
#include "koppel/api/coupler_curve.hpp"
#include "koppel/api/design_chart.hpp"
#include "koppel/api/fit.hpp"
#include "koppel/api/forces.hpp"
#include "koppel/api/model.hpp"
#include "koppel/api/motion_synthesis.hpp"
#include "koppel/api/path_synthesis.hpp"
#include "koppel/api/proportionality.hpp"
#include "koppel/api/simulation.hpp"
#include "koppel/api/sweep_layout.hpp"
#include "koppel/api/synthesis.hpp"
#include "koppel/api/workspace.hpp"
#include "koppel/core/version.hpp"

namespace koppel {

// The version of this koppel (project(VERSION) in its CMakeLists), e.g. "0.1.0".
inline const char* Version() { return kVersion; }

}  // namespace koppel
