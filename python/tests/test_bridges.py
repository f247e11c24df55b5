"""The two bridges to the solver (python/openmss/_core.py, docs/python.md) give the same
answers: the pybind11 extension in this process and `openmss api` in a child process. Every
other test file uses the default (the extension); this one checks that it is the extension and
that the child process agrees with it value for value and byte for byte."""

import filecmp

import pytest

import openmss
from openmss import _core
from conftest import JOINTS, PISTON


@pytest.fixture
def bridge(monkeypatch):
    def use(name):
        monkeypatch.setenv("OPENMSS_BRIDGE", name)
        assert _core.bridge() == name
    return use


def test_the_default_bridge_is_the_extension(monkeypatch):
    monkeypatch.delenv("OPENMSS_BRIDGE", raising=False)
    assert _core._extension is not None, "openmss._native was not built"
    assert _core.bridge() == "native"


def test_an_unknown_bridge_is_refused(bridge, monkeypatch):
    monkeypatch.setenv("OPENMSS_BRIDGE", "shared-memory")
    with pytest.raises(RuntimeError, match="use native or process"):
        _core.bridge()


def test_both_bridges_load_the_same_model(bridge):
    bridge("native")
    native = _core.load_model(str(PISTON / "piston.adm"))
    bridge("process")
    process = _core.load_model(str(PISTON / "piston.adm"))
    assert native == process
    assert native["dof"] == 0 and len(native["parts"]) == 4 and len(native["requests"]) == 8


def test_both_bridges_report_the_same_input_errors(bridge, tmp_path):
    bad = tmp_path / "bad.adm"
    bad.write_text("bad\nPART/1, GROUND\nPART/2, MASS=1, CM=99, IP=1,1,1\nEND\n")
    bridge("native")
    native = _core.load_model(str(bad))
    bridge("process")
    process = _core.load_model(str(bad))
    assert not native["ok"] and native == process
    assert [d["line"] for d in native["diagnostics"] if d["severity"] == "error"] == [3]


def test_both_bridges_write_identical_outputs(bridge, tmp_path):
    # The ADAMS revolute pendulum, 1 s: the .req and .res of the two bridges are the same bytes
    # (the solver is deterministic, docs/architecture.md), and the run summaries agree.
    adm = str(JOINTS / "Revolute_Case01" / "test_Revolute_Case01.adm")
    runs = {}
    for name in ("native", "process"):
        bridge(name)
        out = tmp_path / name
        runs[name] = _core.simulate(adm, str(out), 1.0, 0.01, 0, "GSTIFF", 1e-6, "pendulum")
        assert runs[name]["status"] == "completed", runs[name]["diagnostics"]
    a, b = runs["native"], runs["process"]
    assert a["steps"] == b["steps"] > 0 and a["output_steps"] == b["output_steps"] >= 101
    assert a["time"] == b["time"] == 1.0
    for key in ("req", "res"):
        if a[key] or b[key]:
            assert filecmp.cmp(a[key], b[key], shallow=False), key
    assert a["req"], "the simulate call writes the request file"
