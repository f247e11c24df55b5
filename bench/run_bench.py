#!/usr/bin/env python3
"""Side-by-side benchmark of OpenMSS, Simbody and MuJoCo on the generated chain models.

Driven by scripts/bench.sh (which builds the programs); run it directly only with the paths of
already built programs. For every model and size it runs tight-tolerance references, then each
engine at a small ladder of settings, alternating engines, and measures per run: process wall
time, integration steps, time per step, tip position error against the reference, and peak
resident memory (the child's VmHWM, polled every 5 ms while it runs). It prints the table and writes
docs/performance.md and the scaling plot.
"""

import argparse
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

# Simulated time per model, and why (see docs/performance.md, "Choices"):
# pendulum chains start straight, tilted 0.1 rad, at rest: near-linear, non-chaotic motion, so
# the tip state after the 10 s is a meaningful accuracy measure; the four-bar row
# reaches its singular (flat) configuration near t = 1 s, so it stops at 0.5 s; the bushing
# chain is stiff (ω up to ~300 rad/s) and 1 s covers many periods.
# The stiff chains run 1 s: an explicit peer's step is held near 1e-5 s by their joint modes.
END_TIME = {"chain-planar": 10.0, "chain-spatial": 10.0, "chain-stiff4": 1.0, "chain-stiff8": 1.0,
            "fourbar": 0.5, "bushing": 1.0, "bushing-stiff": 1.0}
# What bench/peers/ builds: Simbody also the bushing chain; MuJoCo has no bushing element.
PEER_MODELS = {"chain-planar", "chain-spatial", "chain-stiff4", "chain-stiff8", "bushing",
               "bushing-stiff"}
MUJOCO_MODELS = PEER_MODELS - {"bushing", "bushing-stiff"}
STIFF_MODELS = {"chain-stiff4", "chain-stiff8", "bushing", "bushing-stiff"}

# (INTEGRATOR, ERROR) settings. GSTIFF (the default) and WSTIFF from ERROR = 1e-3 down, so
# that "matched accuracy" can pair a peer run with the OpenMSS setting of about its tip error
# (the tolerance barely moves their step count on the chains: orders 3-6 are only weakly stable
# on the undamped high-frequency modes, and the stability-limit detection of docs/integrators.md,
# "Order selection", holds order 2 for long stretches; planar N = 100, GSTIFF over 10 s: 419
# steps at 1e-3, 1816 at 1e-4). Not below 1e-6, where the I3 corrector meets round-off.
# MERSON, the explicit method for non-stiff models (docs/integrators.md, "MERSON"), on the
# models it is meant for; not on the stiff bushing chain, where its steps are held by stability
# (it warns and names GSTIFF).
# HHT, the other integrator of real data sets (issue 21), from ERROR = 1e-3 (ADAMS's default)
# down, for the same reason as GSTIFF: its tip error at 1e-3 is far above a peer's loosest run.
OPENMSS_LADDER = [("GSTIFF", 1e-3), ("GSTIFF", 1e-4), ("GSTIFF", 1e-5), ("GSTIFF", 1e-6),
                  ("WSTIFF", 1e-3), ("WSTIFF", 1e-4), ("WSTIFF", 1e-6), ("HHT", 1e-3),
                  ("HHT", 1e-4), ("HHT", 1e-5), ("HHT", 1e-6),
                  ("MERSON", 1e-4), ("MERSON", 1e-5), ("MERSON", 1e-6)]
OPENMSS_SKIP = {("MERSON", m) for m in STIFF_MODELS}
# Simbody (integrator, accuracy): RungeKuttaMersonIntegrator (1e-6: the figure); on the
# stiff chains also CPodesIntegrator, Simbody's implicit BDF.
SIMBODY_LADDER = [("RKMerson", 1e-4), ("RKMerson", 1e-5), ("RKMerson", 1e-6)]
SIMBODY_STIFF_LADDER = SIMBODY_LADDER + [("CPodes", 1e-4), ("CPodes", 1e-5), ("CPodes", 1e-6)]
# MuJoCo (integrator, time step): RK4 (1e-3: the issue's figure). The stiff chains' joint modes
# (up to about 2 sqrt(k/I) / sqrt(1/4) rad/s) hold an explicit step below ~2.8 / omega: RK4 at
# 1e-5 diverges on chain-stiff8 at 1e-4; MuJoCo's "implicit" treats the damping implicitly only.
MUJOCO_LADDER = [("RK4", 1e-2), ("RK4", 1e-3)]
MUJOCO_STIFF_LADDER = {"chain-stiff4": [("RK4", 1e-3), ("RK4", 1e-4), ("implicit", 1e-4)],
                       "chain-stiff8": [("RK4", 2e-5), ("RK4", 1e-5), ("implicit", 1e-5)]}
