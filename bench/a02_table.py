#!/usr/bin/env python3
"""IFToMM A02 (N four-bar mechanism) against its exact one-degree-of-freedom solution.

Usage: bench/a02_table.py [--pivot-order ORDER] OPENMSS GENERATE [N] [END] [INTEGRATOR:ERROR ...]
Runs `openmss run` on the data set `GENERATE fourbar N` with each integrator and ERROR, 400
output steps per 20 s, and prints a Markdown table: the distance of B0 (top of the first rocker)
from the exact solution at t = 10 s, at END, and the largest over all output times, with the
steps and the wall time. docs/validation.md ("IFToMM A02") holds the table for N = 40, 20 s.
--pivot-order (nobtf, colamd) is passed to `openmss run`: KLU's pivot order, which changes
only round-off, to show that a row does not depend on round-off luck.

Exact solution (docs/validation.md): every rocker turns by the same angle phi (the windows stay
parallelograms, the couplers translate), so with thin rods of mass m and length L
  (N+1) m L^2/3 + N m L^2 = A   (rockers about their pivots, couplers translating at L phi'),
  (N+1) m g L/2 + N m g L = g B (potential energy g B sin phi),
  A phi'' = -g B cos phi,  phi(0) = pi/2,  phi'(0) = -1 rad/s (B0 at +1 m/s along x),
integrated here by classical RK4 with h = 1e-4 s (halving h changes B0 by < 1e-12 m).
"""
import math
import os
import subprocess
import sys
import tempfile
import time


def exact_b0(n, times, h=1e-4):
    a = (n + 1) / 3.0 + n
    b = (n + 1) * 0.5 + n
    k = 9.81 * b / a
    p, w, t = math.pi / 2, -1.0, 0.0
    out = []
    for target in times:
        while t < target - 1e-12:
            s = min(h, target - t)
            k1p, k1w = w, -k * math.cos(p)
            k2p, k2w = w + s / 2 * k1w, -k * math.cos(p + s / 2 * k1p)
            k3p, k3w = w + s / 2 * k2w, -k * math.cos(p + s / 2 * k2p)
            k4p, k4w = w + s * k3w, -k * math.cos(p + s * k3p)
            p += s / 6 * (k1p + 2 * k2p + 2 * k3p + k4p)
            w += s / 6 * (k1w + 2 * k2w + 2 * k3w + k4w)
            t += s
        out.append((math.cos(p), math.sin(p)))
    return out


def read_b0(req_path):
    """(t, x, y) of B0 per output time from REQUEST/3 (AINT(v) + 1e-6 (a + b), bench layout)."""
    records = []
    for line in open(req_path).read().splitlines():
        fields = [line[1 + 13 * k:14 + 13 * k] for k in range(len(line) // 13)]
        try:
            values = [float(f) for f in fields]
        except ValueError:
            continue
        if len(values) == 1:
            records.append([values[0]])
        elif records and len(values) == 6:
            records[-1].append(values)
    out = []
    for rec in records:
        if len(rec) >= 4:
            r = rec[3]  # REQUEST/3: DX and DY digits
            out.append((rec[0], r[0] + 1e-6 * (r[1] + r[2]), r[3] + 1e-6 * (r[4] + r[5])))
    return out


def run(openmss, generate, n, end, integrator, error, workdir, pivot_order="default"):
    adm = os.path.join(workdir, "a02.adm")
    if not os.path.exists(adm):
        with open(adm, "w") as f:
            subprocess.run([generate, "fourbar", str(n)], stdout=f, check=True)
    name = f"a02-{integrator.lower()}-{error:g}"
    with open(os.path.join(workdir, name + ".acf"), "w") as f:
        f.write(f"a02.adm\n{name}\nINTEGRATOR/{integrator.replace('_', ', ')}, ERROR={error:g}\n"
                f"SIMULATE/DYNAMIC, END={end:g}, STEPS={int(round(20 * end))}\nSTOP\n")
    start = time.perf_counter()
    extra = [] if pivot_order == "default" else ["--pivot-order", pivot_order]
    proc = subprocess.run([openmss, "run", name + ".acf"] + extra, cwd=workdir,
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    rows = read_b0(os.path.join(workdir, name + ".req"))
    exact = exact_b0(n, [r[0] for r in rows])
    errors = {round(t, 9): math.hypot(x - xe, y - ye) for (t, x, y), (xe, ye) in zip(rows, exact)}
    reached = rows[-1][0] if rows else 0.0
    steps = "–"
    for line in (proc.stdout + proc.stderr).splitlines():
        if "integration steps" in line and "reached t" in line:
            steps = line.split(" with ")[1].split()[0]
    return {"status": proc.returncode, "reached": reached, "wall": wall, "steps": steps,
            "e10": errors.get(10.0), "eEnd": errors.get(round(end, 9)),
            "worst": max(errors.values()) if errors else None}


def fmt(v):
    return "–" if v is None else f"{v:.1e}"


def main():
    pivot_order = "default"
    if len(sys.argv) > 2 and sys.argv[1] == "--pivot-order":
        pivot_order = sys.argv[2]
        del sys.argv[1:3]
    if len(sys.argv) < 3:
        print(__doc__)
        return 64
    openmss, generate = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 40
    end = float(sys.argv[4]) if len(sys.argv) > 4 else 20.0
    settings = sys.argv[5:] or [f"{i}:{e}" for i in ("GSTIFF", "SI2_GSTIFF", "WSTIFF", "DSTIFF",
                                                     "HHT", "MERSON") for e in (1e-4, 1e-6, 1e-8)]
    print(f"| integrator | ERROR | reached t | steps | B0 error at 10 s | at {end:g} s | "
          f"largest | wall s |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as workdir:
        for setting in settings:
            integrator, error = setting.split(":")
            r = run(openmss, generate, n, end, integrator, float(error), workdir, pivot_order)
            print(f"| {integrator.replace('_', ' ')} | {float(error):g} | {r['reached']:g} | "
                  f"{r['steps']} | {fmt(r['e10'])} | {fmt(r['eEnd'])} | {fmt(r['worst'])} | "
                  f"{r['wall']:.1f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
