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
from .runner import run_variant
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


def _client(scheduler: str | None, workers: int | None):
    from distributed import Client, LocalCluster

    if scheduler:
        try:
            return Client(scheduler, timeout="20s"), None
        except (OSError, TimeoutError) as e:
            raise ConnectionError(f"cannot connect to the Dask scheduler {scheduler}: {e}") \
                from None
    # Each task runs the solver as a subprocess and its worker thread only waits for it (the
    # GIL is released), so the workers are threads of this process: one solver per worker,
    # without the seconds that starting worker processes takes.
    cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                           processes=False, dashboard_address=None, silence_logs=logging.ERROR)
    return Client(cluster), cluster


def run_study(study: Study, out: Path, scheduler: str | None = None, workers: int | None = None,
              binary: str | None = None, progress: bool | None = None,
              plot: bool = True) -> Report:
    out = Path(out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    binary = str(Path(binary).resolve()) if binary else default_binary()
    if not Path(binary).is_file():
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
        _run_missing(study, out, binary, missing, keys, results, scheduler, workers, progress,
                     reused, len(variants))
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


def _run_missing(study, out, binary, missing, keys, results, scheduler, workers, progress,
                 reused, total):
    from distributed import as_completed
    from tqdm import tqdm

    tasks = {v.index: {"index": v.index, "binary": binary, "model": str(study.model),
                       "run": study.run, "overrides": list(v.overrides),
                       "outdir": str(variant_dir(out, v.index)), "outputs": study.outputs,
                       "timeout": study.timeout} for v in missing}
    by_index = {v.index: v for v in missing}
    client, cluster = _client(scheduler, workers)
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
        client.close()
        if cluster is not None:
            cluster.close()