# OpenMSS's own tight run: the accuracy reference where Simbody has no model, and a cross-check
# of Simbody's where it has. MERSON at 1e-8 (its error falls about as fast as ERROR: 6e-12 m
# at the tip of the planar 100-chain at 1e-9) also runs the 1000-link chains, where GSTIFF at
# 1e-8 meets round-off in its corrector; GSTIFF at 1e-8 on the stiff bushing chain.
OPENMSS_REFERENCE = {"bushing": ("GSTIFF", 1e-8), "bushing-stiff": ("GSTIFF", 1e-8),
                     "chain-stiff4": ("GSTIFF", 1e-9),
                     "chain-stiff8": ("GSTIFF", 1e-9)}
OPENMSS_REFERENCE_DEFAULT = ("MERSON", 1e-8)
SIMBODY_REFERENCE = 1e-10
# The tight reference runs take several times a measured run (Simbody at 1e-10 on the planar
# 1000-link chain: 60-100 s on this machine), so they get this multiple of the peer time limit.
REFERENCE_TIMEOUT_FACTOR = 3


def run_process(cmd, cwd, timeout):
    """Runs cmd; returns (status, stdout, wall seconds, peak RSS MB, CPU seconds) or status
    'timeout'. CPU seconds: the child's user + system time (wait4), which a machine shared with
    other work inflates far less than the wall time."""
    start = time.perf_counter()
    out_file = tempfile.TemporaryFile(mode="w+")
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=out_file, stderr=subprocess.STDOUT,
                            start_new_session=True)
    # Peak RSS: the child's own VmHWM, polled while it runs. wait4's ru_maxrss would not do: Linux
    # carries the forking Python process's high-water mark across exec into the child's figure.
    hwm_kb = 0
    while True:
        try:
            with open(f"/proc/{proc.pid}/status") as status_file:
                for line in status_file:
                    if line.startswith("VmHWM:"):
                        hwm_kb = max(hwm_kb, int(line.split()[1]))
        except (OSError, ValueError):
            pass
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid != 0:
            break
        if time.perf_counter() - start > timeout:
            os.killpg(proc.pid, signal.SIGKILL)
            # The CPU the run had used when stopped: a lower bound on what it needed, which
            # bounds our ratio when every peer run is stopped (assign_ratios).
            _, _, usage = os.wait4(proc.pid, 0)
            return ("timeout", "", time.perf_counter() - start, hwm_kb / 1024.0,
                    usage.ru_utime + usage.ru_stime)
        time.sleep(0.005)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    out_file.seek(0)
    cpu = usage.ru_utime + usage.ru_stime
    return proc.returncode, out_file.read(), wall, hwm_kb / 1024.0, cpu


def decode_req_tip(req_path):
    """Tip position and velocity from REQUEST/3..5 of the generated data set (see
    bench/model_generators.cpp): each value is AINT(v) + 1e-6 (a + b) in three printed numbers."""
    with open(req_path) as f:
        lines = f.read().splitlines()
    # Fixed-width fields (" %13.5E" x 6): three-digit exponents leave no blank between them.
    rows = [[float(line[1 + 13 * k:14 + 13 * k]) for k in range(6)] for line in lines[-3:]]
    values = []
    for row in rows:
        for half in (0, 3):
            whole, a, b = row[half:half + 3]
            values.append(whole + 1e-6 * (a + b))
    return values


def run_openmss(args, kind, n, error, workdir, timeout, integrator="GSTIFF"):
    name = f"{kind}-{n}-{integrator.lower()}-e{error:g}"
    adm = os.path.join(workdir, f"{kind}-{n}.adm")
    if not os.path.exists(adm):
        with open(adm, "w") as f:
            subprocess.run([args.generate, kind, str(n)], stdout=f, check=True)
    acf = os.path.join(workdir, name + ".acf")
    with open(acf, "w") as f:
        subprocess.run([args.generate, "acf", os.path.basename(adm), name, str(END_TIME[kind]),
                        "10", f"{error:g}", integrator], stdout=f, check=True)
    status, out, wall, rss, cpu = run_process([args.openmss, "run", os.path.basename(acf)],
                                              workdir, timeout)
    result = {"engine": "OpenMSS", "setting": f"{integrator} ERROR={error:g}", "wall": wall,
              "cpu": cpu, "rss": rss, "status": status}
    if status == "timeout":
        return result
    m = re.search(r"reached t = (\S+) with (\d+) integration steps", out)
    if status != 0 or not m or abs(float(m.group(1)) - END_TIME[kind]) > 1e-9:
        result["status"] = "failed"
        result["note"] = out.strip().splitlines()[-1] if out.strip() else "no output"
        return result
    result["steps"] = int(m.group(2))
    result["tip"] = decode_req_tip(os.path.join(workdir, name + ".req"))
    return result


