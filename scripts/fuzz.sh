#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz; clang-15, ASan + UBSan) in build-fuzz and runs
# each one for a while over its corpus (tests/fuzz/corpus/<target>) with its dictionary.
# gpu_sequence draws on llvmpipe and lavapipe: the build needs the GL and Vulkan backends.
# New inputs go to a scratch directory, never into the repository's corpus; a crash, leak or
# timeout stops the run, leaves its input in build-fuzz/findings/<target>/ and fails.
#
#   bash scripts/fuzz.sh                 # every target, 20 s each (the test command's run)
#   bash scripts/fuzz.sh 3600 scene      # one target for an hour (the long runs of docs/records/testing.md)
#   FUZZ_RUNS=1000000 bash scripts/fuzz.sh 0 bake_cache   # a number of executions instead
#   FUZZ_ARGS=-print_coverage=1 bash scripts/fuzz.sh 20 scene   # and the lines it reached, in its log
#   FUZZ_RUNS=1000000 FUZZ_CPU_SECONDS=3600 FUZZ_KEEP=1 bash scripts/fuzz.sh 0 scene
#       # the long runs: a million executions or an hour of the fuzzer's CPU time, whichever
#       # comes first (wall time means little on a shared machine); FUZZ_KEEP keeps the new
#       # inputs in build-fuzz/long/<target>, so that a later run goes on from them
#   FUZZ_PARALLEL=2 bash scripts/fuzz.sh  # two targets at a time (a fuzzer runs on one core;
#       # the default is 1, one after the other)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(api_sequence bake_cache scene png_map gltf gpu_sequence mesh_field)
jobs=${FUZZ_BUILD_JOBS:-$(nproc)}
build=${FUZZ_BUILD_DIR:-build-fuzz}

# FUZZ_NO_BUILD=1: the build is up to date (several long runs at once share it).
if [ -z "${FUZZ_NO_BUILD:-}" ]; then
CC=clang-15 CXX=clang++-15 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRASS_FUZZ=ON ${FUZZ_CMAKE_ARGS:-} \
  -DGRASS_BUILD_TESTS=OFF -DGRASS_BUILD_SAMPLES=ON >/dev/null
cmake --build "$build" -j "$jobs" --target $(printf 'fuzz_%s ' "${targets[@]}")
fi

export ASAN_OPTIONS="detect_leaks=1:intercept_tls_get_addr=0" # scripts/test.sh says why
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export ASAN_SYMBOLIZER_PATH=/usr/bin/llvm-symbolizer
status=0
# Runs a fuzzer with its log in $1. With FUZZ_CPU_SECONDS, runs it in the background and
# interrupts it (SIGINT: libFuzzer prints its final stats and exits 72) once its user +
# system CPU time reaches that many seconds.
run_fuzzer() {
  local log=$1 limit=${FUZZ_CPU_SECONDS:-}
  shift
  if [ -z "$limit" ]; then
    "$@" 2>"$log"
    return
  fi
  "$@" 2>"$log" &
  local pid=$! ticks cpu=0
  ticks=$(getconf CLK_TCK)
  while kill -0 "$pid" 2>/dev/null; do
    sleep 5
    local now
    now=$(awk '{print int(($14 + $15) / '"$ticks"')}' "/proc/$pid/stat" 2>/dev/null) || break # it ended
    cpu=$now
    if [ "$cpu" -ge "$limit" ]; then
      echo "   $cpu s of CPU: interrupting"
      kill -INT "$pid"
      break
    fi
  done
  local rc=0
  wait "$pid" || rc=$?
  echo "   about $cpu s of CPU"
  [ "$rc" -eq 72 ] && rc=0 # libFuzzer's exit code after an interrupt
  return $rc
}

# Fuzzes target $1; prints its report and returns 1 when it found a failure.
fuzz_target() {
  local t=$1 scratch findings max_len label args status=0
  if [ -n "${FUZZ_KEEP:-}" ]; then
    scratch=$build/long/$t
    mkdir -p "$scratch"
  else
    scratch=$(mktemp -d)
  fi
  findings=$build/findings/$t
  mkdir -p "$findings"
  # FUZZ_TIMEOUT: seconds one input may take (wall time: raise it on a loaded machine).
  # The longest input: 64 KiB, but 256 KiB for the scene and glTF loaders, whose hostile files
  # (a scene nested 60,000 deep is 120 KB) did not fit in 64 KiB (issue 37).
  max_len=65536
  case $t in scene | gltf) max_len=262144 ;; esac
  args=(-timeout="${FUZZ_TIMEOUT:-30}" -rss_limit_mb="${FUZZ_RSS_LIMIT_MB:-2048}" -max_len="$max_len" -artifact_prefix="$findings/" -print_final_stats=1)
  # FUZZ_ARGS: more libFuzzer options (-print_coverage=1: which lines the run reached).
  # shellcheck disable=SC2206
  [ -n "${FUZZ_ARGS:-}" ] && args+=(${FUZZ_ARGS})
  [ -f "tests/fuzz/$t.dict" ] && args+=(-dict="tests/fuzz/$t.dict")
  if [ -n "${FUZZ_RUNS:-}" ]; then args+=(-runs="$FUZZ_RUNS"); else args+=(-max_total_time="$seconds"); fi
  # A fixed seed (the test command's short runs): the same mutations in the same order on
  # every run, so that a run fails for a change in the code, not for the draw.
  if [ -n "${FUZZ_SEED:-}" ]; then args+=(-seed="$FUZZ_SEED"); fi
  label="$seconds s"
  [ -n "${FUZZ_RUNS:-}" ] && label="$FUZZ_RUNS runs"
  echo "== fuzz_$t: $label${FUZZ_CPU_SECONDS:+ or $FUZZ_CPU_SECONDS s of CPU}"
  if ! run_fuzzer "$build/findings/$t.log" "$build/tests/fuzz/fuzz_$t" "${args[@]}" "$scratch" "tests/fuzz/corpus/$t"; then
    echo "fuzz_$t found a failure: $build/findings/$t.log, input in $findings/"
    tail -40 "$build/findings/$t.log"
    status=1
  fi
  grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)" \
    "$build/findings/$t.log" || true
  [ -n "${FUZZ_KEEP:-}" ] || rm -rf "$scratch"
  return $status
}

parallel=${FUZZ_PARALLEL:-1}
reports=$(mktemp -d)
pids=()
names=()
# Waits for the oldest running target and prints its report.
wait_oldest() {
  wait "${pids[0]}" || status=1
  cat "$reports/${names[0]}"
  pids=("${pids[@]:1}")
  names=("${names[@]:1}")
}
for t in "${targets[@]}"; do
  (( ${#pids[@]} >= parallel )) && wait_oldest
  fuzz_target "$t" >"$reports/$t" 2>&1 &
  pids+=($!)
  names+=("$t")
done
while (( ${#pids[@]} > 0 )); do wait_oldest; done
rm -rf "$reports"
exit $status
