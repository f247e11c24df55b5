"""A data set loaded and checked by the solver (docs/python.md)."""

import os
import tempfile

from . import _core
from .errors import Diagnostic, InputError, SolverError
from .run import Run


class Part:
    __slots__ = ("id", "name", "ground", "mass")

    def __init__(self, d):
        self.id, self.name, self.ground, self.mass = d["id"], d["name"], d["ground"], d["mass"]

    def __repr__(self):
        return f"Part(id={self.id}, name={self.name!r}, mass={self.mass:g})"


class Request:
    __slots__ = ("id", "name", "kind", "i_marker", "j_marker")

    def __init__(self, d):
        self.id, self.name, self.kind = d["id"], d["name"], d["kind"]
        self.i_marker, self.j_marker = d["i_marker"], d["j_marker"]

    def __repr__(self):
        return f"Request(id={self.id}, kind={self.kind!r}, name={self.name!r})"


def _outdir(outdir):
    if outdir is None:
        return tempfile.mkdtemp(prefix="openmss-")
    os.makedirs(outdir, exist_ok=True)
    return str(outdir)


def _finish(info, path):
    run = Run(info)
    if info["status"] == "input_error":
        raise InputError(run.diagnostics, path)
    if info["status"] == "failed":
        raise SolverError(run, run.diagnostics)
    return run


class Model:
    """A data set (.adm) read and checked in one pass. ``dof`` are its degrees of freedom,
    ``gruebler`` the Gruebler count, ``parts`` and ``requests`` lists by id, ``warnings`` the
    warnings of the reading. Model.load raises InputError with every error."""

    def __init__(self, info):
        self.path = info["path"]
        self.title = info["title"]
        self.dof = info["dof"]
        self.gruebler = info["gruebler"]
        self.parts = [Part(p) for p in info["parts"]]
        self.requests = [Request(r) for r in info["requests"]]
        self.diagnostics = [Diagnostic.from_dict(d) for d in info["diagnostics"]]
        self.warnings = [d for d in self.diagnostics if d.severity == "warning"]

    @classmethod
    def load(cls, path):
        path = os.fspath(path)
        if not os.path.isfile(path):
            raise FileNotFoundError(path)
        info = _core.load_model(path)
        if not info["ok"]:
            raise InputError([Diagnostic.from_dict(d) for d in info["diagnostics"]], path)
        return cls(info)

    def simulate(self, end=1.0, dtout=None, steps=None, integrator=None, error=None,
                 outdir=None, prefix=None):
        """SIMULATE/TRANSIENT to `end` with output every `dtout` (or `steps` output steps,
        100 by default), with INTEGRATOR/`integrator` (GSTIFF, WSTIFF, DSTIFF, ...) and its
        ERROR=`error` when given. The outputs (.msg, .req, and .res when written) go to
        `outdir` (a fresh temporary folder by default). Returns a Run; raises SolverError
        (carrying the Run) when the analysis fails."""
        if dtout is not None and steps is not None:
            raise ValueError("give dtout or steps, not both")
        outdir = _outdir(outdir)
        info = _core.simulate(self.path, outdir, float(end), float(dtout or 0.0),
                              int(steps if steps is not None else 100), integrator or "",
                              float(error or 0.0), prefix or "")
        return _finish(info, self.path)

    def __repr__(self):
        return (f"Model({self.path!r}, title={self.title!r}, dof={self.dof}, "
                f"{len(self.parts)} parts, {len(self.requests)} requests)")


def run_acf(path, outdir=None):
    """Runs an ADAMS command file as `openmss run FILE.acf --outdir OUTDIR` does (outputs in a
    fresh temporary folder by default). Returns a Run; raises InputError when the command file
    or its model has errors, SolverError (carrying the Run) when a command fails."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(path)
    return _finish(_core.run_acf(path, _outdir(outdir)), path)
