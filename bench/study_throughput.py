#!/usr/bin/python3
"""Design-study throughput: the example study (examples/study/piston.yaml, 100 variants) on a
LocalCluster with one worker and with two, each from scratch in a folder of its own.

Prints, for each worker count, the wall time (cluster start, all variants, table and plot),
the variants per second, and the speed-up of two workers over one; and whether the two
tables are byte-for-byte the same (they must be: docs/studies.md). Reported, never asserted:
on a machine whose two cores are shared the figure says more about the load than the code.

    PYTHONPATH=build/python /usr/bin/python3 bench/study_throughput.py [--study FILE]
"""

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--study", default=ROOT / "examples" / "study" / "piston.yaml")
    parser.add_argument("--workers", default="1,2", help="worker counts to compare")
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT / "build" / "python"))
    from openmss.study import load_study, run_study

    study = load_study(args.study)
    counts = [int(w) for w in args.workers.split(",")]
    times, tables = {}, {}
    with tempfile.TemporaryDirectory(prefix="openmss-study-bench-") as tmp:
        for n in counts:
            start = time.monotonic()
            report = run_study(study, Path(tmp) / f"w{n}", workers=n, progress=False, plot=False)
            times[n] = time.monotonic() - start
            tables[n] = report.table.read_bytes()
            ok = report.statuses.get("ok", 0)
            print(f"{n} worker(s): {report.variants} variants ({ok} ok) in {times[n]:.1f} s, "
                  f"{report.variants / times[n]:.2f} variants/s", flush=True)
    base = counts[0]
    for n in counts[1:]:
        print(f"speed-up {n} vs {base} worker(s): {times[base] / times[n]:.2f}x")
    same = len(set(tables.values())) == 1
    print(f"tables identical for {', '.join(map(str, counts))} workers: {'yes' if same else 'NO'}")
    print(f"machine: {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} at the end")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
