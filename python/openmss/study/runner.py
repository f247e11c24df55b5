"""One variant: the C++ solver run in a folder of its own (as a child process, or by the
extension in the worker's process: docs/studies.md), its request file read and its outputs
computed. Runs inside a Dask task (on any worker), so it takes and
returns plain data and never raises: every failure becomes the variant's status and message.
"""

from __future__ import annotations

import os
import resource
import shutil
import subprocess
import time
import uuid
from pathlib import Path

from .outputs import OutputError, compute
from .requests import read_requests
from ..req import RequestFileError

# Exit statuses of `openmss run` (README, "Using it").
STATUS = {0: "ok", 1: "input-error", 2: "failed"}


def command(binary: str, model: str, run: dict, overrides, outdir: str) -> list[str]:
    cmd = [binary, "run", model, "--outdir", outdir, "--quiet"]
    for key in ("end", "steps", "dtout"):
        if key in run:
            cmd += [f"--{key}", repr(run[key]) if isinstance(run[key], float) else str(run[key])]
    for o in overrides:
        cmd += ["--set", o]
    return cmd


def diagnosis(outdir: Path, stderr: str) -> str:
    """The errors of the run as the .msg (or, without one, stderr) states them, one line each,
    joined by ' | ': what the table's message column shows for a failed variant."""
    lines = []
    for msg in sorted(outdir.glob("*.msg")):
        lines += [ln.strip() for ln in msg.read_text(errors="replace").splitlines()
                  if "error:" in ln]
    if not lines:
        lines = [ln.strip() for ln in stderr.splitlines() if ln.strip()][-3:]
    return " | ".join(dict.fromkeys(lines))  # each once, in order


def worker_ready() -> int:
    """Run on each worker by execute.warm: importing this module is the worker's set-up."""
    return os.getpid()


def cpu_seconds() -> tuple[float, float]:
    """CPU time (user + system) of this process and of its finished children (the solver
    runs), for bench/study_throughput.py's account of where a study's time goes."""
    me = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime, kids.ru_utime + kids.ru_stime


def run_variant(task: dict) -> dict:
    """``task``: index, binary, model, run, overrides, outdir, outputs (spec.Output list),
    timeout, in_process (the solver run by the extension in this process instead of the
    program as a child process). Returns index, status, returncode, message, outputs
    (name -> float), seconds."""
    start = time.monotonic()
    final = Path(task["outdir"])
    # The solver writes into a folder of this attempt, moved into place when it is done: a
    # task still running for a study that was interrupted cannot mix its files with those of
    # the rerun (both write the same, deterministic, files; the last move wins).
    outdir = final.parent / ".work" / f"{final.name}-{uuid.uuid4().hex[:12]}"
    outdir.mkdir(parents=True)
    try:
        result = _run(task, outdir)
        final.mkdir(parents=True, exist_ok=True)
        for old in list(final.glob("*.req")) + list(final.glob("*.msg")):
            old.unlink(missing_ok=True)
        for made in sorted(outdir.iterdir()):
            os.replace(made, final / made.name)
    finally:
        shutil.rmtree(outdir, ignore_errors=True)
    result["seconds"] = time.monotonic() - start
    return result


def _solve_in_process(task: dict, outdir: Path) -> tuple[int, str]:
    """The variant run by the extension in this worker (docs/studies.md, "In-process
    solver"): the exit status and standard-error text `openmss run` would give."""
    from .._core import _extension

    if _extension is None:
        raise OSError("the extension openmss._native was not built "
                      "(cmake -DOPENMSS_PYTHON_EXTENSION=ON)")
    run = task["run"]
    return _extension.run_variant(task["model"], str(outdir), list(task["overrides"]),
                                  float(run.get("end", 1.0)), int(run.get("steps", 100)),
                                  float(run.get("dtout", 0.0)))


def _solve(task: dict, outdir: Path) -> tuple[int, str]:
    """(exit status, stderr) of `openmss run` on the variant; raises TimeoutExpired, OSError."""
    if task.get("in_process"):
        return _solve_in_process(task, outdir)
    cmd = command(task["binary"], task["model"], task["run"], task["overrides"], str(outdir))
    proc = subprocess.run(cmd, cwd=outdir, capture_output=True, text=True,
                          timeout=task.get("timeout"), env={**os.environ, "LC_ALL": "C"})
    return proc.returncode, proc.stderr


def _run(task: dict, outdir: Path) -> dict:
    result = {"index": task["index"], "status": "", "returncode": None, "message": "",
              "outputs": {}, "seconds": 0.0}
    try:
        returncode, stderr = _solve(task, outdir)
    except subprocess.TimeoutExpired:
        result.update(status="timeout", message=f"no result after {task['timeout']:g} s")
    except (OSError, RuntimeError) as e:  # RuntimeError: a C++ exception of the extension
        what = "the in-process solver" if task.get("in_process") else task["binary"]
        result.update(status="crashed", message=f"cannot run {what}: "
                      f"{getattr(e, 'strerror', None) or e}")
    else:
        result["returncode"] = returncode
        result["status"] = STATUS.get(returncode, "crashed")
        if returncode != 0:
            result["message"] = diagnosis(outdir, stderr) or f"exit status {returncode}"
        else:
            try:
                reqs = sorted(outdir.glob("*.req"))
                if len(reqs) != 1:
                    raise OutputError(f"expected one request file in {outdir}, found {len(reqs)}"
                                      " (the model needs OUTPUT/REQSAVE)")
                # Only the requests the outputs read (requests.py: a fraction of read_req's
                # cost, which on a short run was that of the solver).
                ids = {o.request for o in task["outputs"] if o.expr is None}
                times, requests = read_requests(reqs[0], ids)
                result["outputs"] = compute(task["outputs"], times, requests)
            except (OutputError, RequestFileError, OSError, ValueError) as e:
                result.update(status="output-error", message=str(e))
    return result
