#!/usr/bin/env python3
"""Large-model scaling and thread speed-up of OpenMSS (issue 21), one command:

    /usr/bin/python3 bench/scaling.py --openmss build/openmss --generate build/bench/openmss-generate

For each model (planar and spatial pendulum chains, bushing chain) and size N (default 1000,
2000, 5000, 10000) it runs GSTIFF twice, to END = T and to END = 2T, and takes the time per step
from the difference (cpu(2T) - cpu(T)) / (steps(2T) - steps(T)), so model construction and
initial conditions, which are run once per process, drop out (each point the least CPU time
of --repeat runs). The whole 2T run's CPU time per step, set-up included, is listed beside it
as a second figure, less noisy but biased by the set-up. Times are CPU times (user + system
of the child, wait4): the machine is shared, and wall-clock times under load are several times
the CPU times. It fits the exponent p of
time per step ~ N^p between the smallest and the largest N, and reports the peak resident memory
of the 2T run per body (the child's VmHWM, polled as bench/run_bench.py does). With
--threads 1,2 every run is made once per thread count (OPENMSS_THREADS) and the speed-up of the
time per step is printed. Writes the tables to --markdown (docs/performance-scale.md).
A run that fails or times out is listed with the last line of its output.
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_bench import run_process  # noqa: E402  (VmHWM polling, timeouts)

# Simulated time of the short run (the long one is twice this): long enough for 50-100 steps
# between the two (at 0.05 s the 1000-link chains took 17 steps more and set-up noise gave a
# negative difference).
SPAN = {"chain-planar": 0.2, "chain-spatial": 0.2, "bushing": 0.05}


def run_once(args, workdir, kind, n, end, threads):
    adm = os.path.join(workdir, f"{kind}-{n}.adm")
    if not os.path.exists(adm):
        with open(adm, "w") as f:
            subprocess.run([args.generate, kind, str(n)], stdout=f, check=True)
    name = f"{kind}-{n}-t{threads}-e{end:g}"
    acf = os.path.join(workdir, name + ".acf")
    with open(acf, "w") as f:
        subprocess.run([args.generate, "acf", os.path.basename(adm), name, f"{end:g}", "2",
                        f"{args.error:g}", "GSTIFF"], stdout=f, check=True)
    os.environ["OPENMSS_THREADS"] = str(threads)
    status, out, wall, rss, cpu = run_process([args.openmss, "run", os.path.basename(acf)],
                                              workdir, args.timeout)
    m = re.search(r"reached t = (\S+) with (\d+) integration steps", out)
    if status != 0 or not m or abs(float(m.group(1)) - end) > 1e-9:
        lines = out.strip().splitlines()
        return {"failed": str(status) + ": " + (lines[0] if lines else "no output")}
    return {"wall": wall, "cpu": cpu, "steps": int(m.group(2)), "rss": rss}


def best_of(args, workdir, kind, n, end, threads):
    """The run with the least CPU time of --repeat runs (the same steps each time: the runs are
    deterministic), so that another job's burst on the shared machine does not enter the
    difference of two runs."""
    runs = [run_once(args, workdir, kind, n, end, threads) for _ in range(args.repeat)]
    failed = [r for r in runs if "failed" in r]
    return failed[0] if failed else min(runs, key=lambda r: r["cpu"])


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--openmss", required=True)
    p.add_argument("--generate", required=True)
    p.add_argument("--sizes", default="1000,2000,5000,10000")
    p.add_argument("--models", default="chain-planar,chain-spatial,bushing")
    p.add_argument("--threads", default="1,2", help="OPENMSS_THREADS values, e.g. 1,2")
    p.add_argument("--error", type=float, default=1e-5)
    p.add_argument("--timeout", type=float, default=1800.0)
    p.add_argument("--repeat", type=int, default=2, help="runs per point; the least CPU counts")
    p.add_argument("--markdown", default="docs/performance-scale.md")
    args = p.parse_args()
    # The programs run in scratch folders: relative paths (scripts/bench.sh passes some) are
    # made absolute first.
    args.openmss, args.generate = os.path.abspath(args.openmss), os.path.abspath(args.generate)
    sizes = [int(s) for s in args.sizes.split(",")]
    threads = [int(t) for t in args.threads.split(",")]
    rows = []
    with tempfile.TemporaryDirectory(prefix="openmss-scale-") as workdir:
        for kind in args.models.split(","):
            for n in sizes:
                for t in threads:
                    short = best_of(args, workdir, kind, n, SPAN[kind], t)
                    long = best_of(args, workdir, kind, n, 2 * SPAN[kind], t)
                    row = {"model": kind, "n": n, "threads": t}
                    failed = short.get("failed") or long.get("failed")
                    if failed:
                        row["failed"] = failed
                    elif long["steps"] > short["steps"]:
                        row["ms_per_step"] = (1000.0 * (long["cpu"] - short["cpu"]) /
                                              (long["steps"] - short["steps"]))
                        row["steps"] = long["steps"]
                        row["cpu"] = long["cpu"]
                        row["wall"] = long["wall"]
                        row["kb_per_body"] = 1024.0 * long["rss"] / n
                        row["rss"] = long["rss"]
                    rows.append(row)
                    print(kind, n, f"threads={t}",
                          {k: round(v, 3) if isinstance(v, float) else v for k, v in row.items()},
                          flush=True)
    os.environ.pop("OPENMSS_THREADS", None)
    lines = ["| model | N | threads | steps (2T) | CPU s (2T) | wall s (2T) | CPU ms/step | "
             "CPU ms/step, whole run | peak RSS MB | KB/body |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "ms_per_step" in r:
            lines.append(f"| {r['model']} | {r['n']} | {r['threads']} | {r['steps']} | "
                         f"{r['cpu']:.3g} | {r['wall']:.3g} | {r['ms_per_step']:.3g} | "
                         f"{1000.0 * r['cpu'] / r['steps']:.3g} | "
                         f"{r['rss']:.0f} | "
                         f"{r['kb_per_body']:.1f} |")
        else:
            note = r.get("failed", "no steps between T and 2T")[:120].replace("|", "/")
            lines.append(f"| {r['model']} | {r['n']} | {r['threads']} | {note} | | | | | | |")
    growth = ["| model | threads | N from | N to | time per step ~ N^p, p = | whole run, p = |",
              "|---|---|---|---|---|---|"]
    for kind in args.models.split(","):
        for t in threads:
            pts = sorted((r["n"], r["ms_per_step"], r["cpu"] / r["steps"]) for r in rows
                         if r["model"] == kind and r["threads"] == t and "ms_per_step" in r
                         and r["ms_per_step"] > 0)
            if len(pts) >= 2:
                (n0, a, wa), (n1, b, wb) = pts[0], pts[-1]
                growth.append(f"| {kind} | {t} | {n0} | {n1} | "
                              f"{math.log(b / a) / math.log(n1 / n0):.2f} | "
                              f"{math.log(wb / wa) / math.log(n1 / n0):.2f} |")
    speed = ["| model | N | ms/step 1 thread | ms/step 2 threads | speed-up |", "|---|---|---|---|---|"]
    for kind in args.models.split(","):
        for n in sizes:
            by = {r["threads"]: r for r in rows if r["model"] == kind and r["n"] == n}
            if 1 in by and 2 in by and "ms_per_step" in by[1] and "ms_per_step" in by[2]:
                a, b = by[1]["ms_per_step"], by[2]["ms_per_step"]
                speed.append(f"| {kind} | {n} | {a:.3g} | {b:.3g} | {a / b:.2f} |")
    text = "\n".join(["# Large models and threads", "",
                      "Generated by `/usr/bin/python3 bench/scaling.py --openmss build/openmss "
                      "--generate build/bench/openmss-generate` (GSTIFF, ERROR = "
                      f"{args.error:g}; time per step from runs to T and 2T, "
                      f"the least CPU time of {args.repeat} runs each; see the script).", "",
                      "## Time per step and memory", ""] + lines +
                     ["", "## Growth", ""] + growth + ["", "## Threads", ""] + speed) + "\n"
    print(text)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