def run_peer(program, engine, kind, n, setting, timeout, label, method):
    # In a scratch folder of its own: MuJoCo writes MUJOCO_LOG.TXT into its working directory
    # (it used to land at the repository root).
    with tempfile.TemporaryDirectory(prefix="openmss-bench-peer-") as cwd:
        status, out, wall, rss, cpu = run_process([os.path.abspath(program), kind, str(n),
                                                   str(END_TIME[kind]), f"{setting:g}", method],
                                                  cwd, timeout)
    result = {"engine": engine, "setting": label, "wall": wall, "cpu": cpu, "rss": rss,
              "status": status}
    if status != 0:
        if status != "timeout":
            result["status"] = "failed"
            result["note"] = out.strip().splitlines()[-1] if out.strip() else "no output"
        return result
    fields = dict(line.split("=", 1) for line in out.splitlines() if "=" in line)
    result["steps"] = int(fields["steps"])
    result["tip"] = [float(x) for x in fields["tip"].split()]
    return result


def distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a[:3], b[:3])) ** 0.5


def fmt_time(s):
    return f"{s:.3g}"


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--openmss", required=True)
    p.add_argument("--generate", required=True)
    p.add_argument("--mujoco")
    p.add_argument("--simbody")
    p.add_argument("--sizes", default="10,100,1000")
    p.add_argument("--models", default="chain-planar,chain-spatial,chain-stiff4,chain-stiff8,"
                   "fourbar,bushing,bushing-stiff")
    p.add_argument("--timeout", type=float, default=900.0, help="seconds per OpenMSS run")
    p.add_argument("--peer-timeout", type=float, default=300.0, help="seconds per peer run")
    p.add_argument("--peer-max-n", type=int, default=1000000,
                   help="skip peer runs above this size")
    p.add_argument("--markdown", default="docs/performance.md")
    p.add_argument("--plot", default="docs/performance-scaling.png")
    p.add_argument("--command", default="scripts/bench.sh")
    args = p.parse_args()
    # The programs run in scratch folders: relative paths (scripts/bench.sh passes some) are
    # made absolute first.
    args.openmss, args.generate = os.path.abspath(args.openmss), os.path.abspath(args.generate)
    sizes = [int(s) for s in args.sizes.split(",")]
    models = args.models.split(",")
    workdir = tempfile.mkdtemp(prefix="openmss-bench-")
    rows, references = [], []
    # (engine, model, setting) or (engine, model, N) that timed out: skip the larger sizes of that
    # setting and the tighter settings at that size, of the same model only.
    timed_out = set()
    current = {"model": None}

    def guarded(engine, label, n, fn, timeout, peer):
        key = (engine, current["model"], label)
        # The method family (GSTIFF, RK-Merson, CPodes, RK4, implicit, ...): a timed-out setting
        # skips the tighter settings of its own family only, since another method (CPodes after
        # RK-Merson on a stiff model) may be much cheaper.
        family = (engine, current["model"], n, label.split()[0])
        if peer and n > args.peer_max_n:
            return {"engine": engine, "setting": label, "status": "skipped",
                    "note": f"skipped, N > {args.peer_max_n} (OPENMSS_BENCH_PEER_MAX_N)"}
        if family in timed_out:
            return {"engine": engine, "setting": label, "status": "skipped",
                    "note": f"skipped, a looser {label.split()[0]} setting took > {timeout:g} s"}
        if key in timed_out:
            return {"engine": engine, "setting": label, "status": "skipped",
                    "note": f"skipped, > {timeout:g} s at a smaller N"}
        r = fn()
        if r["status"] == "timeout":
            timed_out.add(key)
            # A tight reference run that times out says nothing about the looser measured
            # settings of the same engine: only a measured setting skips the tighter ones.
            if not label.startswith("ref "):
                timed_out.add(family)
            r["note"] = f"skipped, > {timeout:g} s (timeout)"
        return r

    for kind in models:
        peers = kind in PEER_MODELS
        current["model"] = kind
        for n in sizes:
            print(f"== {kind} N={n} (t_end {END_TIME[kind]} s)", flush=True)
            # References first: OpenMSS tight, and Simbody tight as the cross-check.
            ref_g, ref_e = OPENMSS_REFERENCE.get(kind, OPENMSS_REFERENCE_DEFAULT)
            ref_om = guarded("OpenMSS", f"ref {ref_g} ERROR={ref_e:g}", n,
                             lambda: run_openmss(args, kind, n, ref_e, workdir, args.timeout,
                                                 ref_g), args.timeout, False)
            ref_sb = None
            if peers and args.simbody:
                ref_sb = guarded("Simbody", f"ref accuracy={SIMBODY_REFERENCE:g}", n,
                                 lambda: run_peer(args.simbody, "Simbody", kind, n,
                                                  SIMBODY_REFERENCE, REFERENCE_TIMEOUT_FACTOR *
                                                  args.peer_timeout,
                                                  f"RK-Merson {SIMBODY_REFERENCE:g}", "RKMerson"),
                                 REFERENCE_TIMEOUT_FACTOR * args.peer_timeout, True)
            # The reference for the accuracy column: Simbody's tight run where it exists (it
            # agrees with MuJoCo at small steps to ~1e-9 m), else OpenMSS's tight run.
            ref = None
            for r in (ref_sb, ref_om):
                if r and "tip" in r:
                    ref = r
                    break
            references.append({"model": kind, "n": n, "openmss": ref_om, "simbody": ref_sb,
                               "used": ref["engine"] if ref else "none"})
            # Measurements, alternating engines setting by setting.
            plans = []
            simbody_ladder = SIMBODY_STIFF_LADDER if kind in STIFF_MODELS else SIMBODY_LADDER
            mujoco_ladder = MUJOCO_STIFF_LADDER.get(kind, MUJOCO_LADDER)
            for i in range(max(len(OPENMSS_LADDER), len(simbody_ladder), len(mujoco_ladder))):
                if i < len(OPENMSS_LADDER) and (OPENMSS_LADDER[i][0], kind) not in OPENMSS_SKIP:
                    g, e = OPENMSS_LADDER[i]
                    plans.append(("OpenMSS", f"{g} ERROR={e:g}", False,
                                  lambda g=g, e=e: run_openmss(args, kind, n, e, workdir,
                                                               args.timeout, g), args.timeout))
                if peers and args.simbody and i < len(simbody_ladder):
                    m, a = simbody_ladder[i]
                    label = f"{'RK-Merson' if m == 'RKMerson' else m} {a:g}"
                    plans.append(("Simbody", label, True,
                                  lambda a=a, m=m, label=label: run_peer(
                                      args.simbody, "Simbody", kind, n, a, args.peer_timeout,
                                      label, m), args.peer_timeout))
                if kind in MUJOCO_MODELS and args.mujoco and i < len(mujoco_ladder):
                    m, h = mujoco_ladder[i]
                    label = f"{m} dt={h:g}"
                    plans.append(("MuJoCo", label, True,
                                  lambda h=h, m=m, label=label: run_peer(
                                      args.mujoco, "MuJoCo", kind, n, h, args.peer_timeout,
                                      label, m), args.peer_timeout))
            for engine, label, peer, fn, timeout in plans:
                r = guarded(engine, label, n, fn, timeout, peer)
                r.update({"model": kind, "n": n})
                if ref and "tip" in r:
                    r["error"] = distance(r["tip"], ref["tip"])
                rows.append(r)
                print("   ", engine, label, r.get("status"), fmt_time(r.get("wall", 0)), "s",
                      "cpu", fmt_time(r.get("cpu", 0)), "s",
                      r.get("steps", ""), f"err {r['error']:.2e}" if "error" in r else
                      r.get("note", ""), flush=True)
            render(args, rows, references, sizes, final=False)
    render(args, rows, references, sizes, final=True)


