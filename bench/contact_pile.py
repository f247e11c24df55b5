#!/usr/bin/python3
"""CONTACT benchmark: N spheres falling into a box (docs/theory.md §6c, "Benchmark").

    /usr/bin/python3 bench/contact_pile.py --openmss build/openmss [--mujoco PEER] 8 27 64

Writes an ADAMS data set of N spheres (radius 0.05, mass 0.1) on a jittered grid above an open
box (a floor and four walls, BOX solids on ground), one CONTACT per sphere against the box and
one per pair of spheres (IMPACT, no friction), runs it with GSTIFF, and prints the wall and CPU
times (the CPU time of the child process: the figure to compare on a shared machine), the
integration steps and the final mean height of the spheres (from the .req: one DISPLACEMENT
request per sphere). With --keep DIR the data set and every output stay in DIR/N (compare two
binaries' .req files there with cmp). With --mujoco, the program bench/peers/mujoco_pile.cpp
(compiled to that path first when it is missing) builds the same spheres and box in MuJoCo
(soft contacts, RK4 at a fixed step) and its figures are printed beside ours. Last, the growth
of OpenMSS's CPU per step between successive sizes is printed as N^p. The pile is what the issue asks (100 and
1000 spheres); OpenMSS has one element per CONTACT statement, so N spheres cost N (N - 1) / 2
pair elements and the 1000-sphere pile (499,500 statements) is measured only when asked.
"""
import argparse
import math
import os
import subprocess
import tempfile

from openmss_run import run_command_file

RADIUS, MASS, SPACING = 0.05, 0.1, 0.12


def layout(n):
    """Sphere centres: a square grid of side k (k^2 >= n / layers) in layers 0.12 apart,
    jittered by a deterministic LCG (1e-3 of the spacing) so the pile is not symmetric."""
    k = 1
    while k * k * k < n:
        k += 1
    state = 12345
    centres = []
    for i in range(n):
        layer, cell = divmod(i, k * k)
        row, col = divmod(cell, k)
        jitter = []
        for _ in range(2):
            state = (1103515245 * state + 12345) % 2**31
            jitter.append((state / 2**31 - 0.5) * 1e-3 * SPACING)
        centres.append(((col - (k - 1) / 2) * SPACING + jitter[0],
                        (row - (k - 1) / 2) * SPACING + jitter[1],
                        RADIUS + 0.02 + layer * SPACING))
    return k, centres


def dataset(n):
    k, centres = layout(n)
    half = k * SPACING / 2 + 0.01  # inner half-width of the box
    law = "IMPACT, STIFFNESS=1e5, DAMPING=10, DMAX=1e-4, EXPONENT=1.5"
    out = ["contact pile", "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND",
           "PART/1, GROUND"]
    # Floor (top face z = 0) and four walls 0.1 thick, as BOX solids on ground markers.
    walls = [(-half - 0.1, -half - 0.1, -0.1, 2 * half + 0.2, 2 * half + 0.2, 0.1),
             (-half - 0.1, -half - 0.1, 0.0, 0.1, 2 * half + 0.2, 2.0),
             (half, -half - 0.1, 0.0, 0.1, 2 * half + 0.2, 2.0),
             (-half, -half - 0.1, 0.0, 2 * half, 0.1, 2.0),
             (-half, half, 0.0, 2 * half, 0.1, 2.0)]
    for w, (x, y, z, dx, dy, dz) in enumerate(walls):
        out.append(f"MARKER/{10 + w}, PART=1, QP={x:.12g},{y:.12g},{z:.12g}")
        out.append(f"GRAPHICS/{1 + w}, BOX, CORNER={10 + w}, X={dx:.12g}, Y={dy:.12g}, "
                   f"Z={dz:.12g}")
    inertia = 0.4 * MASS * RADIUS**2
    for i, (x, y, z) in enumerate(centres):
        p = 100 + i
        out.append(f"PART/{p}, MASS={MASS}, CM={p * 10}, IP={inertia:.12g},{inertia:.12g},"
                   f"{inertia:.12g}, QG={x:.12g},{y:.12g},{z:.12g}")
        out.append(f"MARKER/{p * 10}, PART={p}")
        out.append(f"GRAPHICS/{p * 10}, ELLIPSOID, CM={p * 10}, XSCALE={2 * RADIUS}, "
                   f"YSCALE={2 * RADIUS}, ZSCALE={2 * RADIUS}")
    cid = 1
    for i in range(n):
        out.append(f"CONTACT/{cid}, IGEOM={(100 + i) * 10}, JGEOM=1,2,3,4,5, {law}")
        cid += 1
    for i in range(n):
        for j in range(i + 1, n):
            out.append(f"CONTACT/{cid}, IGEOM={(100 + i) * 10}, JGEOM={(100 + j) * 10}, {law}")
            cid += 1
    # The outputs compared between binaries: the .req (6 digits) and the .res (every part's
    # state and every CONTACT's force to the last bit).
    for i in range(n):
        out.append(f"REQUEST/{100 + i}, DISPLACEMENT, I={(100 + i) * 10}")
    out += ["OUTPUT/REQSAVE", "RESULTS", "ACCGRAV/KGRAV=-9.81", "END", ""]
    return "\n".join(out), centres


