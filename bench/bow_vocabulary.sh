#!/usr/bin/env bash
# Trains candidate bag-of-words vocabularies and measures their place recognition on
# tum_fr1_xyz_300 (every 10th frame against the ground truth), writing
# bench/results/bow_vocabulary.md and bench/results/bow_vocabulary.jsonl.
#
#   bench/bow_vocabulary.sh [--build DIR] [--out DIR]
#
# Candidates: synthetic sequences from `segslam synth` (the shipped vocabulary's data) and
# fr1_xyz_300 itself (trained on the evaluation sequence: an optimistic reference, not a fair
# candidate); each at depth 4 and 5, every 5th frame. Needs ../shared (or
# SEGSLAM_SHARED_DIR).
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_bow"
bench_parse_build_out "$@"
segslam="$build/segslam"
evaluate="$build/bench/segslam_bench_bow_place_recognition"
[[ -x "$segslam" && -x "$evaluate" ]] || bench_fail "build first (./setup.sh)"
bench_require_dir "$shared/data"
mkdir -p "$out" "$root/bench/results"

"$root/scripts/render_vocabulary_sequences.sh" "$segslam" "$out/synth"
synth_args=()
for sequence in "$out"/synth/*/; do synth_args+=(--dataset "$sequence"); done

# name | training arguments
candidates=(
  "synth k10 d4|${synth_args[*]} --k 10 --depth 4"
  "synth k10 d5|${synth_args[*]} --k 10 --depth 5"
  "fr1 (evaluation data) k10 d4|--dataset $shared/data/tum_fr1_xyz_300 --k 10 --depth 4"
  "fr1 (evaluation data) k10 d5|--dataset $shared/data/tum_fr1_xyz_300 --k 10 --depth 5"
)

results="$root/bench/results/bow_vocabulary.jsonl"
: > "$results"
for candidate in "${candidates[@]}"; do
  IFS='|' read -r name arguments <<< "$candidate"
  file="$out/${name// /_}.bin"
  echo "== $name"
  # A vocabulary trained by an earlier run is reused, with its training time.
  if [[ ! -f "$file" || ! -f "$file.seconds" ]]; then
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$segslam" --log-level warn vocab train $arguments --out "$file"
    python3 -c "import sys; print(float(sys.argv[1]) - float(sys.argv[2]))" "$(date +%s.%N)" "$start" > "$file.seconds"
  fi
  seconds=$(cat "$file.seconds")
  "$evaluate" "$file" "$shared/data/tum_fr1_xyz_300" 10 |
    python3 -c "import json,sys,os; r=json.load(sys.stdin); r.update(name=sys.argv[1], train_s=float(sys.argv[2]), bytes=os.path.getsize(sys.argv[3])); print(json.dumps(r))" \
      "$name" "$seconds" "$file" >> "$results"
done

python3 - "$results" "$root/bench/results/bow_vocabulary.md" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
with open(sys.argv[2], "w") as out:
    out.write("# Bag-of-words vocabularies: place recognition on tum_fr1_xyz_300\n\n")
    out.write("Every 10th frame; revisit = >= 1 s apart, within 0.10 m and 10 deg; distinct = > 0.20 m "
              "or 20 deg apart. AP: average precision of revisit pairs ranked by score; top-1: the "
              "best database match (>= 1 s away) is a revisit. Train time includes ORB extraction "
              "(`bench/bow_vocabulary.sh`).\n\n")
    out.write("| training data | words | file | train | transform/frame | adjacent | revisit | distinct | AP | top-1 |\n")
    out.write("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n")
    for r in rows:
        out.write(f"| {r['name']} | {r['words']} | {r['bytes']/1024:.0f} KiB | {r['train_s']:.1f} s | "
                  f"{r['transform_ms_per_frame']:.2f} ms | {r['mean_score_adjacent']:.3f} | "
                  f"{r['mean_score_revisit']:.3f} | {r['mean_score_distinct']:.3f} | "
                  f"{r['average_precision']:.3f} | {r['top1_recall']:.2f} ({r['top1_queries']}) |\n")
print(open(sys.argv[2]).read())
PY
