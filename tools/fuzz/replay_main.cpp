// Replays fuzz inputs without libFuzzer (any compiler; ctest fuzz_corpus in the Release and the
// sanitizer build): every file named, and every file in a directory named, through
// LLVMFuzzerTestOneInput once. A crash or a sanitizer report ends the process (the test fails);
// an input slower than kSlowestSeconds fails it too. Prints "N inputs replayed, slowest T s".
#include <algorithm>
#include <ctime>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

// libFuzzer's limit per input is 1 s in an optimised sanitizer build; the CI's checked build is
// compiled at -O1: five times that, in processor seconds.
#if defined(__SANITIZE_ADDRESS__)
// The slowest input, a Peaucellier linkage that assembles nowhere, takes 15 s there since the
// assembly search of a failed hint probes a whole turn of starts (issue 22 item 7); 0.69 s in Release.
constexpr double kSlowestSeconds = 20.0;
#else
constexpr double kSlowestSeconds = 5.0;
#endif

std::vector<std::filesystem::path> Inputs(int argc, char** argv) {
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    if (std::filesystem::is_directory(argv[i])) {
      for (const auto& item : std::filesystem::directory_iterator(argv[i])) {
        if (item.is_regular_file()) files.push_back(item.path());
      }
    } else {
      files.emplace_back(argv[i]);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::filesystem::path> files = Inputs(argc, argv);
  double slowest = 0;
  std::string slowest_name;
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // processor time, not the wall clock: a machine busy with other work (ctest -j2, a build)
    // slows the wall clock of a fast input past the limit, never its processor time
    const std::clock_t start = std::clock();
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    if (seconds > slowest) {
      slowest = seconds;
      slowest_name = file.filename().string();
    }
  }
  std::cout << files.size() << " inputs replayed, slowest " << slowest << " s (" << slowest_name << ")\n";
  if (files.empty()) {
    std::cerr << "no inputs\n";
    return 1;
  }
  if (slowest > kSlowestSeconds) {
    std::cerr << slowest_name << " took " << slowest << " s, more than " << kSlowestSeconds << " s\n";
    return 1;
  }
  return 0;
}
