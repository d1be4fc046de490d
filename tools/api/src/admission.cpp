#include "admission.hpp"

#include "koppel/solver/assembly.hpp"

namespace koppel {

std::vector<std::string> AdmitMechanism(const MechanismFile& file) {
  const MobilityReport mobility = CheckMobility(file.mechanism);
  if (!mobility.ok()) throw InputError({Diagnostic{file.path, 0, 0, "drive", mobility.error}});
  if (mobility.note.empty()) return {};
  return {mobility.note};
}

AdmittedFile ReadAdmittedMechanism(const std::string& path, const std::vector<std::pair<std::string, std::string>>& overrides) {
  AdmittedFile admitted;
  admitted.file = ReadMechanismFile(path, overrides);
  admitted.notes = AdmitMechanism(admitted.file);
  return admitted;
}

}  // namespace koppel
