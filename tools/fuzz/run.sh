#!/usr/bin/env bash
# Fuzzes every reader of koppel's input files (tools/fuzz/input_fuzz.cpp: mechanisms, poses,
# function specs, points, motor curves, atlases, charts) for SECONDS (default 60): builds the
# libFuzzer target with clang in build-fuzz/, seeds it from the catalog entries, tests/data, the
# seeds of tools/fuzz/seeds and the kept corpus tools/fuzz/corpus (each file prefixed with the
# letter that picks its reader), and runs one job under nice with a time limit per input.
# Crashes are written to build-fuzz/crashes/; each one found becomes a test.
# Exit code: libFuzzer's (0 when nothing was found).
#   tools/fuzz/run.sh 1800     # fuzz for half an hour
#   tools/fuzz/run.sh 0        # replay every corpus input once at normal priority, 1 s each
#   tools/fuzz/run.sh merge    # keep what adds coverage: build-fuzz/corpus minimised into tools/fuzz/corpus
# libFuzzer's limit is wall time: on a loaded machine raise it (KOPPEL_FUZZ_TIMEOUT=5) for the
# fuzzing under nice and prove the 1 s limit with the replay afterwards. ctest fuzz_corpus
# replays tools/fuzz/corpus in every build without libFuzzer.
set -euo pipefail
mode="${1:-60}"
cd "$(dirname "$0")/../.."
root="$PWD"
build="${KOPPEL_FUZZ_BUILD:-$root/build-fuzz}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DKOPPEL_FUZZ=ON -DBUILD_TESTING=OFF ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >/dev/null
cmake --build "$build" --target koppel_input_fuzz -j2 >/dev/null
fuzzer="$build/tools/fuzz/koppel_input_fuzz"
corpus="$build/corpus"
mkdir -p "$corpus" "$build/crashes"
# seed: each source file with the letter of its reader in front
seed() {
  local tag="$1"; shift
  for f in "$@"; do
    [ -f "$f" ] || continue
    local to="$corpus/$tag-$(basename "$f")"
    [ -e "$to" ] || { printf '%s' "$tag"; cat "$f"; } > "$to"
  done
}
seed m catalog/entries/*.yaml tests/data/bad/*.yaml tests/data/{antiparallelogram,five-bar,kite,parallelogram,redundant-parallelogram,slider-crank-loads,triple-rocker}.yaml
seed p tests/data/motion-*.yaml
seed f tests/data/function-*.yaml
seed c tests/data/path-points.csv
cp -n tools/fuzz/seeds/* tools/fuzz/corpus/* "$corpus"/ 2>/dev/null || true
if [ "$mode" = merge ]; then
  rm -rf "$build/merged" && mkdir -p "$build/merged"
  "$fuzzer" -merge=1 -timeout=5 -rss_limit_mb=2048 "$build/merged" "$corpus" > "$build/merge.log" 2>&1
  rm -rf tools/fuzz/corpus && mkdir -p tools/fuzz/corpus && cp "$build/merged"/* tools/fuzz/corpus/
  echo "$(ls tools/fuzz/corpus | wc -l) inputs kept in tools/fuzz/corpus ($(du -sh tools/fuzz/corpus | cut -f1))"
  exit 0
fi
if [ "$mode" = 0 ]; then
  status=0
  find "$corpus" -type f -print0 | xargs -0 "$fuzzer" -timeout=1 -rss_limit_mb=2048 -detect_leaks=1 \
    -artifact_prefix="$build/crashes/" > "$build/replay.log" 2>&1 || status=$?
  grep -E "ERROR|SUMMARY" "$build/replay.log" || true
  awk '/^Executed/ {n++; if ($(NF-1) > max) max = $(NF-1)} END {print n " inputs replayed, slowest " max " ms"}' "$build/replay.log"
  exit "$status"
fi
# -rss_limit_mb: the sanitizers' shadow memory plus a generous margin; a leak or an unbounded
# allocation shows long before it. -max_len: the size of the largest catalog entry and more.
exec nice -n 15 "$fuzzer" "$corpus" -max_total_time="$mode" -timeout="${KOPPEL_FUZZ_TIMEOUT:-1}" \
  -rss_limit_mb=2048 -max_len=16384 -detect_leaks=1 -print_final_stats=1 -artifact_prefix="$build/crashes/" \
  -dict="$root/tools/fuzz/input.dict"
