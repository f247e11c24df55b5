"""Interrupting a design study loses no finished variant. On a real dask-scheduler with two
dask-worker processes: the client is killed mid-study and the study run again runs only the
variants without a result (the finished ones' files are untouched); a worker is killed
mid-study and Dask runs its task on the other; both give the same table, byte for byte."""

import os
import signal
import subprocess
import sys
import time

from study_support import Cluster, fourbar_study, rows, run_cli

# The four-bar over 6 s with DTOUT 0.005: about 0.3 s a variant, so that the study
# is still running when it is interrupted (after 2 or 3 of 20 variants).
SLOW = {"end": 6.0, "dtout": 0.005}


def start_client(study_file, address, out):
    return subprocess.Popen([sys.executable, "-m", "openmss.study", "run", str(study_file),
                             "--scheduler", address, "--out", str(out), "--no-progress",
                             "--no-plot"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=os.environ.copy())


def wait_for_results(out, count, client, timeout=60.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        done = sorted((out / "variants").glob("v*/result.json"))
        if len(done) >= count:
            return done
        assert client.poll() is None, client.communicate()
        time.sleep(0.05)
    raise AssertionError(f"fewer than {count} results after {timeout} s")


def test_an_interrupted_study_resumes_and_a_killed_worker_loses_nothing(tmp_path):
    study_file = fourbar_study(tmp_path, name="slow", model="fourbar.adm", run=SLOW)
    with Cluster(tmp_path) as cluster:
        # The client killed (as by a lost connection or kill -9) after two results.
        out = tmp_path / "interrupted"
        client = start_client(study_file, cluster.address, out)
        wait_for_results(out, 2, client)
        client.send_signal(signal.SIGKILL)
        client.communicate()
        done = sorted((out / "variants").glob("v*/result.json"))
        assert 2 <= len(done) < 20, len(done)
        stamps = {p: p.stat().st_mtime_ns for p in done}
        stamps.update({m: m.stat().st_mtime_ns for p in done for m in p.parent.glob("*.msg")})
        assert len(stamps) == 2 * len(done)  # each finished variant: result.json and its .msg
        r = run_cli(["run", study_file, "--scheduler", cluster.address, "--out", out,
                     "--no-progress"], timeout=120)
        assert r.returncode == 0, r.stderr + cluster.log_text()
        assert f"20 variants ({20 - len(done)} run, {len(done)} already done)" in r.stdout
        assert {p: p.stat().st_mtime_ns for p in stamps} == stamps  # not run again
        resumed = (out / "results.csv").read_text()

        # A worker killed (with the solver it runs) after three results: the study completes
        # on the other worker, and every variant has its true result, none a lost task.
        out = tmp_path / "worker-killed"
        client = start_client(study_file, cluster.address, out)
        wait_for_results(out, 3, client)
        cluster.kill_worker(0)
        stdout, stderr = client.communicate(timeout=120)
        assert client.returncode == 0, stderr + cluster.log_text()
        assert "20 variants (20 run, 0 already done): 5 failed, 15 ok" in stdout
        assert (out / "results.csv").read_text() == resumed
    table = rows(resumed)
    assert len(table) == 20
    assert [r["status"] for r in table].count("ok") == 15
