// AnalysisStatus' words (solver/analysis/src/status.cpp): they are printed in every Brief() and
// read by users and scripts, so each is spelled as the header documents and no two are alike.
#include "koppel/analysis/status.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <string>

namespace koppel::status_test {
namespace {

TEST_CASE("every status has the word its header documents", "[status]") {
  // reference: the header's comment, "not run", "complete", "partial", "failed"
  CHECK(std::string(ToString(AnalysisStatus::kNotRun)) == "not run");
  CHECK(std::string(ToString(AnalysisStatus::kComplete)) == "complete");
  CHECK(std::string(ToString(AnalysisStatus::kPartial)) == "partial");
  CHECK(std::string(ToString(AnalysisStatus::kFailed)) == "failed");
  const std::set<std::string> words = {ToString(AnalysisStatus::kNotRun), ToString(AnalysisStatus::kComplete),
                                       ToString(AnalysisStatus::kPartial), ToString(AnalysisStatus::kFailed)};
  CHECK(words.size() == 4);
}

TEST_CASE("only complete and partial results are usable", "[status]") {
  CHECK(Usable(AnalysisStatus::kComplete));
  CHECK(Usable(AnalysisStatus::kPartial));
  CHECK_FALSE(Usable(AnalysisStatus::kNotRun));
  CHECK_FALSE(Usable(AnalysisStatus::kFailed));
}

}  // namespace
}  // namespace koppel::status_test
