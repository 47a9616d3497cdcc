#!/usr/bin/env bash
# Builds the fuzzers (the "fuzz" CMake preset, into build-fuzz/: the asan preset's flags with
# libFuzzer's coverage tracing, only the fuzzers and the libraries they link) and runs every one
# for a bounded time (default 30 s each) from its seed corpus, two at a time (CURVEFOLD_JOBS); CI
# runs this.
# Usage: scripts/fuzz.sh [SECONDS]
# New corpus entries go to a scratch folder; a crash leaves its input in fuzz-artifacts/ and fails.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
scripts/setup.sh
werror=()
[ "${CI:-}" = "true" ] && werror=(-DCURVEFOLD_WERROR=ON)  # as scripts/build.sh
cmake --preset fuzz "${werror[@]}" >/dev/null
cmake --build --preset fuzz -j"${CURVEFOLD_JOBS:-2}"
build=build-fuzz
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p fuzz-artifacts
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# The fuzzers run CURVEFOLD_JOBS (2) at a time, each single-threaded for its full time, so the
# whole run takes half as long on 2 cores; each is reported when it ends, in this order.
parallel="${CURVEFOLD_JOBS:-2}"
declare -a fuzzers=() pids=()
reported=0
failed=0

report() {
  local fuzzer="${fuzzers[$reported]}" status=0
  wait "${pids[$reported]}" || status=$?
  reported=$((reported + 1))
  echo "== $fuzzer (${seconds} s)"
  grep -E "^(#[0-9]+ +DONE|stat::number_of_executed_units|SUMMARY|ERROR|invariant)" \
    "$scratch/$fuzzer.log" || true
  if [ "$status" -ne 0 ]; then
    tail -40 "$scratch/$fuzzer.log" >&2
    echo "$fuzzer failed; its input is in fuzz-artifacts/" >&2
    failed=1
  fi
}

run() {
  local fuzzer="$1"
  shift
  mkdir -p "$scratch/$fuzzer"
  "$build/fuzz/$fuzzer" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
    -artifact_prefix="fuzz-artifacts/$fuzzer-" -print_final_stats=1 "$scratch/$fuzzer" "$@" \
    >"$scratch/$fuzzer.log" 2>&1 &
  fuzzers+=("$fuzzer")
  pids+=("$!")
  if [ $((${#fuzzers[@]} - reported)) -ge "$parallel" ]; then report; fi
}

run fuzz_fold fuzz/corpus/fold
run fuzz_writers fuzz/corpus/writers
run fuzz_obj_reader tests/data/obj
run fuzz_design_reader fuzz/corpus/design
run fuzz_crease_pattern_fold tests/data/crease_patterns fuzz/corpus/crease_pattern_fold
run fuzz_crease_pattern_svg tests/data/crease_patterns fuzz/corpus/crease_pattern_svg
run fuzz_recording_reader tests/data/recordings fuzz/corpus/recording
run fuzz_gesture_script examples/scripts fuzz/corpus/gesture
while [ "$reported" -lt "${#fuzzers[@]}" ]; do report; done
[ "$failed" -eq 0 ] || exit 1
echo "fuzzers: no crash in ${seconds} s each"
