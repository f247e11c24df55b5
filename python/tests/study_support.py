"""Shared pieces of the design-study tests (test_study_*.py): a real Dask scheduler and
workers on 127.0.0.1, study files, and the reference table made without Dask."""

from __future__ import annotations

import contextlib
import csv
import io
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import yaml

from conftest import BINARY, SOURCE_DIR

FOURBAR = SOURCE_DIR / "examples" / "fourbar"


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _dask_command(name: str) -> list[str]:
    """Debian's console scripts (python3-distributed), else the module they run."""
    found = shutil.which(f"dask-{name}")
    if found:
        return [found]
    return [sys.executable, "-m", f"distributed.cli.dask_{name}"]


class Cluster:
    """A dask-scheduler and ``workers`` dask-worker processes (no nanny, one thread each, so
    that killing one process kills one worker). Always torn down: use as a context manager."""

    def __init__(self, tmp: Path, workers: int = 2):
        self.tmp = tmp
        self.port = free_port()
        self.address = f"tcp://127.0.0.1:{self.port}"
        self.logs = []
        self.scheduler = self._start("scheduler", ["--host", "127.0.0.1", "--port",
                                                   str(self.port), "--no-dashboard"])
        self.workers = [self._start(f"worker{k}", [self.address, "--host", "127.0.0.1",
                                                   "--nthreads", "1", "--no-nanny",
                                                   "--no-dashboard", "--local-directory",
                                                   str(tmp / f"worker{k}")], "worker")
                        for k in range(workers)]
        self.wait_for_workers(workers)

    def _start(self, name, args, kind=None):
        log = open(self.tmp / f"{name}.log", "w")
        self.logs.append(log)
        # The workers import openmss.study: the package on PYTHONPATH (CTest sets it).
        return subprocess.Popen(_dask_command(kind or name) + args, stdout=log,
                                stderr=subprocess.STDOUT, env=os.environ.copy(),
                                start_new_session=True)

    def wait_for_workers(self, n, timeout=45.0):
        from distributed import Client

        deadline = time.monotonic() + timeout
        while True:
            try:
                with Client(self.address, timeout="5s") as c:
                    c.wait_for_workers(n, timeout=max(1.0, deadline - time.monotonic()))
                    return
            except (OSError, TimeoutError):
                if time.monotonic() > deadline:
                    raise AssertionError("the Dask cluster did not start: " + self.log_text())
                time.sleep(0.5)

    def log_text(self):
        return "\n".join(p.read_text() for p in sorted(self.tmp.glob("*.log")))

    def kill_worker(self, k=0):
        os.killpg(self.workers[k].pid, signal.SIGKILL)
        self.workers[k].wait()

    def close(self):
        for p in self.workers + [self.scheduler]:
            if p.poll() is None:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(p.pid, signal.SIGTERM)
        for p in self.workers + [self.scheduler]:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()
        for log in self.logs:
            log.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def fourbar_study(tmp: Path, name="fourbar", model="fourbar.acf", run=None) -> Path:
    """20 variants of the four-bar: coupler mass (5 levels) x ground pivot D at x = 0.38,
    0.40, 0.42 or 0.60 m. At 0.60 the links break Grashof's condition (0.1 + 0.6 > 0.35 +
    0.30): the crank cannot turn fully and the mechanism locks, so those 5 variants fail."""
    data = {
        "name": name,
        "model": str(FOURBAR / model),
        "design": "full_factorial",
        "parameters": [
            {"set": "PART/3.MASS", "values": [1.0, 1.5, 2.0, 2.5, 3.0]},
            {"set": "MARKER/11.QP", "values": [0.38, 0.40, 0.42, 0.60], "template": "{value},0,0"},
        ],
        "outputs": [
            {"name": "torque_max", "request": 6, "component": "F2", "stat": "max"},
            {"name": "torque_min", "request": 6, "component": "F2", "stat": "min"},
            {"name": "pin_x_1s", "request": 1, "component": "X", "stat": "at", "time": 1.0},
            {"name": "force_o_final", "request": 4, "component": "FM", "stat": "final"},
            {"name": "torque_range", "expr": "torque_max - torque_min"},
        ],
    }
    if run:
        data["run"] = run
    path = tmp / f"{name}.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def run_cli(args, cwd=None, **kw):
    """`python3 -m openmss.study ARGS` in a child process, as a user runs it."""
    return subprocess.run([sys.executable, "-m", "openmss.study"] + [str(a) for a in args],
                          cwd=cwd, capture_output=True, text=True, env=os.environ.copy(), **kw)


def rows(csv_text: str) -> list[dict]:
    return list(csv.DictReader(io.StringIO(csv_text)))


def binary() -> str:
    return str(BINARY)
