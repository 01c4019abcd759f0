#!/usr/bin/env python3
"""How far one forming run lies from a reference run of the same path.

    scripts/compare_runs.py REFERENCE_DIR RUN_DIR

Both directories are `spifit run` outputs of an indent, indent_line or line scene. Prints, for
the tool force components Fx, Fy, Fz: the largest difference over the force history (the run
interpolated linearly in time onto the reference's times) over the reference's largest force,
and the difference of the peaks (components below 1e-6 of the largest are skipped); for each section both runs wrote: the largest difference of the
mid-surface depth z and of the thickness at the reference's x0 (the run interpolated in x0); and
both runs' wall time. Exit status 1 when a file is missing. Python's standard library only.
"""
import bisect
import csv
import json
import pathlib
import sys


def read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return {name: [float(r[i]) for r in body] for i, name in enumerate(header)}


def interpolate(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    i = bisect.bisect_right(xs, x)
    t = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
    return ys[i - 1] + t * (ys[i] - ys[i - 1])


def column(table, prefix):
    for name in table:
        if name.split(" [")[0] == prefix:
            return table[name]
    raise KeyError(prefix)


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    ref, run = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    for d in (ref, run):
        if not (d / "force.csv").is_file():
            print(f"compare_runs: {d / 'force.csv'} not found", file=sys.stderr)
            return 1
    fr, fo = read_csv(ref / "force.csv"), read_csv(run / "force.csv")
    tr, to = column(fr, "time"), column(fo, "time")
    largest = max(max(abs(v) for v in column(fr, c)) for c in ("Fx", "Fy", "Fz"))
    for comp in ("Fx", "Fy", "Fz"):
        a, b = column(fr, comp), column(fo, comp)
        scale = max(abs(v) for v in a)
        if scale <= 1e-6 * largest:
            continue  # a component the reference does not load (symmetry)
        worst = max(abs(interpolate(to, b, t) - v) for t, v in zip(tr, a))
        pa, pb = max(a, key=abs), max(b, key=abs)
        print(f"{comp}: history {100 * worst / scale:.2f} % of {scale:.1f} N, peak {pb:.1f} N against {pa:.1f} N ({100 * (pb - pa) / abs(pa):+.2f} %)")
    for sec in sorted((ref / "sections").glob("section_*.csv")) if (ref / "sections").is_dir() else []:
        other = run / "sections" / sec.name
        if not other.is_file():
            continue
        sr, so = read_csv(sec), read_csv(other)
        xr, xo = column(sr, "x0"), column(so, "x0")
        order = sorted(range(len(xo)), key=lambda i: xo[i])
        xo_s = [xo[i] for i in order]
        dz = max(abs(interpolate(xo_s, [column(so, "z")[i] for i in order], x) - z) for x, z in zip(xr, column(sr, "z")))
        dh = max(abs(interpolate(xo_s, [column(so, "thickness")[i] for i in order], x) - h) for x, h in zip(xr, column(sr, "thickness")))
        print(f"{sec.stem}: largest difference z {dz:.4f} mm, thickness {dh:.4f} mm")
    for d in (ref, run):
        s = json.loads((d / "summary.json").read_text())
        print(f"{d}: {s.get('wall_seconds', float('nan')):.2f} s, {s.get('model', {}).get('elements', '?')} elements, "
              f"{s.get('newton_iterations', '?')} Newton iterations")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