def assign_ratios(rows):
    """Sets 'ratio' and 'ratio_vs' on every OpenMSS row with a tip error: our CPU time over the
    fastest peer run at the same model and N that is at least as accurate; when no peer run is,
    over the most accurate peer run (marked *); when no peer run finished because every one was
    stopped at the time limit (or skipped after a looser setting of its method was), over the
    least CPU a stopped run had used, a lower bound on the peers' time (marked <)."""
    for r in rows:
        if r["engine"] != "OpenMSS" or "error" not in r:
            continue
        same = [q for q in rows if q["model"] == r["model"] and q["n"] == r["n"]
                and q["engine"] != "OpenMSS"]
        peer_rows = [q for q in same if "error" in q]
        stopped = [q for q in same if q["status"] == "timeout" and q.get("cpu", 0) > 0]
        # On CPU time (user + system of each process): the machine is shared, and the peers
        # run on one thread (scripts/bench.sh runs OpenMSS with OPENMSS_THREADS=1).
        if peer_rows:
            matched = [q for q in peer_rows if q["error"] <= r["error"]]
            if matched:
                best = min(matched, key=lambda q: q["cpu"])
                r["ratio"] = f"{r['cpu'] / best['cpu']:.2f}"
            else:
                best = min(peer_rows, key=lambda q: q["error"])
                r["ratio"] = f"{r['cpu'] / best['cpu']:.2f}*"
            r["ratio_vs"] = f"{best['engine']} {best['setting']}"
        elif stopped and all(q["status"] in ("timeout", "skipped") for q in same):
            least = min(stopped, key=lambda q: q["cpu"])
            r["ratio"] = f"<{r['cpu'] / least['cpu']:.2f}"
            r["ratio_vs"] = (f"every peer run stopped (least CPU when stopped: "
                             f"{least['engine']} {least['setting']}, {least['cpu']:.0f} s)")


