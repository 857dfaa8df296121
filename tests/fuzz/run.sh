#!/bin/sh
# tests/fuzz/run.sh — the fuzzers' corpora and runs (README.md); `make fuzz` calls it.
#   tests/fuzz/run.sh check             is clang's libFuzzer there? (exit 2 when not)
#   tests/fuzz/run.sh run BUILD SECONDS  each fuzzer of BUILD/bin for SECONDS seconds
# A run first replays tests/fuzz/crashes/<fuzzer>/ (every input a fuzzer once crashed
# on: a regression test), then fuzzes from BUILD/corpus/<fuzzer> (kept between runs,
# so longer runs build on shorter ones) and the seeds: tests/fuzz/seed_inputs/<fuzzer>/,
# examples/, tests/io/bad/ and reference_images/MANIFEST, copied to BUILD/seed_inputs/.
# It prints one line per fuzzer (executions, executions per second, corpus size)
# and exits 1 when any fuzzer found something: its input is in BUILD/artifacts/.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
fuzzers="fuzz_json fuzz_options fuzz_grading"

max_len() {
  case $1 in
    fuzz_json) echo 8192 ;;       # the largest example and bad file are under 2 KB
    fuzz_options) echo 4096 ;;
    fuzz_grading) echo 16384 ;;   # examples/face_a.png is 8.7 KB
  esac
}
dict() {
  case $1 in
    fuzz_json) echo "$here/json.dict" ;;
    fuzz_options) echo "$here/options.dict" ;;
    fuzz_grading) echo "$here/grading.dict" ;;
  esac
}

check() {
  probe=$(mktemp -d)
  printf '%s\n' '#include <cstddef>' '#include <cstdint>' \
    'extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }' \
    > "$probe/probe.cpp"
  if ! clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" 2> "$probe/err"; then
    cat "$probe/err" >&2
    rm -rf "$probe"
    echo "fuzz: clang++ with libFuzzer is missing (Debian: clang and libclang-rt-dev)" >&2
    exit 2
  fi
  rm -rf "$probe"
}

# The seeds of one fuzzer, copied fresh into BUILD/seed_inputs/<fuzzer>.
seeds() {
  dir=$1/seed_inputs/$2
  rm -rf "$dir"
  mkdir -p "$dir"
  case $2 in
    fuzz_json)
      cp "$repo"/examples/*.json "$repo"/examples/csg/*.json "$dir"/
      for seed in "$repo"/tests/io/bad/*.json; do cp "$seed" "$dir/bad_$(basename "$seed")"; done ;;
    fuzz_options)
      cp "$here"/seed_inputs/options/* "$dir"/
      # --load with each example spline file after the NUL byte (fuzz_options.cpp).
      for seed in "$repo"/examples/*.json "$repo"/tests/io/bad/*.json; do
        { printf -- '--load\nfile.json\n--out\nx.png'; printf '\000'; cat "$seed"; } \
          > "$dir/load_$(basename "$seed" .json)"
      done ;;
    fuzz_grading)
      cp "$here"/seed_inputs/grading/* "$repo"/examples/*.png "$repo"/reference_images/MANIFEST "$dir"/ ;;
  esac
}

run() {
  build=$1
  seconds=$2
  failed=""
  for f in $fuzzers; do
    bin=$build/bin/$f
    [ -x "$bin" ] || { echo "fuzz: $bin is missing (make fuzz builds it)" >&2; exit 2; }
    seeds "$build" "$f"
    mkdir -p "$build/corpus/$f" "$build/artifacts/$f" "$build/logs"
    log=$build/logs/$f.log
    # Regression: every input a fuzzer once crashed on must now pass.
    crashes=$(find "$here/crashes/$f" -type f 2>/dev/null | sort)
    if [ -n "$crashes" ]; then
      # shellcheck disable=SC2086 # one argument per file
      if ! "$bin" -runs=1 $crashes > "$build/logs/$f.replay.log" 2>&1; then
        echo "fuzz: $f: an input of tests/fuzz/crashes/$f fails again (log: $build/logs/$f.replay.log):" >&2
        tail -n 30 "$build/logs/$f.replay.log" >&2
        failed="$failed $f"
        continue
      fi
    fi
    status=0
    "$bin" -dict="$(dict "$f")" -max_len="$(max_len "$f")" -timeout=10 -rss_limit_mb=2048 \
      -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$build/artifacts/$f/" \
      "$build/corpus/$f" "$build/seed_inputs/$f" > "$log" 2>&1 || status=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
    units=$(find "$build/corpus/$f" -type f | wc -l)
    if [ "$status" -eq 0 ]; then
      echo "fuzz: $f: ${execs:-?} executions in ${seconds} s, ${rate:-?}/s, corpus $units inputs: clean"
    else
      echo "fuzz: $f: FOUND something after ${execs:-?} executions (exit $status; log: $log):" >&2
      grep -E 'ERROR|runtime error|fuzz finding|SUMMARY|artifact|^    #[0-9]' "$log" | head -n 40 >&2 || true
      failed="$failed $f"
    fi
  done
  if [ -n "$failed" ]; then
    echo "fuzz: failed:$failed (inputs in $build/artifacts/; keep each in tests/fuzz/crashes/<fuzzer>/)" >&2
    exit 1
  fi
}

case ${1:-} in
  check) check ;;
  run) [ $# -eq 3 ] || { echo "usage: $0 run BUILD SECONDS" >&2; exit 2; }; run "$2" "$3" ;;
  *) echo "usage: $0 check | run BUILD SECONDS" >&2; exit 2 ;;
esac
