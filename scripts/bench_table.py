#!/usr/bin/env python3
"""Markdown rows from Google Benchmark JSON files (--benchmark_out=F --benchmark_out_format=json).

  python3 scripts/bench_table.py FILE.json...              print the table
  python3 scripts/bench_table.py --into DOC.md FILE.json...  replace the table between DOC's markers
      <!-- bench_table: begin --> and <!-- bench_table: end -->

One row per benchmark case: its value (the median_s counter the scene benchmarks report, else
the real time of the run or of its median aggregate), the counters that say what the value is
worth (reference error, iterations, elements), the command that reruns it, the machine and the
date from the file's context.
"""
import json
import os
import sys

BEGIN, END = "<!-- bench_table: begin -->", "<!-- bench_table: end -->"
# Counters shown, in this order, with their labels.
SHOWN = [("ref_error", "error vs reference"), ("max_rel_error", "largest relative error"), ("elements", "elements"),
         ("increments", "increments"), ("newton_its", "Newton iterations"), ("newton_iters", "Newton iterations"),
         ("substeps", "sub-steps"), ("contours", "contours"), ("forward_runs", "forward runs"),
         ("max_rel_dev_from_C2", "largest deviation from card C.2")]


def fmt(v):
    if isinstance(v, float) and v != int(v):
        return f"{v:.4g}"
    return f"{int(v):d}" if isinstance(v, (int, float)) else str(v)


def rows(path):
    with open(path) as f:
        data = json.load(f)
    ctx = data["context"]
    exe = os.path.relpath(ctx["executable"]) if os.path.isabs(ctx["executable"]) else ctx["executable"]
    load = ctx.get("load_avg") or [float("nan")]
    machine = f"{ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, load {load[0]:.1f}"
    date = ctx.get("date", "?")[:10]
    by_case = {}
    for b in data["benchmarks"]:
        name = b.get("run_name", b["name"])
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        if b.get("run_type") == "aggregate" or name not in by_case:
            by_case[name] = b
    for name, b in by_case.items():
        if "median_s" in b:
            value = f"{b['median_s']:.4g} s (median of the runs)"
        else:
            value = f"{b['real_time']:.4g} {b['time_unit']}"
        worth = ", ".join(f"{label} {fmt(b[key])}" for key, label in SHOWN if key in b)
        command = f"`{exe} --benchmark_filter='^{name}$'`"
        yield f"| {name} | {value} | {worth} | {command} | {machine} | {date} |"


def table(files):
    out = ["| case | value | what it is worth | command | machine | date |", "|---|---|---|---|---|---|"]
    for path in files:
        out.extend(rows(path))
    return "\n".join(out) + "\n"


def main(argv):
    if len(argv) >= 2 and argv[0] == "--into":
        doc, files = argv[1], argv[2:]
        text = open(doc).read()
        if BEGIN not in text or END not in text:
            sys.exit(f"{doc}: no {BEGIN} ... {END} markers")
        head, rest = text.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        with open(doc, "w") as f:
            f.write(head + BEGIN + "\n" + table(files) + END + tail)
        return
    if not argv:
        sys.exit(__doc__)
    sys.stdout.write(table(argv))


if __name__ == "__main__":
    main(sys.argv[1:])
