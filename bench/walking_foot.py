#!/usr/bin/python3
"""CONTACT benchmark: a two-legged walker whose box feet step on a floor with friction.

    /usr/bin/python3 bench/walking_foot.py --openmss build/openmss [--mujoco PEER] [--keep DIR]

The walking-foot style model of issue 17 (docs/performance.md, "Contact pile", "Walking
foot"). A pelvis (20 kg) is free to move forward (x) and up (z): a carriage slides along x on
ground, the pelvis slides along z on the carriage (two TRANSLATIONAL joints, no motion). Two
legs (thigh 0.4 m, shank 0.4 m, a BOX foot 0.2 x 0.1 x 0.04 m) hang from it on REVOLUTE hip,
knee and ankle joints about y, each driven by a MOTION: the hip swings +-0.3 rad, the knee
flexes up to 0.8 rad during the swing, the ankle keeps the foot parallel to the floor, the
two legs half a cycle apart, 1 Hz, the amplitudes ramped in over the first 0.5 s. Each foot
has one CONTACT with the floor (a BOX on ground): IMPACT (k = 1e6, e = 1.5, c = 500, DMAX =
1e-3) with Coulomb friction (mu_s 0.8, mu_d 0.6). Nothing drives the pelvis: the feet's
friction walks it forward, their normal forces carry it. GSTIFF, ERROR = 1e-3 (--error).

Printed: CPU time of the child (user + system), steps, CPU per step, the distance walked and
the lowest pelvis height (from the .req), and the deepest foot penetration, read from the
foot corners' heights in the .req. With --mujoco, bench/peers/mujoco_walker.cpp (compiled to
that path when missing) runs the same bodies in MuJoCo 2.2 (RK4 at a fixed step, stiff position
servos in place of the MOTIONs, its own soft contacts with friction): a cost figure beside
ours, not the same trajectory.
"""
import argparse
import os
import subprocess
import tempfile

from openmss_run import run_command_file

H = 0.865  # pelvis height at t = 0: the feet's soles 5 mm above the floor
THIGH, SHANK = 0.4, 0.4
FOOT = (0.2, 0.1, 0.04)  # x, y, z extents; the ankle 0.02 above the sole's top face
LEG_Y = (-0.1, 0.1)


def angles(phase):
    """The MOTION functions of one leg (hip, knee, ankle), as ADAMS expressions."""
    ramp = "STEP(TIME,0,0,0.5,1)"
    s = f"SIN(6.283185307179586*TIME+{phase})"
    c = f"COS(6.283185307179586*TIME+{phase})"
    hip = f"{ramp}*(-0.3*{c})"
    knee = f"{ramp}*0.8*((1-{s})/2)**3"
    return hip, knee, f"-({hip})-({knee})"


