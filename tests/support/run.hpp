// Runs the koppel executable as a user would and captures its exit code, stdout and stderr.
#pragma once

#include <string>

namespace koppel::test {

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// `arguments` is appended to the executable's path as shell words (quote them yourself).
RunResult RunKoppel(const std::string& arguments);

}  // namespace koppel::test
