"""read_res on a results file in ADAMS's XRF layout (data/free_fall.res, made by
data/make_free_fall.py) against the closed form of free fall, and on malformed files."""

import pathlib

import numpy as np
import pytest

import openmss

DATA = pathlib.Path(__file__).parent / "data"
G = 9.80665 / 0.0254  # in/s^2


@pytest.fixture(scope="module")
def free_fall():
    return openmss.read_res(DATA / "free_fall.res")


def test_header_entities_and_steps(free_fall):
    f = free_fall
    assert f.title == "free fall of one part, inch and pound-mass"
    assert f.units == {"angle": "rad", "length": "inch", "mass": "pound_mass", "time": "sec"}
    assert f.status == "Successful"
    assert list(f.entities) == ["time", "PART_2_XFORM", "PART_3_XFORM", "REQUEST_3"]
    assert f.entities["PART_2_XFORM"].type == "Part" and f.entities["PART_2_XFORM"].object_id == 2
    # The "input" step is left out; the initial conditions (t = 0) are replaced by the
    # dynamic run's first step at the same time: t = 0, 0.025, ..., 0.25.
    assert f.times.tolist() == pytest.approx([0.025 * k for k in range(11)], abs=0)
    assert f.steps[0] == ("dynamic_001", "dynamic")
    assert f.values.shape == (11, 45)


def test_values_go_to_the_components_of_their_ids(free_fall):
    p2 = free_fall.entity("PART_2_XFORM")
    p3 = free_fall.entity("PART_3_XFORM")
    assert list(p2.columns[:6]) == ["X", "Y", "Z", "PSI", "THETA", "PHI"]
    assert p2.attrs["units"]["VY"] == "inch/sec"
    t = p2.index.to_numpy()
    # Closed form of free fall from rest; the file prints 17 digits, so equality to 1 ulp-ish:
    # relative 1e-15.
    np.testing.assert_allclose(p2["Y"], -0.5 * G * t * t, rtol=1e-15, atol=0)
    np.testing.assert_allclose(p2["VY"], -G * t, rtol=1e-15, atol=0)
    np.testing.assert_allclose(p2["ACCY"], -G, rtol=1e-15, atol=0)
    # PART_3's ids are interleaved with PART_2's (ids by quantity block): it must stay put.
    assert (p3["X"] == 1.0).all() and (p3["Y"] == 5.0).all() and (p3["VY"] == 0.0).all()
    assert len(t) == 11  # 11 steps of 6 columns compared


def test_requests_by_id_with_their_eight_components(free_fall):
    req = free_fall.requests
    assert list(req) == [3]
    d = free_fall.request(3)
    assert list(d.columns) == ["mag", "x", "y", "z", "r_mag", "psi", "theta", "phi"]
    t = d.index.to_numpy()
    np.testing.assert_allclose(d["y"], -0.5 * G * t * t, rtol=1e-15, atol=0)
    np.testing.assert_allclose(d["mag"], 0.5 * G * t * t, rtol=1e-15, atol=0)
    assert free_fall.request_entity(3).components[0].plot_label == "MAG"
    with pytest.raises(KeyError, match="no REQUEST/4"):
        free_fall.request(4)


def test_steps_can_be_chosen_by_type(free_fall):
    ic = openmss.read_res(DATA / "free_fall.res", include=("initialConditions",))
    assert ic.times.tolist() == [0.0]
    inputs = openmss.read_res(DATA / "free_fall.res", include=("input",))
    assert (inputs.values[0, 1:] == 9.0).all()


def test_a_file_cut_off_mid_run_is_named(tmp_path):
    text = (DATA / "free_fall.res").read_text()
    cut = tmp_path / "cut.res"
    cut.write_text(text[: text.index("</Data>\n<TerminationStatus")])
    with pytest.raises(openmss.ResultsFileError, match="not well-formed"):
        openmss.read_res(cut)


def test_a_component_without_id_is_named(tmp_path):
    text = (DATA / "free_fall.res").read_text().replace(' id="20" />', " />", 1)
    bad = tmp_path / "bad.res"
    bad.write_text(text)
    with pytest.raises(openmss.ResultsFileError, match="'VX' of 'PART_3_XFORM' has no valid id"):
        openmss.read_res(bad)
