#!/usr/bin/env bash
# The shards of a sharded Catch2 suite (koppel_add_tests ... SHARDS N) run every test case once:
# the test cases each shard's file-name tags select add up to the whole suite's, so that a test
# file whose cases no shard selects (a case outside a *_test.cpp, a tag misspelt) cannot hide.
# Usage: shards_cover.sh TEST_EXECUTABLE SPEC...
set -euo pipefail
binary=$1
shift
# Catch2 2 exits with the number of test cases listed: the listing's exit code says nothing
count() { "$binary" "$@" --list-test-names-only | grep -c . || true; }
all=$(set +o pipefail; count)
sum=0
for spec in "$@"; do
  n=$(set +o pipefail; count -# "$spec")
  sum=$((sum + n))
done
echo "$all test cases in all, $sum in the $# shards"
[ "$all" -eq "$sum" ]
