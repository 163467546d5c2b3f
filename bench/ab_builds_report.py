#!/usr/bin/env python3
"""Table of an A/B run folder (bench/ab_builds.sh): runs named SEQUENCE_BUILD_SEED, each with its
summary.json; one row per sequence and build."""

import argparse
import collections
import json
import pathlib
import statistics
import sys


def read_runs(folder):
    runs = collections.defaultdict(list)
    for summary_file in sorted(pathlib.Path(folder).glob("*_*_*/summary.json")):
        sequence, build, seed = summary_file.parent.name.rsplit("_", 2)
        if not seed.isdigit():
            continue
        runs[(sequence, build)].append(json.loads(summary_file.read_text()))
    return runs


def row(sequence, build, summaries):
    ates = sorted(s["ate_rmse_m"] for s in summaries)
    lost = [s["lost_frames"] for s in summaries]
    return "| {} | {} | {} | {:.4f} / {:.4f} | {} ({}) | {:.1f} | {:.1f} | {:.1f} |".format(
        sequence, build, len(summaries), statistics.median(ates), ates[-1],
        sum(1 for n in lost if n > 0), sum(lost),
        statistics.median(s["tracking_time"]["median_ms"] for s in summaries),
        statistics.mean(s["keyframes"] for s in summaries),
        statistics.mean(s["network_runs"] for s in summaries))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("folder")
    parser.add_argument("--markdown", help="also write the table to this file")
    args = parser.parse_args()
    runs = read_runs(args.folder)
    if not runs:
        sys.exit(f"ab_builds_report.py: no runs (SEQUENCE_BUILD_SEED/summary.json) in {args.folder}")
    lines = ["| sequence | build | runs | ATE median / worst [m] | runs with frames lost (frames) "
             "| tracking median [ms] | keyframes | network runs |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    lines += [row(sequence, build, summaries)
              for (sequence, build), summaries in sorted(runs.items())]
    table = "\n".join(lines) + "\n"
    print(table, end="")
    if args.markdown:
        pathlib.Path(args.markdown).write_text(table)


if __name__ == "__main__":
    main()
