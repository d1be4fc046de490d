#include "koppel/api/atlas.hpp"

#include "koppel/core/memory.hpp"
#include "koppel/synthesis/atlas.hpp"
#include "koppel/synthesis/atlas_file.hpp"

#include <utility>

namespace koppel {

namespace {

AtlasBuildOptions AtlasOptionsOf(const AtlasBuildSpec& spec) {
  AtlasBuildOptions o;
  o.count = spec.count;
  o.seed = spec.seed;
  o.shard = spec.shard;
  o.shards = spec.shards;
  o.threads = spec.threads;
  return o;
}

AtlasImage ImageOf(const std::vector<AtlasEntry>& entries) {
  AtlasImage image;
  image.bytes = SerialiseAtlas(entries);
  image.curves = entries.size();
  for (const AtlasEntry& e : entries) image.closed += e.closed;
  return image;
}

}  // namespace

std::uint64_t AtlasCurveLimit() { return kMaxAtlasCurves; }

std::string AtlasBuildProblem(const AtlasBuildSpec& spec) {
  std::string why;
  return AtlasOptionsOf(spec).IsValid(&why) ? std::string() : why;
}

Outcome AtlasBuildFits(const AtlasBuildSpec& spec) {
  const MemoryLimit memory = UsableMemory();
  return CheckAtlasBuildMemory(AtlasOptionsOf(spec), memory.bytes, memory.source);
}

AtlasImage BuildAtlasImage(const AtlasBuildSpec& spec, const std::function<void(double)>& progress) {
  return ImageOf(BuildAtlas(AtlasOptionsOf(spec), progress));
}

Expected<AtlasImage> MergeAtlasFiles(const std::vector<std::string>& paths) {
  std::vector<std::vector<AtlasEntry>> parts;
  for (const std::string& path : paths) parts.push_back(ReadAtlasFile(path));
  const Expected<std::vector<AtlasEntry>> merged = MergeAtlases(std::move(parts));
  if (!merged) return Expected<AtlasImage>::Error(merged.error());
  return ImageOf(*merged);
}

}  // namespace koppel
