// Errors are a core type: every layer that reads input (the catalog's file readers, the API's
// requests, the CLI's flags) reports a problem as a Diagnostic and throws them together as one
// InputError, so a front door catches one type whatever layer found the problem.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace koppel {

// One problem in an input file. line and column are 1-based; 0 when unknown.
struct Diagnostic {
  std::string file;
  int line = 0;
  int column = 0;
  std::string path;     // key path, e.g. "joints.A.links[1]"
  std::string message;
  // "mech.yaml:12:7: joint 'A' names unknown link 'crank2' (joints.A.links[1])"
  std::string ToString() const;
};

// Thrown once per file (or per catalog, or per request) with every problem found; what() joins
// the diagnostics' ToString() by newlines.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace koppel
