// A koppel::Model for a command: the file read and admitted by Model::Load (mobility 1, as
// LoadMechanism), its notes on stderr, and the API's InputError turned into exit 2.
#pragma once

#include "common.hpp"

#include "koppel/api/model.hpp"

#include <iostream>
#include <string>
#include <vector>

namespace koppel::cli {

Model LoadModel(const std::string& path, const std::vector<std::string>& sets);

// Calls f(); an InputError (bad input found by the API: an unknown point, output, parameter)
// prints its diagnostics and ends with exit code 2.
template <class F>
auto Checked(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) std::cerr << d.ToString() << "\n";
    throw Exit{kExitBadInput};
  }
}

// Splits "NAME=VALUE" (VALUE a formula); Exit{2} naming the flag otherwise.
std::pair<std::string, double> NamedNumber(const std::string& flag, const std::string& text);

}  // namespace koppel::cli
