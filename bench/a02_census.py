#!/usr/bin/env python3
"""How robustly an integrator crosses A02's flat passages: one setting over many variants.

Usage: bench/a02_census.py OPENMSS GENERATE INTEGRATOR:ERROR [END] [N ...]
Runs the IFToMM A02 data set `GENERATE fourbar N` (docs/validation.md, "IFToMM A02") for every
N given (default 10 15 20 25 30 35 39 40 45 50 55 60) on each of KLU's three pivot orders
(default, nobtf, colamd: `openmss run --pivot-order`, which changes only round-off), END s
(default 20) with 20 outputs per second, as bench/a02_table.py does. Each variant passes the
same kind of singular configuration about 2 END / 2 times; a run that stops at one of them on
one variant and not on the next is crossing it on round-off luck. Prints one line per run
(reached t, steps, B0 error at END and the largest over the outputs, against the exact
solution) and then the count of runs that reached END.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from a02_table import fmt, run  # noqa: E402  (the same runs and exact solution)

ORDERS = ("default", "nobtf", "colamd")
DEFAULT_N = (10, 15, 20, 25, 30, 35, 39, 40, 45, 50, 55, 60)


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 64
    openmss, generate = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    integrator, error = sys.argv[3].split(":")
    end = float(sys.argv[4]) if len(sys.argv) > 4 else 20.0
    windows = [int(a) for a in sys.argv[5:]] or list(DEFAULT_N)
    reached, total, stops = 0, 0, []
    for order in ORDERS:
        for n in windows:
            # One directory per N: run() writes the data set once per directory.
            with tempfile.TemporaryDirectory() as workdir:
                r = run(openmss, generate, n, end, integrator, float(error), workdir, order)
            total += 1
            done = r["reached"] >= end - 1e-9
            reached += done
            if not done:
                stops.append(f"{order} N={n} at t = {r['reached']:g} s")
            print(f"{order:8s} N={n:3d}: reached {r['reached']:g} s, {r['steps']} steps, "
                  f"B0 at END {fmt(r['eEnd'])} m, largest {fmt(r['worst'])} m", flush=True)
    print(f"{integrator.replace('_', ' ')} ERROR={error}: {reached} of {total} runs reached "
          f"END = {end:g} s" + (f"; stopped: {'; '.join(stops)}" if stops else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
