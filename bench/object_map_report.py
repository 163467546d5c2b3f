#!/usr/bin/env python3
"""Tables of bench/object_map.sh.

    object_map_report.py RUNS.jsonl TRUE_COUNTS_JSON OUT.md OUT.json
"""
import collections
import json
import os
import subprocess
import sys


def commit():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()


def label_counts(objects):
    counts = collections.Counter()
    for o in objects:
        counts[o["label"] + (" (dynamic)" if o["dynamic"] else "")] += 1
    return counts


def synthetic_table(rows):
    lines = ["| sequence | labels | layer | true objects | map objects | precision | recall | "
             "map objects per true object | missed / unmatched |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for row in rows:
        if not row["score"]:
            continue
        for layer in ("static", "dynamic"):
            s = row["score"][layer]
            misses = ", ".join(s["missed"] + s["unmatched"]) or "-"
            lines.append(f"| {row['sequence']} | {row['kind']} | {layer} | {s['true_objects']} | "
                         f"{s['map_objects']} | {s['precision']:.2f} | {s['recall']:.2f} | "
                         f"{s['fragments_per_true_object']:.2f} | {misses} |")
    return lines


def real_table(rows, truth):
    lines = ["| sequence | run | " + " | ".join(f"{label} (true)" for label in
                                                 next(iter(truth.values()))) + " | other |",
             "| --- | --- | " + " | ".join("---" for _ in next(iter(truth.values()))) + " | --- |"]
    for row in rows:
        if row["sequence"] not in truth:
            continue
        counts = label_counts(row["objects"])
        wanted = truth[row["sequence"]]
        cells = [f"{counts.get(label, 0)} ({n})" for label, n in wanted.items()]
        other = ", ".join(f"{k} {v}" for k, v in sorted(counts.items()) if k not in wanted) or "-"
        lines.append(f"| {row['sequence']} | {row['kind']} | " + " | ".join(cells) + f" | {other} |")
    return lines


def cost_table(rows):
    lines = ["| sequence | run | keyframes | objects [s] | run wall [s] | share |",
             "| --- | --- | --- | --- | --- | --- |"]
    for row in rows:
        share = 100 * row["objects_seconds"] / row["wall_seconds"]
        lines.append(f"| {row['sequence']} | {row['kind']} | {row['keyframes']} | "
                     f"{row['objects_seconds']:.3f} | {row['wall_seconds']:.1f} | {share:.2f} % |")
    return lines


def main():
    rows = [json.loads(line) for line in open(sys.argv[1])]
    truth = json.loads(sys.argv[2])
    lines = ["# Object map", "",
             f"`bench/object_map.sh` at {commit()}: `segslam run` (1 cm voxels); synthetic runs "
             "scored by `bench/object_map_score.py` (3D IoU >= 0.5 on 5 cm voxels; a dynamic "
             "object matches a person when >= 50 % of it lies on their path). `oracle`: the "
             "dataset's labels and instances; `semantic`: the network's labels (ESPNetv2 Pascal "
             "VOC), both `--deterministic`; `default`: `segslam run` as it comes (30 Hz, fused "
             "masks).", "", "## Synthetic", ""]
    lines += synthetic_table(rows)
    lines += ["", "## Real frames: objects per label (true count in brackets)", ""]
    lines += real_table(rows, truth)
    lines += ["", "## Cost", ""]
    lines += cost_table(rows)
    table = "\n".join(lines) + "\n"
    open(sys.argv[3], "w").write(table)
    json.dump({"true_counts": truth, "runs": rows}, open(sys.argv[4], "w"), indent=1)
    print(table)


if __name__ == "__main__":
    main()
