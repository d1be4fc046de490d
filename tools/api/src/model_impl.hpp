// Model's insides, shared by the files that implement its methods: private to the API.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_source.hpp"
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"

#include <memory>
#include <string>

namespace koppel {

// The parsed file (or text) the model came from, so that Set evaluates it anew with every
// override without reading it again (null for a mechanism built in code; copies share it), and
// the current pose: a solver and a walk on the mechanism, which both hold references into
// `file`, so they are made again whenever the mechanism changes (and never copied).
struct Model::Impl {
  std::shared_ptr<const MechanismSource> source;
  Overrides overrides;
  MechanismFile file;
  std::vector<std::string> notes;  // AdmitMechanism's, for `file`

  std::unique_ptr<PositionSolver> solver;
  std::unique_ptr<Continuation> walk;
  AtBranchPoint walk_action = AtBranchPoint::kContinue;

  void Forget() {
    walk.reset();
    solver.reset();
  }
  PoseResult Pose(int order);
  void StartWalk(const Assembly& assembly, AtBranchPoint action);
};

// How the API's sources beyond model.cpp read a Model's file (the analyses of their own headers
// take a `const Model&`); nothing outside tools/api sees it.
struct ModelAccess {
  static const MechanismFile& File(const Model& model) { return model.impl_->file; }
};

}  // namespace koppel
