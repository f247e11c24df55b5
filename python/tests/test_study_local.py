"""A design study on a LocalCluster: an undamped oscillator whose outputs have a closed form,
the same table for two worker processes and one thread worker, and a rerun that runs only
the missing variants."""

import math

import numpy as np
import pytest
import yaml

from openmss.study import load_study, run_study

from study_support import binary, rows, run_cli

# A mass on a spring along global X, released at rest from x = 1 (spring length 0.8), no
# damping and no gravity along the slide: x(t) = 0.8 + 0.2 cos(sqrt(K/m) t).
OSCILLATOR = """undamped oscillator
PART/1, GROUND
MARKER/10, PART=1, REULER=90D,90D,0
PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1
MARKER/20, PART=2, QP=1,0,0, REULER=90D,90D,0
JOINT/1, TRANSLATIONAL, I=20, J=10
SPRINGDAMPER/3, TRANSLATIONAL, I=20, J=10, K=100, C=0, LENGTH=0.8
INTEGRATOR/GSTIFF, ERROR=1E-7
REQUEST/1, DISPLACEMENT, I=20, J=10
OUTPUT/REQSAVE
END
"""
STEPS = 200  # output times k/200, k = 0..200
# Integration error (ERROR=1E-7 per step, about 10^3 steps) plus the request file's six
# significant digits (5E-7 on values near 1): observed 1.3E-6 for K/m = 50.
TOL = 1e-5


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("osc")
    (tmp / "osc.adm").write_text(OSCILLATOR)
    (tmp / "osc.yaml").write_text(yaml.safe_dump({
        "name": "oscillator", "model": "osc.adm", "run": {"end": 1.0, "steps": STEPS},
        "parameters": [{"set": "SPRINGDAMPER/3.K", "values": [50, 100.0, 200]},
                       {"set": "PART/2.MASS", "range": {"start": 1, "stop": 2, "num": 2}}],
        "outputs": [{"name": "xmin", "request": 1, "component": "X", "stat": "min"},
                    {"name": "xmax", "request": 1, "component": "X", "stat": "max"},
                    {"name": "x_at", "request": 1, "component": "X", "stat": "at", "time": 0.3},
                    {"name": "x_end", "request": 1, "component": "X", "stat": "final"},
                    {"name": "half_range", "expr": "(xmax - xmin) / 2"}]}))
    out = tmp / "two"
    report = run_study(load_study(tmp / "osc.yaml"), out, workers=2, binary=binary(),
                       progress=False)
    return tmp, out, report


def test_outputs_match_the_closed_form(study):
    tmp, out, report = study
    assert (report.variants, report.ran, report.reused) == (6, 6, 0)
    assert report.statuses == {"ok": 6}
    table = rows((out / "results.csv").read_text())
    t = np.arange(STEPS + 1) / STEPS
    compared = 0
    for row in table:
        w = math.sqrt(float(row["SPRINGDAMPER/3.K"]) / float(row["PART/2.MASS"]))
        x = 0.8 + 0.2 * np.cos(w * t)  # sampled at the output times, as the study reduces
        expected = {"xmin": x.min(), "xmax": x.max(), "x_at": 0.8 + 0.2 * math.cos(w * 0.3),
                    "x_end": x[-1], "half_range": (x.max() - x.min()) / 2}
        for name, value in expected.items():
            assert float(row[name]) == pytest.approx(value, abs=TOL), (row, name)
            compared += 1
        assert row["status"] == "ok" and row["message"] == ""
    assert compared == 6 * 5
    # Parameters appear as set: integers as integers, floats in their shortest form.
    assert [r["SPRINGDAMPER/3.K"] for r in table] == ["50", "50", "100.0", "100.0", "200", "200"]
    assert [r["PART/2.MASS"] for r in table] == ["1.0", "2.0"] * 3
    assert report.plot is not None and report.plot.stat().st_size > 10_000


def test_one_worker_gives_the_same_table_and_a_rerun_runs_only_what_is_missing(study):
    tmp, out, _ = study
    reference = (out / "results.csv").read_bytes()
    # One worker, a thread of the study's process (--threads), from the command line:
    # byte-for-byte the same table as two worker processes.
    one = tmp / "one"
    r = run_cli(["run", tmp / "osc.yaml", "--workers", "1", "--threads", "--out", one,
                 "--no-progress"])
    assert r.returncode == 0, r.stderr
    assert "6 variants (6 run, 0 already done): 6 ok" in r.stdout
    assert (one / "results.csv").read_bytes() == reference
    # Two results lost (as when a study is interrupted): the rerun runs those two only.
    results = sorted((out / "variants").glob("v*/result.json"))
    assert len(results) == 6
    before = {p: p.stat().st_mtime_ns for p in results}
    msg_before = {p: p.stat().st_mtime_ns for p in (out / "variants").glob("v*/osc.msg")}
    assert len(msg_before) == 6
    for p in results[1:3]:
        p.unlink()
    r = run_cli(["run", tmp / "osc.yaml", "--out", out, "--no-progress", "--workers", "2"])
    assert r.returncode == 0, r.stderr
    assert "6 variants (2 run, 4 already done): 6 ok" in r.stdout
    kept = [p for p in results if p not in results[1:3]]
    assert all(p.stat().st_mtime_ns == before[p] for p in kept)
    assert all(p.stat().st_mtime_ns == msg_before[p] for p in msg_before
               if p.parent / "result.json" in kept)
    assert all(p.exists() for p in results)
    assert (out / "results.csv").read_bytes() == reference
    # Nothing left to run: no cluster is started, the table is written again unchanged.
    r = run_cli(["run", tmp / "osc.yaml", "--out", out, "--no-progress"])
    assert "(0 run, 6 already done)" in r.stdout
    assert (out / "results.csv").read_bytes() == reference
