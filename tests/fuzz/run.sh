#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, build dir build-fuzz) and runs each one.
#   tests/fuzz/run.sh [SECONDS]      (default 30 per target; two targets run at a time)
# Inputs: generated seeds (make_seeds.py) plus the corpus the earlier runs grew in
# BUILD/fuzz/corpus/<target>; dictionaries *.dict. A crash, sanitizer report, leak, timeout (>10 s per
# input) or memory blow-up (>2 GiB) makes the script exit 1 after all targets ran, naming the input
# saved as BUILD/fuzz/crashes/<target>-crash-<sha1>. Env: MIXENGINE_FUZZ_BUILD (default REPO/build-fuzz),
# MIXENGINE_FUZZ_TARGETS (default "stl obj threemf settings formula").
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
SECONDS_EACH=${1:-30}
BUILD=${MIXENGINE_FUZZ_BUILD:-$REPO/build-fuzz}
TARGETS=(${MIXENGINE_FUZZ_TARGETS:-stl obj threemf settings formula})

command -v clang++ >/dev/null || { echo "run.sh: clang++ not found (./install.sh installs clang)" >&2; exit 1; }
mkdir -p "$BUILD"
cmake -S "$REPO" -B "$BUILD" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMIXENGINE_FUZZ=ON -DMIXENGINE_TESTS=OFF >"$BUILD/cmake.log" 2>&1 || { cat "$BUILD/cmake.log" >&2; exit 1; }
ninja -C "$BUILD" -j2 fuzz_targets >"$BUILD/ninja.log" 2>&1 || { tail -30 "$BUILD/ninja.log" >&2; exit 1; }
python3 "$HERE/make_seeds.py" "$BUILD/fuzz/seeds" >/dev/null
mkdir -p "$BUILD/fuzz/crashes" "$BUILD/fuzz/logs"

run_target() { # TARGET: runs one fuzzer, prints one summary line, returns its exit code
  local t=$1 dict=() corpus=$BUILD/fuzz/corpus/$1 log=$BUILD/fuzz/logs/$1.log
  mkdir -p "$corpus"
  [ -f "$HERE/$t.dict" ] && dict=(-dict="$HERE/$t.dict")
  local rc=0
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions="$HERE/lsan.supp" UBSAN_OPTIONS=print_stacktrace=1 \
    "$BUILD/fuzz/${t}_fuzz" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$BUILD/fuzz/crashes/$t-" -print_final_stats=1 "${dict[@]}" \
    "$corpus" "$BUILD/fuzz/seeds/$t" >"$log" 2>&1 || rc=$?
  local runs cov
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
  if [ "$rc" -eq 0 ]; then
    echo "fuzz $t: ok, $runs inputs in ${SECONDS_EACH} s, coverage $cov, corpus $(ls "$corpus" | wc -l) files"
  else
    echo "fuzz $t: FAILED (exit $rc) after $runs inputs; log $log:"
    grep -E 'ERROR|SUMMARY|Test unit written|terminate|uncaught' "$log" | head -8 | sed 's/^/    /'
  fi
  return "$rc"
}

failed=()
pids=()
names=()
for t in "${TARGETS[@]}"; do
  run_target "$t" &
  pids+=($!)
  names+=("$t")
  if [ ${#pids[@]} -eq 2 ]; then  # two at a time: the machine has 2 cores
    wait "${pids[0]}" || failed+=("${names[0]}")
    pids=("${pids[1]}")
    names=("${names[1]}")
  fi
done
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || failed+=("${names[$i]}")
done
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: ${#failed[@]} of ${#TARGETS[@]} targets failed: ${failed[*]}"
  exit 1
fi
echo "fuzz: ${#TARGETS[@]} targets ran ${SECONDS_EACH} s each, no crash"
