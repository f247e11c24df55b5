"""``python3 -m openmss.study run study.yaml [--scheduler ADDRESS] [--workers N] [--threads]
[--in-process] [--out DIR]``
(also ``openmss study …``): runs a design study (docs/studies.md).

Exit status: 0 when every variant has a result (failed variants are results: their status
and message are in the table), 1 for an unusable study file, a missing program or an
unreachable scheduler, 64 for a usage error, 130 when
interrupted (Ctrl-C; the finished variants are kept)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .design import variants
from .execute import run_study
from .spec import StudyError, load_study


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="openmss study",
                                     description="Design studies of ADAMS data sets on Dask.")
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="run the variants missing in the output folder")
    run.add_argument("study", help="the study file (YAML)")
    run.add_argument("--scheduler", help="address of a running Dask scheduler "
                     "(default: a LocalCluster on this machine)")
    run.add_argument("--workers", type=int, help="LocalCluster workers (default: CPU count)")
    run.add_argument("--threads", action="store_true",
                     help="LocalCluster workers as threads of this process (quicker to start, "
                     "slower per variant) instead of processes")
    run.add_argument("--in-process", action="store_true",
                     help="run each variant's solver inside its worker (the extension) instead "
                     "of as a child process: no start-up per variant, but no timeout, and a "
                     "crash takes the worker down")
    run.add_argument("--out", help="output folder (default: ./<study file name>-study)")
    run.add_argument("--binary", help="the openmss program (default: the build tree's)")
    run.add_argument("--no-progress", action="store_true", help="no progress bar")
    run.add_argument("--no-plot", action="store_true", help="no main-effects PNG")
    show = sub.add_parser("variants", help="print the variants' --set options, run nothing")
    show.add_argument("study")
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 64
    try:
        study = load_study(args.study)
    except StudyError as e:
        print(f"openmss study: error: {e}", file=sys.stderr)
        return 1
    if args.command == "variants":
        for v in variants(study):
            print(v.index, " ".join(f"--set '{o}'" for o in v.overrides))
        return 0
    if args.workers is not None and (args.workers < 1 or args.scheduler):
        print("openmss study: --workers is a positive count of LocalCluster workers "
              "(not given with --scheduler)", file=sys.stderr)
        return 64
    if args.threads and args.scheduler:
        print("openmss study: --threads chooses the LocalCluster's workers (not given with "
              "--scheduler)", file=sys.stderr)
        return 64
    out = Path(args.out) if args.out else Path.cwd() / f"{Path(args.study).stem}-study"
    try:
        report = run_study(study, out, scheduler=args.scheduler, workers=args.workers,
                           binary=args.binary, progress=False if args.no_progress else None,
                           plot=not args.no_plot, processes=not args.threads,
                           in_process=args.in_process)
    except (FileNotFoundError, ConnectionError, ValueError) as e:
        print(f"openmss study: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        done = len(list((out / "variants").glob("v*/result.json")))
        print(f"openmss study: interrupted; {done} variant result(s) are stored in {out}; "
              "run the same command again to run the rest", file=sys.stderr)
        return 130
    counts = ", ".join(f"{n} {s}" for s, n in sorted(report.statuses.items()))
    print(f"{study.name}: {report.variants} variants ({report.ran} run, {report.reused} "
          f"already done): {counts}")
    print(f"  table: {report.table}")
    if report.plot:
        print(f"  main effects: {report.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
