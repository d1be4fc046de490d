#!/usr/bin/env bash
# Fuzzes the mechanism reader for SECONDS (default 60): builds the libFuzzer target with clang in
# build-fuzz/, seeds it from the catalog entries and tests/data, and runs it under nice with a
# time limit per input. Crashes are written to build-fuzz/crashes/; each one found becomes a file
# in tests/data/bad/. Exit code: libFuzzer's (0 when nothing was found).
#   tools/fuzz/run.sh 1800
#   tools/fuzz/run.sh 0        # replays every corpus input once at normal priority, 1 s each
# libFuzzer's limit is wall time: on a loaded machine raise it (KOPPEL_FUZZ_TIMEOUT=5) for the
# fuzzing under nice and prove the 1 s limit with the replay afterwards.
set -euo pipefail
seconds="${1:-60}"
cd "$(dirname "$0")/../.."
root="$PWD"
build="${KOPPEL_FUZZ_BUILD:-$root/build-fuzz}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DKOPPEL_FUZZ=ON -DBUILD_TESTING=OFF ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >/dev/null
cmake --build "$build" --target koppel_mechanism_fuzz -j2 >/dev/null
fuzzer="$build/tools/fuzz/koppel_mechanism_fuzz"
corpus="$build/corpus"
mkdir -p "$corpus" "$build/crashes"
cp -n catalog/entries/*.yaml tests/data/*.yaml tests/data/bad/*.yaml "$corpus"/ 2>/dev/null || true
if [ "$seconds" = 0 ]; then
  status=0
  find "$corpus" -type f -print0 | xargs -0 "$fuzzer" -timeout=1 -rss_limit_mb=2048 -detect_leaks=1 \
    -artifact_prefix="$build/crashes/" > "$build/replay.log" 2>&1 || status=$?
  grep -E "ERROR|SUMMARY" "$build/replay.log" || true
  awk '/^Executed/ {n++; if ($(NF-1) > max) max = $(NF-1)} END {print n " inputs replayed, slowest " max " ms"}' "$build/replay.log"
  exit "$status"
fi
# -rss_limit_mb: the sanitizers' shadow memory plus a generous margin; a leak or an unbounded
# allocation shows long before it. -max_len: the size of the largest catalog entry and more.
exec nice -n 15 "$fuzzer" "$corpus" -max_total_time="$seconds" -timeout="${KOPPEL_FUZZ_TIMEOUT:-1}" \
  -rss_limit_mb=2048 -max_len=16384 -detect_leaks=1 -print_final_stats=1 -artifact_prefix="$build/crashes/" \
  -dict="$root/tools/fuzz/mechanism.dict"