def dataset():
    out = ["walking foot", "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND",
           "PART/1, GROUND",
           "MARKER/10, PART=1, QP=-2,-1,-0.1",
           "GRAPHICS/10, BOX, CORNER=10, X=10, Y=2, Z=0.1",
           f"MARKER/11, PART=1, QP=0,0,{H}, REULER=90D,90D,0",
           # carriage: slides along ground x
           "PART/2, MASS=1, CM=20, IP=0.01,0.01,0.01",
           f"MARKER/20, PART=2, QP=0,0,{H}",
           f"MARKER/21, PART=2, QP=0,0,{H}, REULER=90D,90D,0",
           f"MARKER/22, PART=2, QP=0,0,{H}",
           "JOINT/1, TRANSLATIONAL, I=21, J=11",
           # pelvis: slides along z on the carriage
           "PART/3, MASS=20, CM=30, IP=0.3,0.3,0.3",
           f"MARKER/30, PART=3, QP=0,0,{H}",
           f"MARKER/31, PART=3, QP=0,0,{H}",
           "JOINT/2, TRANSLATIONAL, I=31, J=22"]
    law = ("IMPACT, STIFFNESS=1e6, DAMPING=500, DMAX=1e-3, EXPONENT=1.5, COULOMB_FRICTION=ON, "
           "MU_STATIC=0.8, MU_DYNAMIC=0.6, STICTION_TRANSITION_VELOCITY=0.01, "
           "FRICTION_TRANSITION_VELOCITY=0.02")
    y_axis = "REULER=0,-90D,0"  # the joint markers' z along ground y
    for leg, y in enumerate(LEG_Y):
        b = 100 * (leg + 1)
        hipz, kneez, anklez = H, H - THIGH, H - THIGH - SHANK
        sole = anklez - 0.02 - FOOT[2]
        out += [f"PART/{b + 4}, MASS=3, CM={b + 40}, IP=0.04,0.04,0.002",
                f"MARKER/{b + 40}, PART={b + 4}, QP=0,{y},{hipz - THIGH / 2}",
                f"MARKER/{b + 41}, PART={b + 4}, QP=0,{y},{hipz}, {y_axis}",
                f"MARKER/{b + 42}, PART={b + 4}, QP=0,{y},{kneez}, {y_axis}",
                f"MARKER/{b + 32}, PART=3, QP=0,{y},{hipz}, {y_axis}",
                f"PART/{b + 5}, MASS=2, CM={b + 50}, IP=0.027,0.027,0.001",
                f"MARKER/{b + 50}, PART={b + 5}, QP=0,{y},{kneez - SHANK / 2}",
                f"MARKER/{b + 51}, PART={b + 5}, QP=0,{y},{kneez}, {y_axis}",
                f"MARKER/{b + 52}, PART={b + 5}, QP=0,{y},{anklez}, {y_axis}",
                f"PART/{b + 6}, MASS=1, CM={b + 60}, IP=0.001,0.004,0.004",
                f"MARKER/{b + 60}, PART={b + 6}, QP=0.05,{y},{sole + FOOT[2] / 2}",
                f"MARKER/{b + 61}, PART={b + 6}, QP=0,{y},{anklez}, {y_axis}",
                f"MARKER/{b + 62}, PART={b + 6}, QP={0.05 - FOOT[0] / 2},{y - FOOT[1] / 2},{sole}",
                f"GRAPHICS/{b + 6}, BOX, CORNER={b + 62}, X={FOOT[0]}, Y={FOOT[1]}, Z={FOOT[2]}",
                f"JOINT/{b + 1}, REVOLUTE, I={b + 41}, J={b + 32}",
                f"JOINT/{b + 2}, REVOLUTE, I={b + 51}, J={b + 42}",
                f"JOINT/{b + 3}, REVOLUTE, I={b + 61}, J={b + 52}"]
        for j, f in enumerate(angles(0.0 if leg == 0 else 3.141592653589793)):
            out.append(f"MOTION/{b + 1 + j}, JOINT={b + 1 + j}, FUNCTION={f}")
        out.append(f"CONTACT/{leg + 1}, IGEOM={b + 6}, JGEOM=10, {law}")
        # The sole's corner (the foot stays level to within the joints' round-off).
        out.append(f"REQUEST/{b + 62}, DISPLACEMENT, I={b + 62}")
    out += ["REQUEST/30, DISPLACEMENT, I=30", "OUTPUT/REQSAVE", "RESULTS",
            "ACCGRAV/KGRAV=-9.81", "END", ""]
    return "\n".join(out)


def read_req(path):
    """The .req's records: {time: {request id: [x, y, z, ...]}}."""
    lines = open(path).read().splitlines()
    ids, i = [], 3
    while i < len(lines) and lines[i].split() and len(lines[i].split()) == 5:
        ids.append(int(lines[i].split()[0]))
        i += 2
    out = {}
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        t = float(lines[i])
        out[t] = {rid: [float(v) for v in lines[i + 1 + j].split()] for j, rid in enumerate(ids)}
        i += 1 + len(ids)
    return out


