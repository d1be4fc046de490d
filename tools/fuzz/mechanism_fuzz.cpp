// libFuzzer target: arbitrary bytes through what every koppel command does first — the YAML
// mechanism reader (all its checks and formulas), the structure analysis, and a short sweep from
// the assembly input. Bad input must end in one InputError; anything else that escapes (another
// exception, a crash, a sanitizer report, a leak, more than a second) is a bug. Built only with
// -DKOPPEL_FUZZ=ON and clang; run with tools/fuzz/run.sh SECONDS.
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/sweep.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > koppel::kMaxInputBytes) return 0;  // the file reader refuses these before parsing
  const std::string text(reinterpret_cast<const char*>(data), size);
  koppel::MechanismFile file;
  try {
    file = koppel::ParseMechanismText(text, "fuzz.yaml");
  } catch (const koppel::InputError&) {
    return 0;  // the expected end of bad input
  }
  const koppel::StructureSummary structure = koppel::AnalyseStructure(file.mechanism);
  (void)structure;
  // three samples from the assembly input: the continuation and the Taylor series, no long walk
  koppel::SweepOptions sweep;
  sweep.from = file.mechanism.hint.input;
  sweep.step = file.mechanism.InputIsAngle() ? 0.05 : 0.05 * (1.0 + std::abs(file.mechanism.hint.input));
  sweep.to = sweep.from + 2 * sweep.step;
  sweep.order = 3;
  const koppel::SweepResult result = koppel::Sweep(file.mechanism, sweep);
  (void)result;
  return 0;
}
