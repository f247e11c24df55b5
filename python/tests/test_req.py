"""read_req against the C++ reader (src/output/request_file_reader.cpp, through `openmss api
read-req`) on every request file ADAMS wrote for the joint cases and on our piston's, value
by value; and its diagnostics on malformed files."""

import numpy as np
import pytest

import openmss
from conftest import adams_req_files


def _compare_with_cpp(path):
    """Every record, every value: the Python reader keeping every record (keep="all") against
    the C++ reader. Both parse the same decimal text with correctly rounded conversions, so the
    doubles must be identical (tolerance 0). Returns the count of values compared."""
    py = openmss.read_req(path, keep="all")
    cpp = openmss._core.read_request_file_cpp(str(path))
    assert [e.id for e in py.entries] == cpp["ids"]
    assert [e.type for e in py.entries] == cpp["types"]
    steps = np.array(cpp["steps"], dtype=float)
    assert steps.shape == (len(py.times), 1 + 6 * len(py.entries))
    assert np.array_equal(py.times, steps[:, 0])
    assert np.array_equal(py.values.reshape(len(py.times), -1), steps[:, 1:])
    return steps.size


def test_the_adams_request_files_read_as_the_cpp_reader_reads_them():
    files = adams_req_files()
    # Revolute, Spherical, Universal cases 1 and 2 (Prismatic and Cylindrical have tables only).
    assert len(files) == 6, files
    compared = sum(_compare_with_cpp(p) for p in files)
    # 6 files x 501 records x (1 time + 5 requests x 6 values).
    assert compared == 6 * 501 * 31


def test_our_piston_request_file_reads_as_the_cpp_reader_reads_it(piston_run):
    # 8 requests at t = 0, 0.01, ..., 2 (the .acf's END=2.0, DTOUT=0.01): 201 records.
    assert _compare_with_cpp(piston_run.req) == 201 * (1 + 8 * 6)


def test_records_at_one_time_keep_the_last_by_default(tmp_path):
    # A run with an initial-conditions analysis writes t = 0 twice (docs/output-files.md).
    record = " " + "".join(f"{v:13.5E}" for v in range(6))
    later = " " + "".join(f"{v + 10:13.5E}" for v in range(6))
    p = tmp_path / "twice.req"
    p.write_text(" A.R3    2000-01-01 00:00:00               0         0  3D\ntitle\n"
                 "    1     M_KGS_N_RACA 1.000000000000000E+00\n"
                 "          1             1             2             1             0\n\n"
                 f"   0.00000E+00\n{record}\n   0.00000E+00\n{later}\n"
                 f"   1.00000E-01\n{record}\n")
    every = openmss.read_req(p, keep="all")
    last = openmss.read_req(p)
    assert every.times.tolist() == [0.0, 0.0, 0.1] and last.times.tolist() == [0.0, 0.1]
    assert last.requests[1].iloc[0].tolist() == [10, 11, 12, 13, 14, 15]
    assert last.requests[1].iloc[1].tolist() == [0, 1, 2, 3, 4, 5]
    assert _compare_with_cpp(p) == 3 * 7


def test_frames_carry_adams_names_units_and_comments():
    f = openmss.read_req(adams_req_files()[0])  # Revolute_Case01
    assert f.title == "ADAMS/View model name: test_Revolute_Case01"
    assert f.units == "M_KGS_N_RACA" and f.length_scale == 1.0
    d = f.requests[1]
    assert list(d.columns) == ["X", "Y", "Z", "PSI", "THETA", "PHI"]
    assert d.attrs["units"] == {"X": "m", "Y": "m", "Z": "m", "PSI": "deg", "THETA": "deg",
                                "PHI": "deg"}
    assert list(f.requests[2].columns) == ["VX", "VY", "VZ", "WX", "WY", "WZ"]
    assert f.unit(2, "VX") == "m/s" and f.unit(2, "WZ") == "rad/s"
    assert list(f.requests[3].columns) == ["ACCX", "ACCY", "ACCZ", "WDTX", "WDTY", "WDTZ"]
    assert list(f.requests[5].columns) == ["U2", "U3", "U4", "U6", "U7", "U8"]
    assert f.entry(5).comment == "RForce X Y Z RTorque X Y Z"
    # Values as printed: the first record of REQUEST/1 is "2.00000E+00 ... 1.80000E+02 ...".
    assert d.index[0] == 0.0 and d.iloc[0].tolist() == [2.0, 0.0, 0.0, 180.0, 90.0, 180.0]


@pytest.mark.parametrize("text, message", [
    ("nothing\n", ":1: not a request file"),
    (" A.R3    2000-01-01 00:00:00\ntitle\n    1     M_KGS_N_RACA 1.0E+00\n"
     "          1             1           201           101             0\n\n"
     "   0.00000E+00\n", "cut short: no record for REQUEST/1"),
    (" A.R3    2000-01-01 00:00:00\ntitle\n    0     M_KGS_N_RACA 1.0E+00\n"
     "   0.00000E+00  1.0\n", ":4: expected a time record"),
])
def test_malformed_files_are_named_with_their_line(tmp_path, text, message):
    p = tmp_path / "bad.req"
    p.write_text(text)
    with pytest.raises(openmss.RequestFileError, match=message):
        openmss.read_req(p)
