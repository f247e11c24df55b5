#!/usr/bin/python3
"""Design-study throughput: each study on a LocalCluster of one worker and of two.

For each study and worker count, in a fresh output folder: the cluster is started and every
worker imports the task's module (the start-up, timed apart), then the study runs on that
warm cluster (the steady state: the figure that grows with the study). Prints both times,
the variants per second, the speed-up of two workers over one on the steady state, and
whether the tables are byte-for-byte the same (they must be: docs/studies.md). Exit status 1
when they differ. The speed-up is reported, never asserted: on a machine whose cores are
shared the figure says more about the load than about the code, so the load average is
printed beside it.

Each study runs with the solver as a child process and inside the worker (--in-process),
unless --solver chooses one. The studies (docs/studies.md, "Throughput"): examples/study/piston.yaml (100 variants of a
kinematic run of about 0.06 s: the per-variant overhead shows) and
examples/study/fourbar_motor.yaml (40 variants of a dynamic run of about 0.4 s: the
solver's work dominates).

    PYTHONPATH=build/python /usr/bin/python3 bench/study_throughput.py
        [--study FILE ...] [--workers 1,2] [--threads] [--solver child|in-process|both]
"""

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STUDIES = [ROOT / "examples" / "study" / "piston.yaml",
           ROOT / "examples" / "study" / "fourbar_motor.yaml"]


def load() -> str:
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def measure(study, out, workers, processes, in_process):
    """(start-up seconds, study seconds, report, CPU seconds) of one study on a fresh
    cluster. CPU: of this process (the scheduler and the client), of the worker processes
    and of their children (the solver runs), during the study (not measured for thread
    workers: one process holds them all)."""
    from openmss.study.execute import local_cluster, run_study, warm
    from openmss.study.runner import cpu_seconds

    def cpu():
        if not processes:
            return None
        workers_cpu = client.run(cpu_seconds).values()
        return (sum(cpu_seconds()), sum(w[0] for w in workers_cpu),
                sum(w[1] for w in workers_cpu))

    start = time.monotonic()
    client, cluster = local_cluster(workers, processes=processes)
    try:
        assert warm(client) == workers
        before = cpu()
        ready = time.monotonic()
        report = run_study(study, out, progress=False, plot=False, client=client,
                           in_process=in_process)
        done = time.monotonic()
        after = cpu()
    finally:
        client.close()
        cluster.close()
    used = [b - a for a, b in zip(before, after)] if processes else None
    return ready - start, done - ready, report, used


def bench(path, counts, processes, in_process, tmp):
    from openmss.study import load_study

    study = load_study(path)
    kind = "process" if processes else "thread"
    solver = "in the worker (--in-process)" if in_process else "as a child process"
    print(f"{study.name} ({path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}), "
          f"{kind} workers, solver {solver}:", flush=True)
    steady, tables = {}, {}
    for n in counts:
        startup, steady[n], report, used = measure(study, tmp / f"{study.name}-w{n}", n,
                                                   processes, in_process)
        tables[n] = report.table.read_bytes()
        assert report.ran == report.variants, "a fresh folder runs every variant"
        statuses = ", ".join(f"{c} {s}" for s, c in sorted(report.statuses.items()))
        print(f"  {n} worker(s): start-up {startup:.1f} s; {report.variants} variants "
              f"({statuses}) in {steady[n]:.2f} s = {report.variants / steady[n]:.2f} "
              f"variants/s  [load average {load()}]", flush=True)
        if used:
            per = [1e3 * u / report.variants for u in used]
            print(f"    CPU per variant: scheduler and client {per[0]:.1f} ms, workers "
                  f"{per[1]:.1f} ms, solver child processes {per[2]:.1f} ms", flush=True)
    base = counts[0]
    for n in counts[1:]:
        print(f"  speed-up {n} vs {base} worker(s), steady state: "
              f"{steady[base] / steady[n]:.2f}x")
    same = len(set(tables.values())) == 1
    print(f"  tables identical for {', '.join(map(str, counts))} workers: "
          f"{'yes' if same else 'NO'}", flush=True)
    return same


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--study", action="append", type=Path,
                        help="a study file (repeatable; default: the two example studies)")
    parser.add_argument("--workers", default="1,2", help="worker counts to compare")
    parser.add_argument("--threads", action="store_true",
                        help="thread workers in this process instead of worker processes")
    parser.add_argument("--solver", choices=("child", "in-process", "both"), default="both",
                        help="each variant's solver as a child process (openmss run), inside "
                        "its worker (--in-process, the extension), or each in turn (default)")
    args = parser.parse_args()
    # The workers are spawned processes: they find the package on PYTHONPATH.
    package = str(ROOT / "build" / "python")
    if package not in os.environ.get("PYTHONPATH", "").split(os.pathsep):
        os.environ["PYTHONPATH"] = os.pathsep.join(
            p for p in (package, os.environ.get("PYTHONPATH")) if p)
        sys.path.insert(0, package)
    counts = [int(w) for w in args.workers.split(",")]
    print(f"machine: {os.cpu_count()} CPUs, load average {load()} at the start", flush=True)
    same = True
    with tempfile.TemporaryDirectory(prefix="openmss-study-bench-") as tmp:
        modes = {"child": [False], "in-process": [True], "both": [False, True]}[args.solver]
        for path in args.study or STUDIES:
            for in_process in modes:
                same = bench(path.resolve(), counts, not args.threads, in_process,
                             Path(tmp) / ("in-process" if in_process else "child")) and same
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
