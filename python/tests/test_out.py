"""The tabular output file (.out, docs/output-files.md) read by openmss.read_out against the .req
of the same run (read by openmss.read_req): on the piston example every .req value is the .out
value of the same request, column and time with the same printed digits, so equal exactly, and
the magnitude columns are the norms of their printed components."""

import math
import os

import numpy as np

import openmss
from conftest import PISTON

REQ_TO_OUT = {  # the .req's six columns F2 F3 F4 F6 F7 F8 among the .out's columns (no TIME)
    "DISPLACEMENT": [1, 2, 3, 4, 5, 6],  # no F5 column
    "VELOCITY": [1, 2, 3, 5, 6, 7], "ACCELERATION": [1, 2, 3, 5, 6, 7],
    "FORCE": [1, 2, 3, 5, 6, 7], "EXPRESSIONS": [1, 2, 3, 5, 6, 7],
}


def test_piston_out_holds_the_req_values(tmp_path):
    run = openmss.run_acf(PISTON / "piston.acf", outdir=tmp_path)
    out = openmss.read_out(os.path.join(tmp_path, "piston.out"))
    req = openmss.read_req(run.req, keep="all")  # every record, as the .out holds them
    assert out.status == "Successful"
    # Driven by a motion (zero degrees of freedom): initial conditions, then kinematics.
    assert out.blocks == ["initialConditions_001", "kinematic_001"]
    assert sorted(out.requests) == sorted(e.id for e in req.entries)
    compared = 0
    for k, e in enumerate(req.entries):
        table = out.requests[e.id]
        cols = REQ_TO_OUT[table.attrs["type"]]
        assert len(table) == len(req.values)
        np.testing.assert_array_equal(table.index.to_numpy(), np.asarray(req.times))
        np.testing.assert_array_equal(table.to_numpy()[:, cols], req.values[:, k, :])
        compared += req.values[:, k, :].size
    assert compared == len(req.entries) * 6 * len(req.values)
    # ACCM = |(ACCX, ACCY, ACCZ)|: each printed value within 5e-6 of itself (six digits).
    acc = out.requests[13]
    norm = np.sqrt((acc[["ACCX", "ACCY", "ACCZ"]].to_numpy() ** 2).sum(axis=1))
    assert np.all(np.abs(acc["ACCM"].to_numpy() - norm) <= 1.1e-5 * norm + 1e-300)
    assert acc.attrs["units"]["ACCX"] == "in/s**2"
    assert not math.isnan(norm.max()) and norm.max() > 1.0
