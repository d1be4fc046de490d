// Model's insides, shared by the files that implement its methods: private to the API.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_source.hpp"

#include <memory>
#include <string>
#include <vector>

namespace koppel {

// What a Model is, made once and never changed: the file read (null for a mechanism built in
// code; Model::With evaluates it anew with one more override), the overrides so far, the
// mechanism file they give and what admitting it noted.
struct Model::Impl {
  std::shared_ptr<const MechanismSource> source;
  Overrides overrides;
  MechanismFile file;
  std::vector<std::string> notes;  // AdmitMechanism's, for `file`
};

// How the API's sources beyond model.cpp read a Model's file (the analyses of their own headers
// take a `const Model&`); nothing outside tools/api sees it.
struct ModelAccess {
  static const MechanismFile& File(const Model& model) { return model.impl_->file; }
  static bool HasSource(const Model& model) { return model.impl_->source != nullptr; }
  // A model of a file made in code (the editor page's mechanism, editor_mechanism.cpp): admitted
  // as Model::Load admits; it has no source, so With refuses to set a parameter.
  static Model FromFile(MechanismFile file);
};

}  // namespace koppel
