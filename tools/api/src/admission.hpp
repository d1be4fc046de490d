// Private to the API (every koppel::Model is admitted here). The rule every front door (the CLI, the Python module, C++ users of koppel::Model) applies to a
// mechanism before analysing it: one drive needs mobility 1. The Grübler–Kutzbach count
// 3 (n - 1) - 2 j_R - 2 j_P is checked against the rank of the joint equations at an assembled
// pose, which decides where the two disagree: an overconstrained linkage that moves (a
// parallelogram with a third parallel crank) is admitted with a note; a mechanism with more (a
// five-bar) or fewer degrees of freedom than drives is refused.
#pragma once

#include "koppel/catalog/mechanism_file.hpp"  // MechanismFile, InputError

#include <string>
#include <utility>
#include <vector>

namespace koppel {

// The notes worth telling the user about an admitted mechanism (none for most); InputError
// naming the file and the field "drive" when it is refused.
std::vector<std::string> AdmitMechanism(const MechanismFile& file);

// A mechanism file read with parameter overrides (name -> formula) and admitted: what every
// command and Model::Load read a file with.
struct AdmittedFile {
  MechanismFile file;
  std::vector<std::string> notes;
};
AdmittedFile ReadAdmittedMechanism(const std::string& path, const std::vector<std::pair<std::string, std::string>>& overrides);

}  // namespace koppel
