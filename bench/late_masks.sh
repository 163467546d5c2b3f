#!/usr/bin/env bash
# Measures what the two map-cleaning checks (points seen through by the depth image; points on a
# late network mask) do to the ATE when masks arrive late, and that they do not hurt a static
# scene. Writes bench/results/late_masks.md.
#
#   bench/late_masks.sh [--build DIR] [--out DIR]
#
# All runs are deterministic: `--network-interval N --network-latency N` reproduces the threaded
# pipeline's timing (a network output every N frames, used N frames after its frame), so the
# figures do not depend on how busy the machine is.
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_late_masks"
bench_parse_build_out "$@"
bench_require_segslam
bench_require_dir "$shared/data"
walker="$shared/data/tum_fr1_xyz_300_walker"
fr1="$shared/data/tum_fr1_xyz_300"
mkdir -p "$out" "$root/bench/results"

declare -A checks=(
  [off]="--cull-seen-through 0 --no-late-mask-culling"
  [seen-through]="--no-late-mask-culling"
  [late-mask]="--cull-seen-through 0"
  [both]=""
)

# sequence name | dataset | masks | timing options | checks
configurations=(
  "walker|$walker|none||off" "walker|$walker|none||both"
  "walker|$walker|semantic|--network-interval 5|off" "walker|$walker|semantic|--network-interval 5|both"
  "walker|$walker|semantic|--network-interval 12 --network-latency 12|off"
  "walker|$walker|semantic|--network-interval 12 --network-latency 12|seen-through"
  "walker|$walker|semantic|--network-interval 12 --network-latency 12|late-mask"
  "walker|$walker|semantic|--network-interval 12 --network-latency 12|both"
  "walker|$walker|fused|--network-interval 12 --network-latency 12|off"
  "walker|$walker|fused|--network-interval 12 --network-latency 12|both"
  "walker|$walker|fused|--network-interval 20 --network-latency 20|off"
  "walker|$walker|fused|--network-interval 20 --network-latency 20|both"
  "fr1_xyz_300|$fr1|none||off" "fr1_xyz_300|$fr1|none||both"
  "fr1_xyz_300|$fr1|fused||off" "fr1_xyz_300|$fr1|fused||both"
)

table="$root/bench/results/late_masks.md"
{
  echo "# Map cleaning with late masks"
  echo
  echo "\`bench/late_masks.sh\`: \`segslam run --deterministic --no-map\`. Checks: seen-through ="
  echo "points that two frames' depth sees through are culled; late-mask = points on a late network"
  echo "output's person are culled."
  echo
  echo "| sequence | masks | timing | checks | ATE (m) | keyframes | points culled by late masks |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
} > "$table"
n=0
for configuration in "${configurations[@]}"; do
  IFS='|' read -r name dataset masks timing check <<< "$configuration"
  n=$((n + 1))
  run_dir="$out/run_$n"
  # shellcheck disable=SC2086
  "$segslam" run --dataset "$dataset" --out "$run_dir" --seg "$masks" --deterministic --no-map \
    $timing ${checks[$check]} > "$run_dir.log" 2>&1
  row=$(python3 - "$run_dir/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"{s['ate_rmse_m']:.4f} | {s['keyframes']} | {s.get('points_culled_by_late_masks', 0)}")
PY
)
  echo "| $name | $masks | ${timing:-default} | $check | $row |" >> "$table"
  echo "late_masks.sh: $name $masks $timing $check: $row"
done
echo "late_masks.sh: wrote $table"
