"""What the bench reports share: the runs file (one JSON object per line) and the outputs.

    REPORT.py RUNS.jsonl --commit C --markdown OUT.md --json OUT.json
"""
import argparse
import json


def parse_report_arguments(description):
    """The report's arguments, and the runs read from the runs file."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("runs")
    parser.add_argument("--commit", required=True)
    parser.add_argument("--markdown", required=True)
    parser.add_argument("--json", required=True)
    args = parser.parse_args()
    with open(args.runs) as lines:
        runs = [json.loads(line) for line in lines if line.strip()]
    return args, runs


def write_report(args, lines, results):
    """The markdown table lines and the JSON results, with the commit they were measured at."""
    with open(args.markdown, "w") as markdown:
        markdown.write("\n".join(lines) + "\n")
    with open(args.json, "w") as out:
        json.dump({"commit": args.commit, **results}, out, indent=2)
