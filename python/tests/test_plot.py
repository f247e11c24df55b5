"""`openmss plot`: the PNG exists with the expected size, and the plotted lines hold exactly
the file's data (read back from the Line2D objects, not judged from pixels); the command line
passes arguments and exit status through (src/app/python_tool.cpp)."""

import pathlib
import struct
import subprocess

import numpy as np
import pytest

import openmss
from conftest import BINARY, JOINTS
from openmss import plot

CASE = JOINTS / "Revolute_Case01"
ADAMS = CASE / "test_Revolute_Case01_ADAMS.req"


def png_size(path):
    """Width and height from the PNG's IHDR chunk (bytes 16..24)."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_a_request_component_is_plotted_with_names_and_units(piston_run, tmp_path):
    out = tmp_path / "piston.png"
    fig, ax, lines = plot.plot(piston_run.req, 11, "2", output=out)
    assert png_size(out) == (800, 450)  # plot.FIGSIZE x plot.DPI
    frame = openmss.read_req(piston_run.req).requests[11]
    assert len(lines) == 1
    assert np.array_equal(lines[0].get_xdata(), frame.index.to_numpy())
    assert np.array_equal(lines[0].get_ydata(), frame["X"].to_numpy())
    assert len(lines[0].get_xdata()) == 201
    assert ax.get_ylabel() == "X [in]" and ax.get_xlabel() == "time [s]"
    assert ax.get_title() == "REQUEST/11 PISTON CM DISPLACEMENT X Y Z PSI THETA PHI"


def test_components_by_name_and_the_angles_units(piston_run, tmp_path):
    _, ax, lines = plot.plot(piston_run.req, 11, "theta", output=tmp_path / "t.png")
    assert ax.get_ylabel() == "THETA [deg]"
    _, ax, _ = plot.plot(piston_run.req, 12, "VX", output=tmp_path / "v.png")
    assert ax.get_ylabel() == "VX [in/s]"
    _, ax, _ = plot.plot(piston_run.req, 7, 8, output=tmp_path / "f.png")
    assert ax.get_ylabel() == "TZ [lbf·in]"


def test_vs_overlays_adams_and_ours(tmp_path):
    run = openmss.run_acf(CASE / "test_Revolute_Case01.acf", outdir=tmp_path)
    out = tmp_path / "vs.png"
    _, ax, lines = plot.plot(run.req, 1, "Z", vs=ADAMS, output=out, label="OpenMSS",
                             vs_label="ADAMS")
    assert png_size(out) == (800, 450)
    assert [l.get_label() for l in lines] == ["OpenMSS", "ADAMS"]
    adams = openmss.read_req(ADAMS).requests[1]
    assert np.array_equal(lines[1].get_ydata(), adams["Z"].to_numpy())
    assert np.array_equal(lines[0].get_ydata(), run.requests[1]["Z"].to_numpy())
    assert len(lines[1].get_ydata()) == 501
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["OpenMSS", "ADAMS"]


def test_a_res_file_is_plotted_with_its_own_units(tmp_path):
    res = pathlib.Path(__file__).parent / "data" / "free_fall.res"
    _, ax, lines = plot.plot(res, 3, 3, output=tmp_path / "r.png")  # F3: "y"
    frame = openmss.read_res(res).request(3)
    assert np.array_equal(lines[0].get_ydata(), frame["y"].to_numpy())
    assert ax.get_ylabel() == "y [inch]"


def test_a_magnitude_is_not_in_a_req(piston_run, tmp_path):
    with pytest.raises(SystemExit, match="F1.*magnitude"):
        plot.plot(piston_run.req, 11, 1, output=tmp_path / "m.png")


def test_the_command_line_passes_arguments_and_status_through(piston_run, tmp_path):
    out = tmp_path / "cli.png"
    ok = subprocess.run([str(BINARY), "plot", piston_run.req, "--request", "12",
                         "--component", "VX", "-o", str(out)], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    assert f"wrote {out} (201 points)" in ok.stdout
    assert png_size(out) == (800, 450)
    bad = subprocess.run([str(BINARY), "plot", piston_run.req, "--request", "99",
                          "--component", "2", "-o", str(tmp_path / "x.png")],
                         capture_output=True, text=True)
    assert bad.returncode == 1 and "no REQUEST/99" in bad.stderr
    usage = subprocess.run([str(BINARY), "plot"], capture_output=True, text=True)
    assert usage.returncode == 2 and "--request" in usage.stderr  # argparse's usage status
