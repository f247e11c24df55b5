"""The study's request reader (openmss/study/requests.py) against read_req: the same times
and the same doubles (tolerance 0: both convert the same decimal text) for every request of
the ADAMS joint cases' request files and of our piston's, for all requests and for a subset;
and a file cut short is an error as it is for read_req."""

import numpy as np
import pytest

import openmss
from openmss.study.requests import read_requests

from conftest import adams_req_files


def _compare(path, ids=None):
    """The requests of ``ids`` (all when None) read both ways; the count of values compared."""
    full = openmss.read_req(path)
    wanted = [e.id for e in full.entries] if ids is None else ids
    times, requests = read_requests(path, set(wanted) | {999_999})  # an id the file lacks
    assert np.array_equal(times, full.times)
    assert sorted(requests) == sorted(wanted)
    compared = 0
    for k, e in enumerate(full.entries):
        if e.id in requests:
            kind, rows = requests[e.id]
            assert kind == e.kind
            assert np.array_equal(rows, full.values[:, k, :]), (path, e.id)
            compared += rows.size
    return compared


def test_adams_request_files_read_as_read_req_reads_them():
    files = adams_req_files()
    assert len(files) == 6, files
    assert sum(_compare(p) for p in files) > 6 * 100 * 6  # each file: several requests


def test_piston_requests_all_and_a_subset(piston_run):
    assert _compare(piston_run.req) == 201 * 8 * 6
    assert _compare(piston_run.req, [8, 14]) == 201 * 2 * 6


def test_records_at_one_time_keep_the_last_and_a_cut_file_is_refused(tmp_path):
    record = " " + "".join(f"{v:13.5E}" for v in range(6))
    later = " " + "".join(f"{v + 10:13.5E}" for v in range(6))
    head = (" A.R3    2000-01-01 00:00:00               0         0  3D\ntitle\n"
            "    2     M_KGS_N_RACA 1.000000000000000E+00\n"
            "          1             1             2             1             0\n\n"
            "          2             2             2             1             0\n\n")
    p = tmp_path / "twice.req"
    p.write_text(head + f"   0.00000E+00\n{record}\n{record}\n   0.00000E+00\n{later}\n"
                 f"{record}\n   1.00000E-01\n{record}\n{later}\n")
    times, requests = read_requests(p, {2})
    assert times.tolist() == [0.0, 0.1] and list(requests) == [2]
    assert requests[2][1].tolist() == [[0, 1, 2, 3, 4, 5], [10, 11, 12, 13, 14, 15]]
    assert _compare(p) == 2 * 2 * 6
    p.write_text(head + f"   0.00000E+00\n{record}\n")  # REQUEST/2's record missing
    with pytest.raises(openmss.RequestFileError,
                       match=":10: output step at time .* cut short: no record for REQUEST/2"):
        read_requests(p, {1})
