// The atlas file of path synthesis (atlas.hpp), format 2, little endian:
//   header (36 bytes): "KOPPEL-ATLAS", the format version (u32, 2), the features per entry
//     (u32, 18), the entry count (u64), and the XXH3-64 of those 28 bytes;
//   the entries in sections of kAtlasSectionEntries (the last one shorter), each section followed
//     by the XXH3-64 of its bytes. An entry (132 bytes): seed, index (u64); crank, coupler,
//     rocker, p, q (f64); branch, side (i8); closed (u8); a zero byte; the descriptor (18 f32).
// A read checks every checksum before it trusts a byte of its section: a flipped bit, a truncated
// or an extended file is refused, naming the section. Format 1 (before the checksums) is refused
// with the advice to build the atlas again.
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/synthesis/atlas.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace koppel {

inline constexpr std::uint32_t kAtlasFormatVersion = 2;
// Entries per checksummed section: 540 KB, so a damaged byte is placed to within half a megabyte
// and the checksums add 15 ppm to the file.
inline constexpr std::uint64_t kAtlasSectionEntries = 4096;

std::string SerialiseAtlas(const std::vector<AtlasEntry>& entries);
// The error says what is wrong and where (the header, section k, entry i).
Expected<std::vector<AtlasEntry>> ParseAtlas(const std::string& bytes);
// Bytes of a file holding `count` entries.
std::uint64_t AtlasFileSize(std::uint64_t count);

// Reads an atlas file section by section (memory holds the entries, not the file too), through
// the one file reader (koppel/core/input_file.hpp: registered as an input of the run). Throws
// io::FileError (kRefused) with "path: what is wrong".
std::vector<AtlasEntry> ReadAtlasFile(const std::string& path);

}  // namespace koppel