def run_openmss(openmss, end, error, steps, workdir):
    with open(os.path.join(workdir, "walk.adm"), "w") as f:
        f.write(dataset())
    with open(os.path.join(workdir, "walk.acf"), "w") as f:
        f.write(f"walk.adm\nwalk\nINTEGRATOR/GSTIFF, ERROR={error:g}\n"
                f"SIMULATE/DYNAMIC, END={end:g}, STEPS={steps}\nSTOP\n")
    proc, wall, cpu, m = run_command_file(openmss, "walk.acf", workdir)
    if not m:
        tail = (proc.stdout + proc.stderr).strip().splitlines()[-2:]
        return {"wall": wall, "cpu": cpu, "status": "failed", "note": tail}
    req = read_req(os.path.join(workdir, "walk.req"))
    last = req[max(req)]
    depth = max(-rec[rid][2] for rec in req.values() for rid in (162, 262))
    return {"wall": wall, "cpu": cpu, "steps": int(m.group(2)), "status": "ok",
            "walked": last[30][0], "lowest": min(rec[30][2] for rec in req.values()),
            "depth": depth}


def compile_mujoco(peer):
    if os.path.exists(peer):
        return
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "peers",
                          "mujoco_walker.cpp")
    subprocess.run(["g++", "-std=c++20", "-O2", "-o", peer, source, "-lmujoco"], check=True)


def run_mujoco(peer, end, dt):
    proc = subprocess.run([peer, f"{end:g}", f"{dt:g}"], capture_output=True, text=True)
    values = dict(line.split("=", 1) for line in proc.stdout.splitlines() if "=" in line)
    return {k: float(v) for k, v in values.items()}, proc.returncode


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--openmss", required=True)
    p.add_argument("--mujoco", help="bench/peers/mujoco_walker.cpp compiled (compiled if missing)")
    p.add_argument("--end", type=float, default=4.0)
    p.add_argument("--error", type=float, default=1e-3)
    p.add_argument("--steps", type=int, default=400, help="output steps")
    p.add_argument("--dt", type=float, default=1e-4, help="MuJoCo's fixed step")
    p.add_argument("--keep", help="keep the data set and outputs in KEEP")
    args = p.parse_args()
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
        r = run_openmss(os.path.abspath(args.openmss), args.end, args.error, args.steps,
                        args.keep)
    else:
        with tempfile.TemporaryDirectory(prefix="openmss-walk-") as workdir:
            r = run_openmss(os.path.abspath(args.openmss), args.end, args.error, args.steps,
                            workdir)
    line = (f"walker: OpenMSS GSTIFF ERROR={args.error:g} to {args.end:g} s: {r['status']} in "
            f"{r['wall']:.2f} s wall, {r['cpu']:.2f} s CPU")
    if r["status"] == "ok":
        line += (f", {r['steps']} steps, {1e3 * r['cpu'] / r['steps']:.3f} ms CPU/step, walked "
                 f"{r['walked']:.4f} m, lowest pelvis {r['lowest']:.4f} m, deepest sole "
                 f"{1e3 * r['depth']:.3f} mm (at the outputs)")
    else:
        line += f" ({r.get('note')})"
    print(line, flush=True)
    if args.mujoco:
        compile_mujoco(args.mujoco)
        q, rc = run_mujoco(os.path.abspath(args.mujoco), args.end, args.dt)
        print(f"walker: MuJoCo RK4 dt={args.dt:g}: {'ok' if rc == 0 else 'failed'} in "
              f"{q.get('wall', float('nan')):.2f} s wall, {q.get('cpu', float('nan')):.2f} s "
              f"CPU, {int(q.get('steps', 0))} steps, walked {q.get('walked', float('nan')):.4f} "
              f"m, lowest pelvis {q.get('lowest', float('nan')):.4f} m, deepest sole "
              f"{1e3 * q.get('depth', float('nan')):.3f} mm", flush=True)


if __name__ == "__main__":
    main()
