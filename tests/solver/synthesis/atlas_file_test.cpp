// The atlas file (solver/synthesis/src/atlas_file.cpp): it reads back byte for byte; every
// section carries a checksum, so a flipped bit anywhere (every byte of the header, bits spread
// over every section of entries and their checksums) is refused, naming where; a truncated or
// extended file, a format-1 atlas and what is not an atlas are refused; ReadAtlasFile reads the
// same through the file reader. Reference: the layout documented in atlas_file.hpp (36-byte
// header, 132-byte entries, a checksum after every kAtlasSectionEntries entries).
#include "koppel/synthesis/atlas_file.hpp"

#include "koppel/core/input_file.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>

namespace koppel::atlas_file_test {
namespace {

constexpr std::size_t kHeaderBytes = 36, kEntryBytes = 132, kChecksumBytes = 8;  // atlas_file.hpp

// Valid entries without drawing them (drawing 8 000 curves takes a second): what a build
// writes, in index order.
std::vector<AtlasEntry> Entries(std::size_t count) {
  std::vector<AtlasEntry> entries(count);
  for (std::size_t i = 0; i < count; ++i) {
    AtlasEntry& e = entries[i];
    e.seed = 7;
    e.index = i;
    e.crank = 0.5 + 1e-4 * static_cast<double>(i);
    e.coupler = 2.0;
    e.rocker = 1.5;
    e.p = 0.25;
    e.q = -0.5;
    e.branch = i % 2 ? 1 : -1;
    e.side = 1;
    e.closed = i % 3 == 0;
    for (int k = 0; k < kAtlasFeatures; ++k) e.descriptor[k] = static_cast<float>(0.01 * k - 1e-5 * static_cast<double>(i));
  }
  return entries;
}

std::string Flipped(std::string bytes, std::size_t bit) {
  bytes[bit / 8] = static_cast<char>(bytes[bit / 8] ^ (1 << (bit % 8)));
  return bytes;
}

}  // namespace

TEST_CASE("an atlas file reads back to the same entries, byte for byte", "[atlas][file]") {
  // two full sections and a short third one
  const std::size_t count = 2 * kAtlasSectionEntries + 100;
  const std::vector<AtlasEntry> entries = Entries(count);
  const std::string bytes = SerialiseAtlas(entries);
  CHECK(bytes.size() == kHeaderBytes + count * kEntryBytes + 3 * kChecksumBytes);
  CHECK(bytes.size() == AtlasFileSize(count));
  CHECK(AtlasFileSize(0) == kHeaderBytes);
  const Expected<std::vector<AtlasEntry>> back = ParseAtlas(bytes);
  REQUIRE(back);
  CHECK(back->size() == count);
  CHECK(SerialiseAtlas(*back) == bytes);
  REQUIRE(ParseAtlas(SerialiseAtlas({})));
  CHECK(ParseAtlas(SerialiseAtlas({}))->empty());
}

TEST_CASE("a flipped bit anywhere in an atlas is refused", "[atlas][file]") {
  const std::size_t count = 2 * kAtlasSectionEntries + 100;
  const std::string bytes = SerialiseAtlas(Entries(count));
  // every byte of the header, one bit each (which bit rotates with the byte)
  for (std::size_t byte = 0; byte < kHeaderBytes; ++byte) {
    const Expected<std::vector<AtlasEntry>> r = ParseAtlas(Flipped(bytes, 8 * byte + byte % 8));
    INFO("header byte " << byte << ": " << r.error());
    CHECK_FALSE(r);
  }
  // 300 bits spread at random (fixed seed) over the entries and checksums, and the first and
  // last bit of every section: each is refused, naming its section
  const std::size_t section_bytes = kAtlasSectionEntries * kEntryBytes + kChecksumBytes;
  std::vector<std::size_t> bits;
  std::mt19937_64 random(23);
  std::uniform_int_distribution<std::size_t> any_bit(8 * kHeaderBytes, 8 * bytes.size() - 1);
  for (int i = 0; i < 300; ++i) bits.push_back(any_bit(random));
  for (std::size_t s = 0; s < 3; ++s) {
    bits.push_back(8 * (kHeaderBytes + s * section_bytes));
    bits.push_back(std::min(8 * (kHeaderBytes + (s + 1) * section_bytes) - 1, 8 * bytes.size() - 1));
  }
  for (std::size_t bit : bits) {
    const std::size_t section = (bit / 8 - kHeaderBytes) / section_bytes;
    const Expected<std::vector<AtlasEntry>> r = ParseAtlas(Flipped(bytes, bit));
    INFO("bit " << bit << ": " << r.error());
    CHECK_FALSE(r);
    CHECK_THAT(r.error(), Catch::Contains("section " + std::to_string(section + 1) + " of 3") && Catch::Contains("checksum"));
  }
}

TEST_CASE("a truncated, extended, older or foreign file is refused with the reason", "[atlas][file]") {
  const std::string bytes = SerialiseAtlas(Entries(50));
  CHECK_THAT(ParseAtlas(bytes.substr(0, bytes.size() - 1)).error(), Catch::Contains("truncated"));
  CHECK_THAT(ParseAtlas(bytes + "x").error(), Catch::Contains("but the file has"));
  CHECK_THAT(ParseAtlas("name: four-bar\n").error(), Catch::Contains("not a koppel atlas"));
  CHECK_THAT(ParseAtlas("").error(), Catch::Contains("not a koppel atlas"));
  // format 1: the same header without its checksum, the entries packed without sections
  std::string v1 = bytes.substr(0, 28);
  const std::uint32_t one = 1;
  std::memcpy(v1.data() + 12, &one, sizeof one);
  v1 += bytes.substr(kHeaderBytes, 50 * kEntryBytes);
  CHECK_THAT(ParseAtlas(v1).error(), Catch::Contains("atlas format 1") && Catch::Contains("build it again"));
}

TEST_CASE("an entry outside what a build writes is refused even with a valid checksum", "[atlas][file]") {
  std::vector<AtlasEntry> entries = Entries(10);
  entries[4].crank = -1;  // a length must be positive
  CHECK_THAT(ParseAtlas(SerialiseAtlas(entries)).error(), Catch::Contains("curve 4") && Catch::Contains("malformed"));
  entries = Entries(10);
  entries[6].descriptor[3] = std::numeric_limits<float>::quiet_NaN();
  CHECK_THAT(ParseAtlas(SerialiseAtlas(entries)).error(), Catch::Contains("curve 6"));
  entries = Entries(10);
  entries[2].branch = 0;
  CHECK_THAT(ParseAtlas(SerialiseAtlas(entries)).error(), Catch::Contains("curve 2"));
}

TEST_CASE("ReadAtlasFile reads a file as ParseAtlas reads its bytes, and refuses with the path", "[atlas][file]") {
  test::TempDir dir;
  const std::string bytes = SerialiseAtlas(Entries(kAtlasSectionEntries + 1));
  const std::string path = dir.Write("atlas.bin", bytes);
  CHECK(SerialiseAtlas(ReadAtlasFile(path)) == bytes);
  const std::string damaged = dir.Write("damaged.bin", Flipped(bytes, 8 * (kHeaderBytes + 5000)));
  try {
    ReadAtlasFile(damaged);
    FAIL("a damaged atlas was read");
  } catch (const io::FileError& e) {
    CHECK(e.kind() == io::FileError::Kind::kRefused);
    CHECK_THAT(e.what(), Catch::StartsWith(damaged + ": section 1 of 2"));
  }
  CHECK_THROWS_AS(ReadAtlasFile("/dev/zero"), io::FileError);
  CHECK_THROWS_AS(ReadAtlasFile(dir.path().string()), io::FileError);
}

}  // namespace koppel::atlas_file_test