def ratio_value(text):
    return float(text.strip("<*"))


def best_per_integrator(rows, sizes):
    """Per model and N, each OpenMSS integrator's least ratio over its ERROR settings (a ratio
    against a peer run at least as accurate preferred over a * one), as markdown rows."""
    integrators = list(dict.fromkeys(r["setting"].split()[0] for r in rows
                                     if r["engine"] == "OpenMSS" and "ratio" in r))
    lines = ["| model | N | " + " | ".join(integrators) + " |",
             "|---|---|" + "---|" * len(integrators)]
    for kind in dict.fromkeys(r["model"] for r in rows):
        for n in sizes:
            cells = []
            for g in integrators:
                cand = [q for q in rows if q["model"] == kind and q["n"] == n
                        and q["engine"] == "OpenMSS" and "ratio" in q
                        and q["setting"].split()[0] == g]
                if not cand:
                    cells.append("–")
                    continue
                best = min(cand, key=lambda q: ("*" in q["ratio"], ratio_value(q["ratio"])))
                cells.append(f"{best['ratio']} at {best['setting'].split('=')[1]} "
                             f"({best['error']:.0e} m)")
            if any(c != "–" for c in cells):
                lines.append(f"| {kind} | {n} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def render(args, rows, references, sizes, final):
    assign_ratios(rows)

    header = ("| model | N | engine | setting | wall s | CPU s | steps | CPU ms/step | "
              "tip error m | peak RSS MB | ours / best peer (CPU) |")
    lines = [header, "|" + "---|" * 11]
    for r in rows:
        if "steps" in r:
            per = 1000.0 * r["cpu"] / max(r["steps"], 1)
            lines.append(
                f"| {r['model']} | {r['n']} | {r['engine']} | {r['setting']} | "
                f"{fmt_time(r['wall'])} | {fmt_time(r['cpu'])} | {r['steps']} | {per:.3g} | "
                + (f"{r['error']:.1e}" if "error" in r else "no reference") +
                f" | {r['rss']:.0f} | "
                f"{r.get('ratio', '') + (' vs ' + r['ratio_vs'] if 'ratio' in r else '')} |")
        else:
            lines.append(f"| {r['model']} | {r['n']} | {r['engine']} | {r['setting']} | "
                         f"{r.get('note', r['status'])} | | | | | | |")
    ref_lines = ["| model | N | OpenMSS tight run vs Simbody 1e-10 (tip, m) | reference used |",
                 "|---|---|---|---|"]
    for rf in references:
        om, sb = rf["openmss"], rf["simbody"]
        if om and sb and "tip" in om and "tip" in sb:
            cross = f"{distance(om['tip'], sb['tip']):.1e}"
        else:
            missing = [x for x in (om, sb) if x and "tip" not in x]
            cross = "; ".join(f"{x['engine']}: {x.get('note', x['status'])}" for x in missing)
            cross = cross or "no peer model"
        ref_lines.append(f"| {rf['model']} | {rf['n']} | {cross} | {rf['used']} |")
    # Summary: per model and size with a peer, every OpenMSS setting's ratio and tip error side
    # by side (the setting a user picks depends on the accuracy wanted).
    settings = list(dict.fromkeys(r["setting"] for r in rows if r["engine"] == "OpenMSS"))
    summary = ["| model | N | " + " | ".join(settings) + " |",
               "|---|---|" + "---|" * len(settings)]
    for kind in dict.fromkeys(r["model"] for r in rows):
        for n in sizes:
            cells, any_ratio = [], False
            for setting in settings:
                r = next((q for q in rows if q["model"] == kind and q["n"] == n
                          and q["engine"] == "OpenMSS" and q["setting"] == setting), None)
                if r and "ratio" in r:
                    any_ratio = True
                    cells.append(f"{r['ratio']} ({r['error']:.0e} m)")
                else:
                    cells.append("–" if not r else str(r.get("note", r["status"]))[:20])
            if any_ratio:
                summary.append(f"| {kind} | {n} | " + " | ".join(cells) + " |")
    growth = ["| model | setting | N from | N to | time per step grows as N^p, p = |",
              "|---|---|---|---|---|"]
    for kind in dict.fromkeys(r["model"] for r in rows):
        for setting in dict.fromkeys(r["setting"] for r in rows if r["engine"] == "OpenMSS"):
            pts = sorted((r["n"], r["cpu"] / max(r["steps"], 1)) for r in rows
                         if r["model"] == kind and r["setting"] == setting
                         and r["engine"] == "OpenMSS" and "steps" in r and r["n"] >= 100)
            if len(pts) >= 2 and pts[-1][0] > pts[0][0]:
                p_exp = math.log(pts[-1][1] / pts[0][1]) / math.log(pts[-1][0] / pts[0][0])
                growth.append(f"| {kind} | {setting} | {pts[0][0]} | {pts[-1][0]} | {p_exp:.2f} |")
    args.summary = ("Each integrator's best setting (least ratio, with its ERROR and tip error):"
                    "\n\n" + best_per_integrator(rows, sizes) + "\n\nEvery setting:\n\n" +
                    "\n".join(summary) + "\n\nTime per step (from N = 100 up):\n\n" +
                    "\n".join(growth))
    table = "\n".join(lines)
    if final:
        print()
        print(args.summary)
        print()
        print(table)
        print()
        print("\n".join(ref_lines))

    if args.markdown:
        write_markdown(args, table, "\n".join(ref_lines), sizes)
    if args.plot:
        write_plot(args.plot, rows)


BEGIN_MARK = ("<!-- BEGIN generated by scripts/bench.sh (bench/run_bench.py): the text up to the "
              "END mark is rewritten by every run; write by hand outside it. -->")
END_MARK = "<!-- END generated by scripts/bench.sh -->"
REPRODUCING = """## Reproducing

    scripts/bench.sh            # N = 10, 100, 1000
    scripts/bench.sh --quick    # N = 10, 100

Environment knobs: `OPENMSS_BENCH_TIMEOUT` (seconds per OpenMSS run, default 900),
`OPENMSS_BENCH_PEER_TIMEOUT` (seconds per peer run, default 300), `OPENMSS_BENCH_PEER_MAX_N`
(skip peer runs above this N, e.g. 100 to leave MuJoCo's dense O(N^3) N = 1000 out),
`OPENMSS_BENCH_BUILD_DIR` (default build-bench). The peer programs are
`bench/peers/mujoco_chain.cpp` and `bench/peers/simbody_chain.cpp`, compiled by the script with
g++; they build the models from the same generator source as the ADAMS data sets.
"""


def splice_generated(path, generated):
    """Puts `generated` between BEGIN_MARK and END_MARK of the page at `path`, leaving the text
    outside the marks (hand-written sections) as it is. A new page gets a title, the marks and
    the reproducing notes; a page without the marks is not touched (the block goes to
    path + ".generated" and a message says so), so that no hand-written text is lost."""
    block = f"{BEGIN_MARK}\n{generated.strip()}\n{END_MARK}"
    if not os.path.exists(path):
        with open(path, "w") as f:
            f.write(f"# Performance\n\n{block}\n\n{REPRODUCING}")
        return path
    with open(path) as f:
        page = f.read()
    begin, end = page.find(BEGIN_MARK), page.find(END_MARK)
    if begin < 0 or end < begin:
        aside = path + ".generated"
        with open(aside, "w") as f:
            f.write(block + "\n")
        print(f"run_bench.py: {path} has no generated-section marks; wrote {aside} instead",
              file=sys.stderr)
        return aside
    with open(path, "w") as f:
        f.write(page[:begin] + block + page[end + len(END_MARK):])
    return path


def write_markdown(args, table, ref_table, sizes):
    machine = subprocess.run(["sh", "-c", "lscpu | sed -n 's/^Model name: *//p'; nproc"],
                             capture_output=True, text=True).stdout.split("\n")
    openmss_settings = '; '.join(f'{g} at ERROR = {e:g}' for g, e in OPENMSS_LADDER)
    simbody = ', '.join(f'{a:g}' for _, a in SIMBODY_LADDER)
    mujoco = ', '.join(f'{h:g}' for _, h in MUJOCO_LADDER)
    stiff_mujoco = '; '.join(f"{k}: " + ', '.join(f'{m} dt = {h:g}' for m, h in v)
                             for k, v in MUJOCO_STIFF_LADDER.items())
    text = f"""Side-by-side timings of OpenMSS, Simbody 3.7 and MuJoCo 2.2.2 (the Debian packages) on the
benchmark models of `bench/model_generators.cpp`, produced by one command:

    {args.command}

Machine: {machine[0].strip() if machine else 'unknown'}, {machine[1].strip() if len(machine) > 1
else '?'} cores, shared with other work while measured: ratios are of CPU time (user + system
of each whole process), which the load inflates far less than the wall time (also listed).
Sizes: N = {', '.join(str(s) for s in sizes)}. Generated {time.strftime('%Y-%m-%d %H:%M')}.

## Models and choices

- **chain-planar / chain-spatial**: N slender links (1 m, 1 kg, radius 0.02 m) joined by
  revolute joints, hanging from ground; spatial chains alternate joint axes between ground z
  and x and lean towards x and z. Each chain starts straight, tilted 0.1 rad from the vertical,
  at rest, and runs 10 s (the issue's horizon). The small tilt keeps the motion near-linear,
  so it is not chaotic and the tip state at 10 s is a meaningful accuracy measure; a chain
  released from horizontal would diverge between any two integrators within seconds.
- **chain-stiff4 / chain-stiff8**: the planar chain with a rotational SPRINGDAMPER on every
  joint, stiffness over the link's inertia about its joint k/I = 1e4 and 1e8 1/s^2, damping
  ratio 0.05 (MuJoCo: hinge stiffness and damping; Simbody: MobilityLinearSpring and
  MobilityLinearDamper), 1 s. Stiff: the joint modes hold an explicit method's step near
  1/sqrt(k/I), while an implicit one steps over them.
- **fourbar**: the IFToMM benchmark A02 "N four-bar mechanism" (N square windows of unit
  1 kg thin rods, B0 moving at 1 m/s, gravity 9.81 along -y). It runs 0.5 s, before the first
  flat singular configuration (t = 0.72 s); the passages through it and the benchmark's 20 s
  are measured against the exact solution in docs/validation.md ("IFToMM A02"). OpenMSS only:
  MuJoCo closes loops with soft constraints, and the Simbody program does not build loops yet.
- **bushing**: N free 1 kg blocks each held to the previous one by a BUSHING and a
  translational SPRINGDAMPER (6N DOF, stiff), 1 s. OpenMSS and Simbody (the BUSHING law as a
  custom force: see "The bushing chain against Simbody"); not MuJoCo (no bushing element).
- **bushing-stiff**: the same chain with 100x the stiffnesses (1e6 N/m, 1e4 N m/rad) and a
  damping ratio of about 0.1: modes near 1000 rad/s, the stiff case of the bushing chain.
- **Settings**: OpenMSS {openmss_settings} (MERSON not on the stiff models);
  Simbody RungeKuttaMersonIntegrator at accuracy {simbody}
  (1e-6 is the issue's figure), on the stiff chains also CPodesIntegrator (implicit BDF) at the
  same accuracies; MuJoCo RK4 at dt = {mujoco}
  (1e-3 is the issue's figure; 1e-2 is the coarse step that still reaches a comparable
  accuracy), on the stiff chains {stiff_mujoco} (RK4 at twice the
  larger step diverges). Engines alternate setting by setting, so slow drifts of the machine
  load hit all.
  GSTIFF and WSTIFF run from ERROR = 1e-3 down, so that a peer run can be matched with the
  OpenMSS setting of about its accuracy; their step count moves little with the tolerance on
  these chains (orders 3–6 are only weakly stable on the undamped high-frequency modes, and the
  stability-limit detection of docs/integrators.md, "Order selection", holds order 2 for long
  stretches). Not below 1e-6, where the I3 corrector meets round-off on the chains.
  MERSON is the explicit Kutta–Merson method on the index-1 equations (docs/integrators.md),
  for non-stiff models.
- **Times** are of the whole process (model construction, initial conditions, integration,
  OpenMSS's 10 output steps), measured from outside; **peak RSS** is the child's VmHWM, polled
  every 5 ms. OpenMSS runs on one thread (`OPENMSS_THREADS=1`, set by `scripts/bench.sh`
  unless the command sets it), as the peers do, so that CPU times compare like with like.
- **Accuracy**: distance of the tip (end of the last link; B0 for the four-bar row; last
  block's far end for the bushing chain) at the final time from a reference: Simbody at
  accuracy 1e-10 where the model exists in Simbody, else OpenMSS's tight run (MERSON at
  ERROR = 1e-8; GSTIFF at 1e-8 on the bushing chain, 1e-9 on the stiff chains). The references
  are cross-checked below. OpenMSS reads its tip from REQUEST/3..5, which carry each
  value split into exactly printable pieces (the .req file prints six digits).
- **ours / best peer**: our CPU time over the least CPU time of a peer run at least as accurate;
  `*` marks rows where no peer run was as accurate and the most accurate one is used; `<`
  rows where every peer run was stopped at the time limit. Rows reading "skipped" hit the time
  limit (`timeout`) or a size cap; larger sizes of the same setting and tighter settings of the
  same method at that size are then skipped rather than left to hang.

## Summary

For each model and size with a peer, the ratio of our CPU time to the least of a peer run at
least as accurate (`*`: no peer run was as accurate, so the most accurate one is used; `<`: every
peer run was stopped at the time limit, so the ratio is below our time over the least CPU a
stopped run had used), with our tip error in brackets (all rows are in "Results" below): first
each integrator's best ERROR setting, then every setting; then how each of our settings' CPU
time per step grows from N = 100 to the largest N. Issue 21 asks for a ratio of at most 1.0 at
N = 100 and 1000 on the chains (0.5 on the stiff models), and time per step growing no faster
than N^1.1 from N = 1000 to 10,000 (measured by `bench/scaling.py`, hand-written section
"Large models and two threads" below; the plot under "Scaling" shows N = 10 to 1000).

{args.summary}

## Results

{table}

### References

{ref_table}

## Scaling

![time per step against N](performance-scaling.png)
"""
    splice_generated(args.markdown, text)


# The plot: one panel per model, each engine's settings as lines, so that a panel's legend stays
# readable (with every model in one panel it ran off the figure).
def write_plot(path, rows):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no plot", file=sys.stderr)
        return
    models = list(dict.fromkeys(r["model"] for r in rows if "steps" in r))
    if not models:
        return
    cols = min(3, len(models))
    nrows = (len(models) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(5.2 * cols, 4.2 * nrows), squeeze=False)
    for ax, kind in zip(axes.flat, models):
        series = {}
        for r in rows:
            if "steps" in r and r["model"] == kind:
                key = f"{r['engine']} {r['setting']}"
                series.setdefault(key, []).append((r["n"],
                                                   1000.0 * r["cpu"] / max(r["steps"], 1)))
        for key, pts in sorted(series.items()):
            pts.sort()
            if len(pts) > 1:
                style = "-" if key.startswith("OpenMSS") else "--"
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, marker="o",
                          markersize=3, label=key)
        ax.set_title(kind, fontsize=9)
        ax.set_xlabel("N", fontsize=8)
        ax.set_ylabel("CPU ms per step", fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        ax.tick_params(labelsize=7)
        if ax.lines:
            ax.legend(fontsize=5, ncol=2)
    for ax in list(axes.flat)[len(models):]:
        ax.axis("off")
    fig.suptitle("Time per step against model size (OpenMSS solid, peers dashed)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def rows_from_markdown(path):
    """The measured rows of a page's generated Results table (the columns render() writes), to
    draw the plot again without re-running (--replot)."""
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) != 11 or not cells[1].isdigit():
                continue
            try:
                cpu, steps = float(cells[5]), int(cells[6])
            except ValueError:
                continue  # a skipped or failed run
            rows.append({"model": cells[0], "n": int(cells[1]), "engine": cells[2],
                         "setting": cells[3], "cpu": cpu, "steps": steps})
    return rows


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--replot":
        # python3 bench/run_bench.py --replot docs/performance.md docs/performance-scaling.png
        write_plot(sys.argv[3], rows_from_markdown(sys.argv[2]))
    else:
        main()
