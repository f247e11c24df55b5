"""The package imports from the build, finds its program, and reads models (Model.load)."""

import subprocess
import sys

import pytest

import openmss
from conftest import BINARY, JOINTS, PISTON


def test_the_package_is_the_built_one():
    assert openmss.__version__ == "0.1.0"
    # The program the package drives prints the same version.
    out = subprocess.run([openmss._core.binary(), "--version"], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == f"openmss {openmss.__version__}"


def test_the_readme_command_prints_the_piston_dof():
    # docs/example-piston.md: Gruebler 3 x 6 - (5 + 3 + 4 + 5) - 1 = 0 with the crank driven.
    out = subprocess.run([sys.executable, "-c",
                          "import openmss; print(openmss.Model.load("
                          "'examples/piston/piston.adm').dof)"],
                         cwd=PISTON.parent.parent, capture_output=True, text=True, check=True)
    assert out.stdout == "0\n"


def test_model_lists_parts_and_requests():
    m = openmss.Model.load(PISTON / "piston.adm")
    assert m.dof == 0 and m.gruebler == 0
    assert [p.id for p in m.parts] == [1, 2, 3, 4]
    assert [p.mass for p in m.parts] == [0.0, 2.0, 1.5, 2.0]  # PART/01 GROUND; MASS= of 2..4
    assert m.parts[0].ground and not any(p.ground for p in m.parts[1:])
    assert [r.id for r in m.requests] == [7, 8, 9, 10, 11, 12, 13, 14]
    assert m.requests[0].kind == "force" and m.requests[0].name == "CRANK/GROUND REACTION"


def test_a_revolute_pendulum_has_one_dof():
    # One moving part on a revolute joint: 6 - 5 = 1 (ADAMS's .msg of this case says the same).
    m = openmss.Model.load(JOINTS / "Revolute_Case01" / "test_Revolute_Case01.adm")
    assert m.dof == 1


def test_every_input_error_of_the_one_pass_is_raised_with_its_location(tmp_path):
    bad = tmp_path / "bad.adm"
    bad.write_text("two errors\n"
                   "PART/1, GROUND\n"
                   "PART/2, MASS=1, CM=99, IP=1,1,1\n"        # line 3: CM names no marker
                   "MARKER/20, PART=2\n"
                   "JOINT/1, REVOLUTE, I=20, J=77\n"          # line 5: J names no marker
                   "END\n")
    with pytest.raises(openmss.InputError) as info:
        openmss.Model.load(bad)
    e = info.value
    assert len(e.errors) == 2, [str(d) for d in e.errors]
    assert [d.line for d in e.errors] == [3, 5]
    assert [d.statement for d in e.errors] == ["PART/2", "JOINT/1"]
    assert e.file == str(bad) and e.line == 3 and e.statement == "PART/2"
    assert all(d.hint for d in e.errors)  # each says what to change
    assert f"{bad}:3:" in str(e) and f"{bad}:5:" in str(e)


def test_a_missing_file_is_a_file_not_found_error(tmp_path):
    with pytest.raises(FileNotFoundError):
        openmss.Model.load(tmp_path / "none.adm")
