"""A LocalCluster of worker processes (the default of `openmss study run`) loses no variant
when one of its worker processes is killed mid-study: Dask's nanny starts a new worker, the
lost task runs again, and the table equals the one of an uninterrupted study with thread
workers, byte for byte. (A killed client and a killed dask-worker of a scheduler/worker
pair: test_study_resume.py.)"""

import os
import signal
import subprocess
import sys
import time

import psutil

from study_support import fourbar_study, rows, run_cli

# As in test_study_resume.py: about 0.3 s a variant, so the study is still running when the
# worker is killed.
SLOW = {"end": 6.0, "dtout": 0.005}


def worker_processes(client_pid):
    """The LocalCluster's worker processes: children of the study's process started by
    multiprocessing's spawn (not its resource tracker, not the solvers they run)."""
    return [p for p in psutil.Process(client_pid).children()
            if "spawn_main" in " ".join(p.cmdline())]


def test_a_killed_worker_process_loses_no_variant(tmp_path):
    study_file = fourbar_study(tmp_path, name="slow", model="fourbar.adm", run=SLOW)
    reference = tmp_path / "threads"
    r = run_cli(["run", study_file, "--workers", "2", "--threads", "--out", reference,
                 "--no-progress", "--no-plot"], timeout=240)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "processes"
    client = subprocess.Popen([sys.executable, "-m", "openmss.study", "run", str(study_file),
                               "--workers", "2", "--out", str(out), "--no-progress",
                               "--no-plot"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True, env=os.environ.copy())
    try:
        deadline = time.monotonic() + 120
        while len(list((out / "variants").glob("v*/result.json"))) < 3:
            assert client.poll() is None, client.communicate()
            assert time.monotonic() < deadline, "fewer than 3 results after 120 s"
            time.sleep(0.05)
        workers = worker_processes(client.pid)
        assert len(workers) == 2, [p.cmdline() for p in workers]
        os.kill(workers[0].pid, signal.SIGKILL)
        stdout, stderr = client.communicate(timeout=240)
    finally:
        if client.poll() is None:
            client.kill()
            client.communicate()
    assert client.returncode == 0, stderr
    assert "20 variants (20 run, 0 already done): 5 failed, 15 ok" in stdout
    table = (out / "results.csv").read_text()
    assert table == (reference / "results.csv").read_text()
    assert len(rows(table)) == 20
