// The coupler-curve atlas of path synthesis (koppel atlas build|merge): what a build draws, the
// memory it needs, the atlas file's bytes. The space drawn from, the descriptor and the file
// format are the synthesis library's (koppel/synthesis/atlas.hpp, atlas_file.hpp); here they
// are plain numbers and bytes.
#pragma once

#include "koppel/core/expected.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace koppel {

// Curves one atlas may hold (kMaxAtlasCurves): a larger --count is a mistake.
std::uint64_t AtlasCurveLimit();

struct AtlasBuildSpec {
  std::uint64_t count = 0;  // curves of the whole atlas (every shard together)
  std::uint64_t seed = 1;
  int shard = 0, shards = 1;  // build the shard-th of `shards` equal parts
  int threads = 0;            // 0: one per core
};

// Empty when the spec can be built; else why not ("--shard: ...", as the flags are named).
std::string AtlasBuildProblem(const AtlasBuildSpec& spec);
// Done when the build fits in the memory this process may use (UsableMemory); else the error
// gives both figures and the way out (shards, merged afterwards).
Outcome AtlasBuildFits(const AtlasBuildSpec& spec);

// An atlas file's image and what it holds.
struct AtlasImage {
  std::string bytes;        // the file (atlas_file.hpp's format), to be written as is
  std::uint64_t curves = 0;
  std::uint64_t closed = 0;  // curves of cranks that turn fully; the others are rocker arcs
};

// Draws the shard (the same entries on any number of threads); `progress`, when given, is called
// from the calling thread with the fraction done. Check AtlasBuildProblem first.
AtlasImage BuildAtlasImage(const AtlasBuildSpec& spec, const std::function<void(double)>& progress = {});
// The union of the atlas files at `paths`, ordered by seed and index. A file that cannot be read
// throws io::FileError ("path: what is wrong"); a curve found twice is the error.
Expected<AtlasImage> MergeAtlasFiles(const std::vector<std::string>& paths);

}  // namespace koppel
