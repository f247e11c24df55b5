"""A design study on a real Dask cluster: a dask-scheduler and two dask-worker processes on
127.0.0.1 run the 20 variants of the four-bar study; the table is byte-for-byte the one made
by running the same variants one by one with `openmss run --set` (and reading their request
files here, without the study package), and the one a LocalCluster gives. The five variants
whose ground pivot breaks Grashof's condition lock up and are recorded with the .msg
diagnosis; the others still run."""

import csv
import io
import math
import subprocess

import numpy as np

import openmss
from openmss.study import load_study, variants

from study_support import Cluster, binary, fourbar_study, rows, run_cli


def one_by_one(study_file, tmp):
    """The reference table: each variant run by the command-line program in turn, its
    outputs computed here from openmss.read_req with NumPy, formatted as documented
    (docs/studies.md: ten significant digits)."""
    study = load_study(study_file)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["variant", "PART/3.MASS", "MARKER/11.QP", "torque_max", "torque_min",
                "pin_x_1s", "force_o_final", "torque_range", "status", "message"])
    for v in variants(study):
        d = tmp / f"v{v.index}"
        d.mkdir()
        cmd = [binary(), "run", str(study.model), "--outdir", str(d), "--quiet"]
        for o in v.overrides:
            cmd += ["--set", o]
        code = subprocess.run(cmd, capture_output=True).returncode
        cells = [""] * 5
        message = ""
        if code == 0:
            rf = openmss.read_req(d / "fourbar.req")
            torque = rf.requests[6]["U2"].to_numpy()  # F2 of the expression request
            force = rf.requests[4][["FX", "FY", "FZ"]].to_numpy()
            k = int(np.flatnonzero(rf.times == 1.0)[0])  # 1.0 is an output time (DTOUT 0.01)
            values = [torque.max(), torque.min(), rf.requests[1]["X"].to_numpy()[k],
                      math.sqrt((force[-1] ** 2).sum())]
            values.append(values[0] - values[1])
            cells = [format(float(x), ".10g") for x in values]
        else:
            errors = [ln.strip() for ln in (d / "fourbar.msg").read_text().splitlines()
                      if "error:" in ln]
            message = " | ".join(dict.fromkeys(errors))
        status = {0: "ok", 2: "failed"}[code]
        w.writerow([v.index, v.values[0], v.values[1]] + cells + [status, message])
    return buf.getvalue()


def test_cluster_table_is_the_one_by_one_table(tmp_path):
    study_file = fourbar_study(tmp_path)
    with Cluster(tmp_path) as cluster:
        r = run_cli(["run", study_file, "--scheduler", cluster.address, "--out",
                     tmp_path / "cluster", "--no-progress"], timeout=120)
        assert r.returncode == 0, r.stderr + cluster.log_text()
    assert "20 variants (20 run, 0 already done): 5 failed, 15 ok" in r.stdout
    table = (tmp_path / "cluster" / "results.csv").read_text()
    reference = one_by_one(study_file, tmp_path)
    assert table == reference
    assert len(rows(table)) == 20
    # The locked variants: ground pivot at 0.6 m, each with the kinematic failure's message.
    failed = [row for row in rows(table) if row["status"] == "failed"]
    assert [row["MARKER/11.QP"] for row in failed] == ["0.6"] * 5
    for row in failed:
        assert "error: kinematic analysis failed at time" in row["message"]
        assert "The mechanism may lock up" in row["message"]
        assert row["torque_max"] == ""
    # A LocalCluster (one command, no scheduler) gives the same bytes.
    r = run_cli(["run", study_file, "--workers", "2", "--out", tmp_path / "local",
                 "--no-progress"], timeout=120)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "local" / "results.csv").read_text() == table
