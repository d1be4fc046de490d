// libFuzzer target: arbitrary bytes through every reader of koppel's input files and what the
// commands do first with what they read. The first byte chooses the reader, the rest is the file:
//   m  a mechanism (koppel analyze and all): the reader, the structure analysis, a short sweep;
//   p  poses (synth motion): the reader, the Burmester curves of four poses (12 directions,
//      unrefined: a second under the sanitizers), the dyads of five;
//   f  a function spec (synth function): the reader and its formula at the range's ends;
//   c  points (synth path): the reader and the descriptor of the closed path;
//   t  a motor curve (simulate --motor): the reader;
//   a  an atlas (synth path, atlas merge): the file's bytes as they are (header, checksums);
//   e  atlas entries: the bytes as entries written with valid checksums, so that the entry checks
//      and the k-d tree over what they admit are reached;
//   g  a design chart (plot chart.csv): the reader and the picture.
// Any other first byte picks a reader by its value. Bad input must end in one InputError (or the
// reader's own error value); anything else that escapes (another exception, a crash, a sanitizer
// report, a leak, more than a second) is a bug. Built with -DKOPPEL_FUZZ=ON and clang
// (tools/fuzz/run.sh); replayed without libFuzzer by replay_main.cpp (ctest fuzz_corpus).
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/motor_curve.hpp"
#include "koppel/catalog/path_points.hpp"
#include "koppel/catalog/synthesis_spec.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/plot/plots.hpp"
#include "koppel/solver/sweep.hpp"
#include "koppel/synthesis/atlas_file.hpp"
#include "koppel/synthesis/burmester.hpp"
#include "koppel/synthesis/motion_dyads.hpp"
#include "koppel/synthesis/path_synthesis.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace koppel {
namespace {

void Mechanism(const std::string& text) {
  const MechanismFile file = ParseMechanismText(text, "fuzz.yaml");
  (void)AnalyseStructure(file.mechanism);
  // three samples from the assembly input: the continuation and the Taylor series, no long walk
  SweepOptions sweep;
  sweep.from = file.mechanism.hint.input;
  sweep.step = file.mechanism.InputIsAngle() ? 0.05 : 0.05 * (1.0 + std::abs(file.mechanism.hint.input));
  sweep.to = sweep.from + 2 * sweep.step;
  sweep.order = 3;
  (void)Sweep(file.mechanism, sweep);
}

void Poses(const std::string& text) {
  const MotionSpecFile spec = ParseMotionSpecText(text, "poses.yaml");
  if (spec.poses.size() == 4) (void)CentrePointCurve(spec.poses, 12, false);
  if (spec.poses.size() == 5) (void)DyadsForPoses(spec.poses, DyadRequest{});
}

void Function(const std::string& text) {
  const FunctionSpecFile spec = ParseFunctionSpecText(text, "spec.yaml");
  double y = 0;
  (void)spec.request.function(spec.request.x_from, &y);
}

void Points(const std::string& text) {
  const std::vector<Eigen::Vector2d> points = ParseTimedPathPoints(text, "points.csv").points;
  CurveDescriptor descriptor;
  if (points.size() >= 3 && DescribeCurve(points, &descriptor)) (void)OtherBranchOfAmbiguity(descriptor);
}

void Motor(const std::string& text) { (void)ParseMotorCurveText(text, "motor.csv"); }

void AtlasBytes(const std::string& text) { (void)ParseAtlas(text); }

// Entries from the bytes in the order of the file's fields, written and read back.
void AtlasEntries(const std::string& text) {
  constexpr std::size_t kFieldBytes = 8 + 8 + 5 * 8 + 3 + kAtlasFeatures * 4;
  std::vector<AtlasEntry> entries;
  for (std::size_t at = 0; at + kFieldBytes <= text.size() && entries.size() < 64; at += kFieldBytes) {
    const char* p = text.data() + at;
    AtlasEntry e;
    auto take = [&p](void* field, std::size_t n) {
      std::memcpy(field, p, n);
      p += n;
    };
    take(&e.seed, 8);
    take(&e.index, 8);
    for (double* v : {&e.crank, &e.coupler, &e.rocker, &e.p, &e.q}) take(v, 8);
    take(&e.branch, 1);
    take(&e.side, 1);
    take(&e.closed, 1);
    take(e.descriptor.data(), sizeof e.descriptor);
    entries.push_back(e);
  }
  const Expected<std::vector<AtlasEntry>> read = ParseAtlas(SerialiseAtlas(entries));
  if (!read || read->empty()) return;
  const AtlasIndex index(*read);
  (void)index.Nearest(read->front().descriptor, read->front().closed != 0, 3);
}

void Chart(const std::string& text) { (void)plot::ChartPlot(text, "chart.csv"); }

using Reader = void (*)(const std::string&);
struct Choice {
  char tag;
  Reader read;
};
constexpr Choice kReaders[] = {{'m', Mechanism}, {'p', Poses}, {'f', Function}, {'c', Points},
                               {'t', Motor},     {'a', AtlasBytes}, {'e', AtlasEntries}, {'g', Chart}};
constexpr std::size_t kReaderCount = sizeof kReaders / sizeof kReaders[0];

Reader ReaderFor(std::uint8_t first) {
  for (const Choice& c : kReaders) {
    if (c.tag == static_cast<char>(first)) return c.read;
  }
  return kReaders[first % kReaderCount].read;
}

}  // namespace
}  // namespace koppel

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the file reader refuses more than kMaxInputBytes before parsing
  if (size == 0 || size - 1 > koppel::kMaxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    koppel::ReaderFor(data[0])(text);
  } catch (const koppel::InputError&) {
    // the expected end of bad input
  }
  return 0;
}
