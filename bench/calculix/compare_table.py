#!/usr/bin/env python3
"""Table of the tool force against depth: spifit (DIR/force.csv) against CalculiX (JOB.dat).

spifit: force.csv has the tool centre z (tool_z) and Fz, the force BY the sheet ON the tool (a
half model's forces are mirrored to the full sheet); depth = (t/2 + R) - tool_z, the travel
from first touch (the tool tip on the top surface, spifit's path z = 0).
CalculiX: *NODE PRINT of the tool's reference node, U and RF at every increment; depth =
-U3, Fz = -RF3 (RF is the force on the reference node that holds the tool; the sheet pushes
the tool up with -RF).
Both curves are interpolated linearly at the requested depths. Standard library only.
"""

import argparse
import csv
import json
import re
import sys


def read_spifit(path, zero):
    depth, fz = [0.0], [0.0]
    with open(path, encoding="utf-8") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    head = rows[0]
    iz = next(i for i, h in enumerate(head) if h.startswith("tool_z"))
    ifz = next(i for i, h in enumerate(head) if h.startswith("Fz"))
    for r in rows[1:]:
        d = zero - float(r[iz])
        if d > depth[-1]:
            depth.append(d)
            fz.append(float(r[ifz]))
    return depth, fz


def read_ccx(path, node=None):
    """(depth, Fz) of the node printed with *NODE PRINT U, RF (the first node of the blocks)."""
    u, rf = {}, {}
    block = None
    time = None
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = re.match(r"\s*(displacements|forces) \(.*\) for set (\S+) and time\s+(\S+)", line)
            if m:
                block = m.group(1)
                time = float(m.group(3))
                continue
            parts = line.split()
            if block and len(parts) == 4 and re.match(r"^\d+$", parts[0]):
                if node is None or int(parts[0]) == node:
                    vals = [float(p) for p in parts[1:]]
                    (u if block == "displacements" else rf)[time] = vals
                    block = None  # the first node of the block only
    times = sorted(t for t in u if t in rf)
    depth, fz = [0.0], [0.0]
    for t in times:
        d = -u[t][2]
        if d > depth[-1]:
            depth.append(d)
            fz.append(-rf[t][2])
    return depth, fz


def interp(xs, ys, x):
    if x > xs[-1] + 1e-9:
        return None
    for i in range(1, len(xs)):
        if x <= xs[i] + 1e-12:
            a = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + a * (ys[i] - ys[i - 1])
    return ys[-1]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--spifit", required=True, help="spifit output directory (force.csv, summary.json)")
    p.add_argument("--ccx", required=True, help="CalculiX .dat file")
    p.add_argument("--thickness", type=float, default=1.2)
    p.add_argument("--radius", type=float, default=5.0)
    p.add_argument("--depths", required=True, help="comma-separated depths [mm]")
    p.add_argument("--json", help="also write the table here")
    a = p.parse_args()
    sd, sf = read_spifit(a.spifit + "/force.csv", a.thickness / 2 + a.radius)
    cd, cf = read_ccx(a.ccx)
    depths = [float(x) for x in a.depths.split(",") if x.strip()]
    rows = []
    print("| depth [mm] | Fz spifit [N] | Fz CalculiX [N] | (spifit - CalculiX) / CalculiX |")
    print("|---:|---:|---:|---:|")
    for d in depths:
        fs, fc = interp(sd, sf, d), interp(cd, cf, d)
        rel = (fs - fc) / fc if fs is not None and fc not in (None, 0.0) else None
        rows.append({"depth": d, "fz_spifit": fs, "fz_calculix": fc, "relative_difference": rel})
        f = lambda v, spec: "n/a" if v is None else format(v, spec)
        print("| %.2f | %s | %s | %s |" % (d, f(fs, ".1f"), f(fc, ".1f"),
                                           "n/a" if rel is None else "%+.1f %%" % (100 * rel)))
    print("reached: spifit %.3f mm, CalculiX %.3f mm" % (sd[-1], cd[-1]))
    if a.json:
        with open(a.json, "w", encoding="utf-8") as f:
            json.dump({"rows": rows, "spifit_depth_reached": sd[-1], "calculix_depth_reached": cd[-1]}, f, indent=1)
    if cd[-1] + 1e-6 < max(depths) or sd[-1] + 1e-6 < max(depths):
        sys.exit(1)


if __name__ == "__main__":
    main()
