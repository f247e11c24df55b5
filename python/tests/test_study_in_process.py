"""The in-process solver (`openmss study run --in-process`: each variant run by the extension
openmss._native inside its worker, python/bindings/variant_run.cpp) gives the table of the
child-process solver byte for byte, and the same .msg and .req files: on the 20-variant four-bar
study (5 variants lock up) and on variants that are input errors (an override the data set
refuses: the message comes from the .msg; a model that does not exist: from what the program
prints on standard error, captured in-process)."""

import pytest
import yaml

from openmss.study import load_study, run_study

from study_support import binary, fourbar_study, rows


def both(study_file, tmp_path):
    """The study run with the child-process solver on two thread workers and with the
    in-process solver on two worker processes; returns both output folders."""
    study = load_study(study_file)
    child = tmp_path / "child"
    run_study(study, child, workers=2, processes=False, binary=binary(), progress=False,
              plot=False)
    inproc = tmp_path / "in-process"
    run_study(study, inproc, workers=2, binary=binary(), progress=False, plot=False,
              in_process=True)
    return child, inproc


def test_in_process_runs_give_the_child_process_table_and_messages(tmp_path):
    child, inproc = both(fourbar_study(tmp_path), tmp_path)
    table = (child / "results.csv").read_text()
    assert (inproc / "results.csv").read_text() == table
    statuses = [r["status"] for r in rows(table)]
    assert statuses.count("ok") == 15 and statuses.count("failed") == 5
    assert all("kinematic analysis failed" in r["message"] for r in rows(table)
               if r["status"] == "failed")
    compared = 0
    for made in sorted((child / "variants").glob("v*/*.msg")) + \
            sorted((child / "variants").glob("v*/*.req")):
        twin = inproc / "variants" / made.parent.name / made.name
        assert twin.read_bytes() == made.read_bytes(), made
        compared += 1
    assert compared == 20 + 20  # a .msg each; a .req each (a lock-up keeps its first steps)


def test_input_errors_read_the_same_in_process(tmp_path):
    study_file = fourbar_study(tmp_path, name="bad")
    study_file.write_text(study_file.read_text().replace("PART/3.MASS", "PART/33.MASS"))
    child, inproc = both(study_file, tmp_path)
    table = (child / "results.csv").read_text()
    assert (inproc / "results.csv").read_text() == table
    assert [r["status"] for r in rows(table)] == ["input-error"] * 20
    assert "the data set has no PART/33 to override" in rows(table)[0]["message"]


def test_a_model_that_cannot_be_read_gives_the_same_message_in_process(tmp_path):
    # The command file names a data set that does not exist: no .msg is written, so the
    # message is what the program prints on standard error (captured in-process).
    (tmp_path / "gone.acf").write_text("gone\ngone\nsimulate/transient, end=1, steps=10\nstop\n")
    study_file = fourbar_study(tmp_path, name="gone")
    data = yaml.safe_load(study_file.read_text())
    data["model"] = str(tmp_path / "gone.acf")
    study_file.write_text(yaml.safe_dump(data))
    child, inproc = both(study_file, tmp_path)
    table = (child / "results.csv").read_text()
    assert (inproc / "results.csv").read_text() == table
    assert not list((child / "variants").glob("v*/*.msg"))
    assert [r["status"] for r in rows(table)] == ["input-error"] * 20
    assert "the data set" in rows(table)[0]["message"] and "gone" in rows(table)[0]["message"]


def test_a_timeout_needs_the_child_process_solver(tmp_path):
    study_file = fourbar_study(tmp_path)
    study_file.write_text(study_file.read_text() + "timeout: 60\n")
    with pytest.raises(ValueError, match="timeout: a variant run in the worker's process cannot "
                       "be stopped"):
        run_study(load_study(study_file), tmp_path / "out", in_process=True, binary=binary())
