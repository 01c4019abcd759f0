#!/usr/bin/env python3
"""Where a cone's wall is thinnest, and the tool forces, for one or more cone runs.

    scripts/cone_wall_profile.py [--contour N] [--forces FROM TO] RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a `spifit run` output of a cone scene. From its section after contour N of
stage 1 (default: the last one written, sections/section_s1_cNNN.csv) it prints the thinnest
section node in the wall (the nodes whose top surface lies at least 1 mm below its initial
height and 2 mm above the part centre's top) with its depth below the initial top surface,
and the thinnest point of the wall's thickness smoothed over three neighbouring nodes (the
nodal thickness of a coarse wall waves over a few nodes; thesis §9.2.2 reads the minimum off a
smooth profile: about 13 mm deep in the experiment and 21 mm with its shells after 60 contours
of the 70-degree cone, Fig. 9.8). With --forces, the means of the contours' central-third
means (contours.csv) over contours FROM..TO: Fr, Ftheta, Fz (thesis Table 9.1 gives the
steady state over contours 60-80 of the 100-contour path). Then the wall time (summary.json).
Python's standard library only.
"""
import argparse
import csv
import json
import pathlib
import sys


def read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return {name.split(" ")[0]: [float(r[i]) for r in body] for i, name in enumerate(header)}


def section_file(run, contour):
    sections = sorted((run / "sections").glob("section_s1_c*.csv"))
    if contour is not None:
        wanted = run / "sections" / f"section_s1_c{contour:03d}.csv"
        return wanted if wanted.exists() else None
    return sections[-1] if sections else None


def wall_minimum(section):
    depth, thickness = section["depth"], section["thickness"]
    centre = depth[0]  # the first point lies on the axis
    wall = [i for i in range(len(depth)) if 1.0 <= depth[i] <= centre - 2.0]
    if not wall:
        return None
    node = min(wall, key=lambda i: thickness[i])
    smooth = {}
    for i in wall:
        if 0 < i < len(depth) - 1:
            smooth[i] = (thickness[i - 1] + thickness[i] + thickness[i + 1]) / 3.0
    best = min(smooth, key=smooth.get) if smooth else node
    return {
        "centre_depth": centre,
        "wall_nodes": len(wall),
        "thinnest": (thickness[node], depth[node]),
        "smoothed": (smooth.get(best, thickness[best]), depth[best]),
    }


def contour_means(run, first, last):
    c = read_csv(run / "contours.csv")
    rows = [i for i, k in enumerate(c["contour"]) if first <= k <= last]
    if not rows:
        return None
    return {key: sum(c[key][i] for i in rows) / len(rows) for key in ("Fr", "Ftheta", "Fz")} | {"contours": len(rows)}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+", type=pathlib.Path)
    p.add_argument("--contour", type=int)
    p.add_argument("--forces", type=int, nargs=2, metavar=("FROM", "TO"))
    a = p.parse_args()
    status = 0
    for run in a.runs:
        f = section_file(run, a.contour)
        if f is None:
            print(f"{run}: no section file", file=sys.stderr)
            status = 1
            continue
        m = wall_minimum(read_csv(f))
        print(f"{run} ({f.name}):")
        if m is None:
            print("  no wall nodes")
        else:
            print(f"  centre depth {m['centre_depth']:.2f} mm, {m['wall_nodes']} wall nodes")
            print(f"  thinnest node {m['thinnest'][0]:.3f} mm at a depth of {m['thinnest'][1]:.1f} mm")
            print(f"  thinnest over three nodes {m['smoothed'][0]:.3f} mm at a depth of {m['smoothed'][1]:.1f} mm")
        if a.forces:
            means = contour_means(run, *a.forces)
            if means:
                print(f"  contours {a.forces[0]}-{a.forces[1]} ({means['contours']}): Fr {means['Fr']:.1f} N, "
                      f"Ftheta {means['Ftheta']:.1f} N, Fz {means['Fz']:.1f} N, Fr/Fz {means['Fr'] / means['Fz']:.3f}")
        try:
            s = json.loads((run / "summary.json").read_text())
            print(f"  {s.get('model', {}).get('elements')} elements, {s.get('increments')} increments, "
                  f"{s.get('newton_iterations')} iterations, {s.get('wall_seconds', 0.0):.0f} s")
        except (OSError, ValueError):
            pass
    return status


if __name__ == "__main__":
    sys.exit(main())
