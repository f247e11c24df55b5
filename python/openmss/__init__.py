"""OpenMSS from Python: load ADAMS data sets, run them, read and plot results.

    import openmss
    model = openmss.Model.load("examples/piston/piston.adm")
    print(model.dof)
    run = model.simulate(end=2.0, dtout=0.01, integrator="GSTIFF")
    run.requests[7]              # pandas DataFrame indexed by time
    openmss.read_req("x.req")    # a request file written by ADAMS or OpenMSS

docs/python.md describes the package."""

from . import _core
from .errors import Diagnostic, InputError, OpenMSSError, SolverError
from .model import Model, run_acf
from .out import TabularFile, TabularFileError, read_out
from .req import RequestFile, RequestFileError, read_req
from .res import ResultsFile, ResultsFileError, read_res
from .run import Run

__version__ = _core.version

__all__ = [
    "Diagnostic", "InputError", "Model", "OpenMSSError", "RequestFile", "RequestFileError",
    "ResultsFile", "ResultsFileError", "Run", "SolverError", "TabularFile", "TabularFileError",
    "read_out", "read_req", "read_res", "run_acf",
]
