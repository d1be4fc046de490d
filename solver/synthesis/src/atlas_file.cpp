#include "koppel/synthesis/atlas_file.hpp"

#include "koppel/core/input_file.hpp"

#include <fmt/core.h>

#define XXH_INLINE_ALL  // header-only: no library to link or install
#include <xxhash.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>

namespace koppel {
namespace {

static_assert(std::endian::native == std::endian::little, "the atlas file is written little endian as it lies in memory");

constexpr char kMagic[12] = {'K', 'O', 'P', 'P', 'E', 'L', '-', 'A', 'T', 'L', 'A', 'S'};
constexpr std::uint64_t kHeaderFields = sizeof kMagic + 4 + 4 + 8;  // what the header's checksum covers
constexpr std::uint64_t kChecksumBytes = 8;
constexpr std::uint64_t kHeaderBytes = kHeaderFields + kChecksumBytes;
constexpr std::uint64_t kEntryBytes = 8 + 8 + 5 * 8 + 4 + kAtlasFeatures * 4;

template <class T> void Put(std::string* out, T v) { out->append(reinterpret_cast<const char*>(&v), sizeof v); }
template <class T> T Get(const char*& p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  p += sizeof v;
  return v;
}

std::uint64_t Checksum(const char* bytes, std::size_t n) { return XXH3_64bits(bytes, n); }
void PutChecksum(std::string* out, std::size_t from) { Put<std::uint64_t>(out, Checksum(out->data() + from, out->size() - from)); }

void PutEntry(std::string* out, const AtlasEntry& e) {
  Put(out, e.seed);
  Put(out, e.index);
  for (double v : {e.crank, e.coupler, e.rocker, e.p, e.q}) Put(out, v);
  Put(out, e.branch);
  Put(out, e.side);
  Put(out, e.closed);
  Put<std::uint8_t>(out, 0);
  for (float v : e.descriptor) Put(out, v);
}

// One entry from its 132 bytes; false when a value lies outside what a build writes.
bool GetEntry(const char*& p, AtlasEntry* e) {
  e->seed = Get<std::uint64_t>(p);
  e->index = Get<std::uint64_t>(p);
  for (double* v : {&e->crank, &e->coupler, &e->rocker, &e->p, &e->q}) *v = Get<double>(p);
  e->branch = Get<std::int8_t>(p);
  e->side = Get<std::int8_t>(p);
  e->closed = Get<std::uint8_t>(p);
  const auto pad = Get<std::uint8_t>(p);
  bool finite = std::isfinite(e->crank) && std::isfinite(e->coupler) && std::isfinite(e->rocker) && std::isfinite(e->p) && std::isfinite(e->q);
  for (float& v : e->descriptor) {
    v = Get<float>(p);
    finite = finite && std::isfinite(v);
  }
  return finite && e->crank > 0 && e->coupler > 0 && e->rocker > 0 && std::abs(e->branch) == 1 && std::abs(e->side) == 1 && e->closed <= 1 && pad == 0;
}

using Result = Expected<std::vector<AtlasEntry>>;
// Up to n more bytes of the file: fewer only at its end.
using ReadBytes = std::function<std::string(std::size_t n)>;

// The header's entry count, or the error.
Expected<std::uint64_t> ParseHeader(const std::string& header, std::optional<std::uint64_t> size) {
  using Count = Expected<std::uint64_t>;
  if (header.size() < kHeaderFields || std::memcmp(header.data(), kMagic, sizeof kMagic) != 0) return Count::Error("not a koppel atlas (no KOPPEL-ATLAS header)");
  const char* p = header.data() + sizeof kMagic;
  const auto version = Get<std::uint32_t>(p), features = Get<std::uint32_t>(p);
  const auto count = Get<std::uint64_t>(p);
  if (version == 1) return Count::Error("atlas format 1, from before koppel checked its atlases: this koppel reads format 2; build it again (koppel atlas build)");
  if (version != kAtlasFormatVersion) return Count::Error(fmt::format("atlas format {}: this koppel reads format {} (a damaged header, or a newer koppel's atlas)", version, kAtlasFormatVersion));
  if (header.size() < kHeaderBytes || Get<std::uint64_t>(p) != Checksum(header.data(), kHeaderFields))
    return Count::Error("the header does not match its checksum: the file is damaged (a flipped bit, a bad copy); build or copy it again");
  if (features != kAtlasFeatures) return Count::Error(fmt::format("an atlas of {} features per curve: this koppel reads {}", features, kAtlasFeatures));
  if (count > kMaxAtlasCurves) return Count::Error(fmt::format("the header promises {} curves, more than any atlas holds ({})", count, kMaxAtlasCurves));
  if (size && *size != AtlasFileSize(count))
    return Count::Error(fmt::format("the header promises {} curves ({} bytes) but the file has {} bytes (truncated or not an atlas)", count, AtlasFileSize(count), *size));
  return count;
}

// The entries of an atlas read by `read`; `size`, when known, the file's size.
Result ParseAtlasFrom(const ReadBytes& read, std::optional<std::uint64_t> size) {
  const Expected<std::uint64_t> count = ParseHeader(read(kHeaderBytes), size);
  if (!count) return Result::Error(count.error());
  const std::uint64_t sections = (*count + kAtlasSectionEntries - 1) / kAtlasSectionEntries;
  std::vector<AtlasEntry> entries;
  for (std::uint64_t s = 0; s < sections; ++s) {
    const std::uint64_t first = s * kAtlasSectionEntries, n = std::min(kAtlasSectionEntries, *count - first);
    const std::string where = fmt::format("section {} of {} (curves {} to {})", s + 1, sections, first, first + n - 1);
    const std::string bytes = read(n * kEntryBytes + kChecksumBytes);
    if (bytes.size() < n * kEntryBytes + kChecksumBytes) return Result::Error(fmt::format("the file ends in {}: it is truncated", where));
    const char* p = bytes.data() + n * kEntryBytes;
    if (Get<std::uint64_t>(p) != Checksum(bytes.data(), n * kEntryBytes))
      return Result::Error(fmt::format("{} does not match its checksum: the file is damaged (a flipped bit, a bad copy); build or copy it again", where));
    p = bytes.data();
    for (std::uint64_t i = 0; i < n; ++i) {
      AtlasEntry e;
      if (!GetEntry(p, &e)) return Result::Error(fmt::format("curve {} (seed {}, index {}) is malformed", first + i, e.seed, e.index));
      entries.push_back(e);
    }
  }
  if (!read(1).empty()) return Result::Error(fmt::format("the file goes on after the {} curves its header promises", *count));
  return entries;
}

}  // namespace

std::uint64_t AtlasFileSize(std::uint64_t count) {
  return kHeaderBytes + count * kEntryBytes + (count + kAtlasSectionEntries - 1) / kAtlasSectionEntries * kChecksumBytes;
}

std::string SerialiseAtlas(const std::vector<AtlasEntry>& entries) {
  std::string out;
  out.reserve(AtlasFileSize(entries.size()));
  out.append(kMagic, sizeof kMagic);
  Put<std::uint32_t>(&out, kAtlasFormatVersion);
  Put<std::uint32_t>(&out, kAtlasFeatures);
  Put<std::uint64_t>(&out, entries.size());
  PutChecksum(&out, 0);
  for (std::size_t first = 0; first < entries.size(); first += kAtlasSectionEntries) {
    const std::size_t section = out.size();
    const std::size_t end = std::min<std::size_t>(entries.size(), first + kAtlasSectionEntries);
    for (std::size_t i = first; i < end; ++i) PutEntry(&out, entries[i]);
    PutChecksum(&out, section);
  }
  return out;
}

Expected<std::vector<AtlasEntry>> ParseAtlas(const std::string& bytes) {
  std::size_t offset = 0;
  const ReadBytes read = [&](std::size_t n) {
    const std::string part = bytes.substr(offset, n);
    offset += part.size();
    return part;
  };
  return ParseAtlasFrom(read, bytes.size());
}

std::vector<AtlasEntry> ReadAtlasFile(const std::string& path) {
  io::InputFile file(path);
  Result entries = ParseAtlasFrom([&](std::size_t n) { return file.Read(n); }, file.RegularFileSize());
  if (!entries) throw io::FileError(io::FileError::Kind::kRefused, path, entries.error(), path + ": " + entries.error());
  return std::move(*entries);
}

}  // namespace koppel
