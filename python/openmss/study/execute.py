"""Running a study on Dask: a LocalCluster on this machine, or a running scheduler.

Each missing variant is one task (runner.run_variant). The client stores each result the
moment its task finishes (store.py), so a study interrupted at any point (the client
stopped, a worker killed: Dask runs the lost task again elsewhere) keeps every finished
variant, and running it again runs only the rest. The table and the plot are made from the
stored results once all variants have one.
"""

from __future__ import annotations

import contextlib
import logging
import os
import sys
from dataclasses import dataclass
from pathlib import Path

from .._core import binary as default_binary
from .design import variants as make_variants
from .plot import main_effects
from .runner import run_variant, worker_ready
from .spec import Study
from .store import TABLE, load_result, save_result, study_key, table_text, variant_dir, \
    variant_key


@dataclass
class Report:
    table: Path
    plot: Path | None
    variants: int
    reused: int  # results found on disk from an earlier run
    ran: int
    statuses: dict  # status -> count


# Dask's housekeeping, which serves its dashboard and diagnostics (this cluster has no
# dashboard): a statistical profiler sampling each worker's stack every 10 ms, an event-loop
# tick every 20 ms, a system monitor every 0.5 s, the nanny's memory check every 0.1 s. On a
# two-core machine the defaults cost an idle LocalCluster of two worker processes about 17 %
# of one core (measured: 72 ms/s in this process, 100 ms/s in the workers), CPU the solver
# runs of a study want; with these settings about 4 % (27 and 14 ms/s). Given to the worker
# processes by their nannies; a cluster reached with --scheduler keeps its own settings.
QUIET = {"distributed.worker.profile.enabled": False,
         "distributed.admin.tick.interval": "1s",
         "distributed.admin.system-monitor.interval": "2s",
         "distributed.worker.memory.monitor-interval": "1s"}


def local_cluster(workers: int | None = None, processes: bool = True):
    """A LocalCluster on this machine and its client: ``workers`` workers (default: the CPU
    count) of one thread each. ``processes``: each worker a process of its own (started by
    Dask's nanny with the spawn method, so nothing of this process is inherited), so that
    the Python part of each variant (starting the solver, reading its request file, the
    task's round trip) runs in parallel; thread workers share this process and its GIL, but
    start in a fraction of a second (docs/studies.md, "Workers")."""
    import dask
    from distributed import Client, LocalCluster

    with dask.config.set({"distributed.worker.multiprocessing-method": "spawn", **QUIET}):
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                               processes=processes, dashboard_address=None,
                               silence_logs=logging.ERROR)
        return Client(cluster), cluster


def warm(client) -> int:
    """Imports the task's module on every worker of ``client`` (a benchmark times the study
    apart from that one-off cost); the number of workers."""
    return len(client.run(worker_ready))


def _client(scheduler: str | None, workers: int | None, processes: bool):
    from distributed import Client

    if scheduler:
        try:
            return Client(scheduler, timeout="20s"), None
        except (OSError, TimeoutError) as e:
            raise ConnectionError(f"cannot connect to the Dask scheduler {scheduler}: {e}") \
                from None
    return local_cluster(workers, processes)


def run_study(study: Study, out: Path, scheduler: str | None = None, workers: int | None = None,
              binary: str | None = None, progress: bool | None = None,
              plot: bool = True, processes: bool = True, client=None,
              in_process: bool = False) -> Report:
    """Runs the variants of ``study`` that ``out`` holds no result for and writes the table
    (and the plot). The cluster: ``client`` when given (a distributed.Client the caller
    owns and closes), else the scheduler at ``scheduler``, else a LocalCluster of
    ``workers`` workers, processes or threads (local_cluster) started and closed here.
    ``in_process``: each variant's solver run by the extension inside its worker instead of
    the program as a child process (no start-up per variant; no timeout)."""
    out = Path(out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    binary = str(Path(binary).resolve()) if binary else default_binary()
    if in_process and study.timeout is not None:
        raise ValueError(f"{study.path}: timeout: a variant run in the worker's process cannot "
                         "be stopped; remove the timeout or run the solver as a child process "
                         "(without --in-process)")
    if not in_process and not Path(binary).is_file():
        raise FileNotFoundError(f"the openmss program {binary} does not exist: build the "
                                "project (scripts/build.sh), set OPENMSS_BINARY or use --binary")
    variants = make_variants(study)
    base = study_key(study)
    keys = {v.index: variant_key(base, v) for v in variants}
    results = {}
    for v in variants:
        stored = load_result(out, v, keys[v.index])
        if stored is not None:
            results[v.index] = stored
    missing = [v for v in variants if v.index not in results]
    reused = len(results)
    if missing:
        _run_missing(study, out, binary, missing, keys, results, progress, reused,
                     len(variants), client or (scheduler, workers, processes), in_process)
    with contextlib.suppress(OSError):
        (out / "variants" / ".work").rmdir()  # the tasks' scratch folders, when all are gone
    table = out / TABLE
    tmp = out / (TABLE + ".tmp")
    tmp.write_text(table_text(study, variants, results))
    os.replace(tmp, table)
    png = out / "main_effects.png"
    drawn = plot and main_effects(study, variants, results, png)
    statuses: dict = {}
    for r in results.values():
        statuses[r["status"]] = statuses.get(r["status"], 0) + 1
    return Report(table, png if drawn else None, len(variants), reused, len(missing), statuses)


def _run_missing(study, out, binary, missing, keys, results, progress, reused, total, where,
                 in_process):
    from distributed import as_completed
    from tqdm import tqdm

    tasks = {v.index: {"index": v.index, "binary": binary, "model": str(study.model),
                       "run": study.run, "overrides": list(v.overrides),
                       "outdir": str(variant_dir(out, v.index)), "outputs": study.outputs,
                       "timeout": study.timeout, "in_process": in_process} for v in missing}
    by_index = {v.index: v for v in missing}
    owned = isinstance(where, tuple)
    client, cluster = _client(*where) if owned else (where, None)
    try:
        futures = [client.submit(run_variant, tasks[v.index], pure=False,
                                 key=f"openmss-study-{keys[v.index][:16]}-v{v.index:05d}")
                   for v in missing]
        show = sys.stderr.isatty() if progress is None else progress
        with tqdm(total=total, initial=reused, desc=study.name, unit="variant",
                  disable=not show) as bar:
            for future in as_completed(futures):
                index = int(future.key.rsplit("-v", 1)[1])
                try:
                    result = future.result()
                except Exception as e:  # noqa: BLE001 - a task lost by the cluster is recorded
                    result = {"index": index, "status": "task-error", "returncode": None,
                              "message": f"{type(e).__name__}: {e}", "outputs": {},
                              "seconds": 0.0}
                save_result(out, by_index[index], keys[index], result)
                results[index] = result
                bar.update(1)
    finally:
        if owned:
            client.close()
            if cluster is not None:
                cluster.close()
