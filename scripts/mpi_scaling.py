#!/usr/bin/env python3
"""Projected wall time of a fit or a sweep on W worker ranks, from its measured run times.

A simulation of the scheduler of `mpirun spifit fit|sweep` (docs/guide/parallel-runs.md): jobs
go, in the order they are handed out, to the first worker that is free (rank 0's queue), and a
batch ends when its last job ends.

  sweep DIR  the points of a sweep (DIR/sweep.csv, column wall_seconds) are one batch, the
             sensitivity runs (if any) a second one of 1 + 2 per input runs of the median time.
  fit DIR    a Levenberg-Marquardt fit on FE scenes (DIR/fit.json): per iteration one run at
             the point and one batch of 2p perturbed runs (p free parameters), plus the
             Jacobian at the solution; every run takes the median time of fit.json's
             runs_by_scene, per scene file and one after another when the fit has several.

The measured times are those of runs with the threads they had; a projection for W workers
assumes each worker has that many cores of its own and that rank 0's own work (the optimiser,
reports) is negligible. Prints W, projected wall, speed-up and efficiency (speed-up / W).
"""
import csv
import json
import statistics
import sys

WORKERS = [1, 2, 4, 8, 16, 32, 64]


def makespan(durations, workers):
    """Greedy list scheduling in order: each job to the worker free first."""
    free = [0.0] * workers
    end = 0.0
    for d in durations:
        i = min(range(workers), key=lambda k: free[k])
        free[i] += d
        end = max(end, free[i])
    return end


def sweep_batches(directory):
    with open(f"{directory}/sweep.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    times = [float(r["wall_seconds"]) for r in rows]
    batches = [times]
    try:
        with open(f"{directory}/sensitivities.csv", newline="") as f:
            inputs = {r["input"] for r in csv.DictReader(f)}
        if inputs:
            batches.append([statistics.median(times)] * (1 + 2 * len(inputs)))
    except FileNotFoundError:
        pass
    return batches


def fit_batches(directory):
    with open(f"{directory}/fit.json") as f:
        fit = json.load(f)
    p = sum(1 for v in fit["parameters"].values() if "value" in v)
    per_point = sum(s["median_seconds"] for s in fit["runs_by_scene"])
    batches = []
    for _ in range(int(fit["iterations"]) + 1):  # + the Jacobian at the solution
        batches.append([per_point])
        batches.append([per_point] * (2 * p))
    return batches


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("sweep", "fit"):
        sys.exit(__doc__)
    batches = sweep_batches(sys.argv[2]) if sys.argv[1] == "sweep" else fit_batches(sys.argv[2])
    serial = sum(sum(b) for b in batches)
    widest = max(len(b) for b in batches)
    print(f"{sum(len(b) for b in batches)} runs in {len(batches)} batches (widest {widest}), {serial:.1f} s of runs")
    print(f"{'workers':>8} {'wall [s]':>10} {'speed-up':>9} {'efficiency':>10}")
    for w in WORKERS:
        wall = sum(makespan(b, w) for b in batches)
        print(f"{w:>8} {wall:>10.1f} {serial / wall:>9.2f} {serial / wall / w:>10.0%}")


if __name__ == "__main__":
    main()
