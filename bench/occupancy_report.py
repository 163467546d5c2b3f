#!/usr/bin/env python3
"""Tables of bench/occupancy.sh: per sequence and mode, the occupancy and point-map scores.

    occupancy_report.py RUNS.jsonl --commit C --markdown OUT.md --json OUT.json
"""
import statistics

from report_runs import parse_report_arguments, write_report


def row(sequence, mode, runs):
    occupancy = [r["map_evaluation"]["occupancy"] for r in runs]
    evaluation = [r["map_evaluation"] for r in runs]
    maps = [r["summary"]["map"] for r in runs]
    worst = lambda values: max(values)
    return {
        "sequence": sequence, "mode": mode, "runs": len(runs),
        "ghost_pct": [100 * o["ghost_share"] for o in occupancy],
        "ghost_beyond_a_voxel_pct": [100 * o["ghost_beyond_a_voxel_share"] for o in occupancy],
        "kept_pct": [100 * o["kept_share"] for o in occupancy],
        "occupied_on_people_pct": [100 * o.get("on_people_share", 0.0) for o in occupancy],
        "completeness_pct": [100 * e["completeness"] for e in evaluation],
        "points_on_people_pct": [100 * e["on_dynamic_share"] for e in evaluation],
        "occupancy_cost_pct": [100 * m["occupancy"]["seconds"] / r["summary"]["wall_seconds"]
                               for m, r in zip(maps, runs)],
        "ate_m": [r["summary"]["ate_rmse_m"] for r in runs],
    }


def cell(values, pattern):
    return " / ".join(pattern % v for v in values)


def main():
    args, runs = parse_report_arguments(__doc__.split("\n")[0])
    rows = []
    for sequence in dict.fromkeys(r["sequence"] for r in runs):
        for mode in ("camera_rate", "deterministic"):
            mine = [r for r in runs if r["sequence"] == sequence and r["mode"] == mode]
            if mine:
                rows.append(row(sequence, mode, mine))
    lines = [
        "# Occupancy maps with people",
        "",
        f"`bench/occupancy.sh` at {args.commit}: each sequence run as users run it (30 Hz, default "
        "masks) and once `--deterministic`; `segslam eval map --occupancy-reference` against the "
        "run of the same frames without people (tum_fr1_xyz_300, same mode). 5 cm voxels. Per run "
        "(/ between runs): ghosts = occupied voxels the people-free run sees free; beyond a voxel "
        "= those with no occupied voxel of it within one voxel; kept = its occupied voxels "
        "occupied here within a voxel; on people = occupied voxels holding a true person surface "
        "point; completeness and points on people of the point map (2 cm, 3 cm); cost = "
        "occupancy seconds / run wall seconds.",
        "",
        "| sequence | mode | ghosts % | beyond a voxel % | kept % | occupied on people % "
        "| completeness % | points on people % | cost % | ATE m |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        lines.append(
            f"| {r['sequence']} | {r['mode']} | {cell(r['ghost_pct'], '%.2f')} | "
            f"{cell(r['ghost_beyond_a_voxel_pct'], '%.2f')} | {cell(r['kept_pct'], '%.1f')} | "
            f"{cell(r['occupied_on_people_pct'], '%.2f')} | {cell(r['completeness_pct'], '%.1f')} | "
            f"{cell(r['points_on_people_pct'], '%.2f')} | {cell(r['occupancy_cost_pct'], '%.1f')} | "
            f"{cell(r['ate_m'], '%.4f')} |")
    write_report(args, lines, {"rows": rows})


if __name__ == "__main__":
    main()
