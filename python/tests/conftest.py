"""Shared paths of the Python tests. CTest sets OPENMSS_SOURCE_DIR and OPENMSS_BINARY
(python/CMakeLists.txt); run by hand, the paths default to this checkout and build/."""

import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("OPENMSS_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
BINARY = pathlib.Path(os.environ.get("OPENMSS_BINARY", SOURCE_DIR / "build" / "openmss"))
JOINTS = SOURCE_DIR / "tests" / "validation" / "adams-joints"
PISTON = SOURCE_DIR / "examples" / "piston"


def adams_req_files():
    """The request files ADAMS wrote for the joint cases (six of the nine cases have one)."""
    return sorted(JOINTS.glob("*/*_ADAMS.req"))


@pytest.fixture(scope="session")
def piston_run(tmp_path_factory):
    """examples/piston/piston.acf run once through the package (2 s, DTOUT 0.01)."""
    import openmss

    return openmss.run_acf(PISTON / "piston.acf", outdir=tmp_path_factory.mktemp("piston"))


def pytest_sessionfinish(session, exitstatus):
    """A skipped test fails the file: CTest counts each pytest file as one test and would
    report a file with skips as passed (scripts/ctest_counts.sh counts CTest's results)."""
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None and reporter.stats.get("skipped") and exitstatus == 0:
        session.exitstatus = 1
