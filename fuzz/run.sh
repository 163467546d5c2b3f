#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (in build-fuzz/) and runs each one for a bounded time.
# Usage: fuzz/run.sh [seconds_per_target]   (default 20)
# Seeds come from fuzz/corpus/<target>/ (left unchanged), keywords from fuzz/<target>.dict when
# there is one; what the fuzzer finds goes under build-fuzz/fuzz_work/<target>/. Exits non-zero
# when any target crashes, leaks or times out; the input that did it is in
# build-fuzz/fuzz_work/<target>/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
build_dir=build-fuzz

CC=clang CXX=clang++ cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSEGSLAM_BUILD_FUZZ=ON -DSEGSLAM_BUILD_TESTS=OFF -DSEGSLAM_BUILD_BENCH=OFF >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target segslam_fuzz

# Runs one target for the bounded time; its summary (or the failure) goes to $work/summary.txt.
fuzz_target() {
  local target=$1 work="$build_dir/fuzz_work/$1"
  mkdir -p "$work/corpus" "$work/findings"
  local options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
                 -artifact_prefix="$work/findings/")
  if [ -f "fuzz/$target.dict" ]; then options+=(-dict="fuzz/$target.dict"); fi
  {
    echo "== $target (${seconds} s)"
    if "$build_dir/fuzz/$target" "${options[@]}" "$work/corpus" "fuzz/corpus/$target" \
        >"$work/log.txt" 2>&1; then
      grep -E '^Done [0-9]+ runs' "$work/log.txt" || true
      grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+' "$work/log.txt" | tail -n 1 || true
    else
      tail -n 40 "$work/log.txt"
      echo "!! $target failed: inputs in $work/findings/, log in $work/log.txt"
      return 1
    fi
  } >"$work/summary.txt"
}

# The targets run side by side, one per core: each still gets its full time.
targets=()
for source in fuzz/fuzz_*.cc; do targets+=("$(basename "$source" .cc)"); done
declare -A pids
failed=()
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  fuzz_target "$target" &
  pids[$target]=$!
done
for target in "${targets[@]}"; do
  wait "${pids[$target]}" || failed+=("$target")
  cat "$build_dir/fuzz_work/$target/summary.txt"
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzzing found problems in: ${failed[*]}"
  exit 1
fi
echo "fuzzing found nothing in ${seconds} s per target"