def run_openmss(openmss, n, end, error, workdir):
    text, _ = dataset(n)
    with open(os.path.join(workdir, "pile.adm"), "w") as f:
        f.write(text)
    with open(os.path.join(workdir, "pile.acf"), "w") as f:
        f.write(f"pile.adm\npile\nINTEGRATOR/GSTIFF, ERROR={error:g}\n"
                f"SIMULATE/DYNAMIC, END={end:g}, STEPS=10\nSTOP\n")
    proc, wall, cpu, m = run_command_file(openmss, "pile.acf", workdir)
    if not m:
        tail = (proc.stdout + proc.stderr).strip().splitlines()[-1:]
        return {"wall": wall, "cpu": cpu, "status": "failed", "note": tail}
    return {"wall": wall, "cpu": cpu, "steps": int(m.group(2)), "t": float(m.group(1)),
            "status": "ok", "height": final_mean_height(os.path.join(workdir, "pile.req"), n)}


def final_mean_height(req, n):
    """Mean z of the spheres at the last output time of the .req: its last n lines are the
    DISPLACEMENT records (x y z, ...) of the last time, one per sphere; nan when unreadable."""
    try:
        with open(req) as f:
            lines = f.read().splitlines()
        heights = [float(line.split()[2]) for line in lines[-n:]]
    except (OSError, ValueError, IndexError):
        return float("nan")
    return sum(heights) / n


def compile_mujoco(peer):
    """Compiles bench/peers/mujoco_pile.cpp to `peer` when it is not there yet."""
    if os.path.exists(peer):
        return
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "peers", "mujoco_pile.cpp")
    subprocess.run(["g++", "-std=c++20", "-O2", "-o", peer, source, "-lmujoco"], check=True)


def run_mujoco(peer, n, end, dt):
    _, centres = dataset(n)
    k, _ = layout(n)
    args = [peer, str(n), str(k), f"{end:g}", f"{dt:g}"]
    proc = subprocess.run(args, capture_output=True, text=True)
    values = dict(line.split("=", 1) for line in proc.stdout.splitlines() if "=" in line)
    return {"wall": float(values.get("wall", "nan")), "cpu": float(values.get("cpu", "nan")),
            "steps": int(values.get("steps", "0")),
            "height": float(values.get("mean_height", "nan")),
            "status": "ok" if proc.returncode == 0 else "failed"}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("sizes", nargs="+", type=int)
    p.add_argument("--openmss", required=True)
    p.add_argument("--mujoco", help="bench/peers/mujoco_pile.cpp compiled (compiled if missing)")
    p.add_argument("--end", type=float, default=0.5)
    p.add_argument("--error", type=float, default=1e-3)
    p.add_argument("--dt", type=float, default=1e-4, help="MuJoCo's fixed step")
    p.add_argument("--keep", help="keep each size's data set and outputs in KEEP/N")
    args = p.parse_args()
    if args.mujoco:
        compile_mujoco(args.mujoco)
    per_step = []  # (N, OpenMSS CPU per step) of the sizes that ran
    for n in args.sizes:
        if args.keep:
            workdir = os.path.join(args.keep, str(n))
            os.makedirs(workdir, exist_ok=True)
            r = run_openmss(os.path.abspath(args.openmss), n, args.end, args.error, workdir)
        else:
            with tempfile.TemporaryDirectory(prefix="openmss-pile-") as workdir:
                r = run_openmss(os.path.abspath(args.openmss), n, args.end, args.error, workdir)
        pairs = n * (n - 1) // 2
        line = (f"pile N={n}: {n + pairs} CONTACT elements, OpenMSS GSTIFF ERROR={args.error:g} "
                f"to {args.end:g} s: {r['status']} in {r['wall']:.2f} s wall, "
                f"{r['cpu']:.2f} s CPU")
        if r["status"] == "ok":
            line += (f", {r['steps']} steps, {1e3 * r['cpu'] / max(r['steps'], 1):.3f} ms CPU/step"
                     f", mean height {r['height']:.6f} m")
            per_step.append((n, r["cpu"] / max(r["steps"], 1)))
        else:
            line += f" ({r.get('note')})"
        print(line, flush=True)
        if args.mujoco:
            q = run_mujoco(os.path.abspath(args.mujoco), n, args.end, args.dt)
            print(f"pile N={n}: MuJoCo RK4 dt={args.dt:g}: {q['status']} in {q['wall']:.2f} s "
                  f"wall, {q['cpu']:.2f} s CPU, {q['steps']} steps, mean height "
                  f"{q['height']:.6f} m", flush=True)
    # The growth of the CPU per step between successive sizes, as N^p (the issue asks p <= 1.2).
    for (n0, c0), (n1, c1) in zip(per_step, per_step[1:]):
        if n1 != n0 and c0 > 0 and c1 > 0:
            print(f"CPU per step N={n0} -> N={n1}: N^{math.log(c1 / c0) / math.log(n1 / n0):.2f}")


if __name__ == "__main__":
    main()
