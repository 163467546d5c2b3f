#!/usr/bin/env python3
"""Tabulates a bench/object_tracks.sh folder: per sequence and run, the person objects of each
build as "dynamic tracks [keyframes each] / still [keyframes each]", static objects labelled
dynamic, and per build how many runs have as many dynamic tracks as walkers.

    object_tracks_report.py FOLDER
"""
import collections
import json
import os
import sys


def person_objects(run_dir):
    with open(os.path.join(run_dir, "map", "objects.json")) as f:
        objects = json.load(f)["objects"]
    dynamic = [o["keyframes"] for o in objects if o["label"] == "person" and o["dynamic"]]
    still = [o["keyframes"] for o in objects if o["label"] == "person" and not o["dynamic"]]
    wrong = [o["label"] for o in objects if o["label"] != "person" and o["dynamic"]]
    return dynamic, still, wrong


def main():
    folder = sys.argv[1]
    walkers = dict(line.split() for line in open(os.path.join(folder, "walkers.txt")))
    runs = collections.defaultdict(dict)
    for entry in sorted(os.listdir(folder)):
        path = os.path.join(folder, entry)
        if not os.path.isdir(path) or entry.count("__") != 2:
            continue
        name, run, build = entry.split("__")
        runs[(name, run)][build] = person_objects(path)
    builds = sorted({b for by_build in runs.values() for b in by_build})
    print("| sequence (walkers) | run | " + " | ".join(builds) + " |")
    print("| --- | --- | " + " | ".join("---" for _ in builds) + " |")
    right = collections.Counter()
    total = collections.Counter()
    for name in walkers:
        for (run_name, run), by_build in sorted(runs.items(), key=lambda r: (r[0][1] != "det", r[0][1])):
            if run_name != name:
                continue
            cells = []
            for build in builds:
                if build not in by_build:
                    cells.append("-")
                    continue
                dynamic, still, wrong = by_build[build]
                ok = len(dynamic) == int(walkers[name]) and not wrong
                right[build] += ok
                total[build] += 1
                text = f"{dynamic} / {still}" + (f" + dynamic {', '.join(wrong)}" if wrong else "")
                cells.append(text if ok else f"**{text}**")
            print(f"| {name} ({walkers[name]}) | {run} | " + " | ".join(cells) + " |")
    print()
    for build in builds:
        print(f"{build}: {right[build]} of {total[build]} runs with as many dynamic tracks as "
              "walkers and no static object labelled dynamic")


if __name__ == "__main__":
    main()
