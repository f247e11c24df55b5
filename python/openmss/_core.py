"""The bridge from the package to the solver (src/api, docs/python.md).

Two bridges return the same dictionaries:
- "native" (the default): the pybind11 extension `_native` (python/bindings/module.cpp) calls
  the C++ API in this process;
- "process": each call runs the `openmss` program's machine interface, `openmss api ...`
  (src/app/api_command.cpp), in a child process and reads the one JSON document it prints, so
  a run that crashes cannot take the interpreter down.
OPENMSS_BRIDGE=process (or native) chooses; without it the extension is used when it was built
(cmake -DOPENMSS_PYTHON_EXTENSION=ON, the default), the child process otherwise."""

import json
import os
import subprocess

from . import _build

try:  # the in-process extension (python/bindings/module.cpp)
    from . import _native as _extension
except ImportError:
    _extension = None


def bridge():
    """The bridge in use: "native" or "process" (module docstring)."""
    wanted = os.environ.get("OPENMSS_BRIDGE", "")
    if wanted == "process":
        return "process"
    if wanted == "native" and _extension is None:
        raise RuntimeError("OPENMSS_BRIDGE=native, but the extension openmss._native was not "
                           "built (cmake -DOPENMSS_PYTHON_EXTENSION=ON)")
    if wanted not in ("", "native"):
        raise RuntimeError(f"OPENMSS_BRIDGE={wanted}: use native or process")
    return "native" if _extension is not None else "process"


def _native():
    return _extension if bridge() == "native" else None

version = _build.VERSION


def binary():
    """The `openmss` program the package drives: $OPENMSS_BINARY, else the one built beside
    the package (build/openmss for build/python/openmss)."""
    env = os.environ.get("OPENMSS_BINARY")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    beside = os.path.join(os.path.dirname(os.path.dirname(here)), "openmss")
    return beside if os.path.isfile(beside) else _build.BINARY


def _call(*args):
    exe = binary()
    if not os.path.isfile(exe):
        raise RuntimeError(f"the openmss program {exe} does not exist: build the project "
                           "(scripts/build.sh) or set OPENMSS_BINARY")
    p = subprocess.run([exe, "api", *[str(a) for a in args]], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True, errors="replace", check=False)
    if p.returncode != 0:
        raise RuntimeError(f"openmss api {args[0]} failed (status {p.returncode}): "
                           f"{p.stderr.strip()}")
    return json.loads(p.stdout)


def load_model(path):
    native = _native()
    if native is not None:
        return native.load_model(path)
    return _call("load", path)


def run_acf(path, outdir):
    native = _native()
    if native is not None:
        return native.run_acf(path, outdir)
    return _call("run-acf", path, outdir)


def simulate(path, outdir, end, dtout, steps, integrator, error, prefix):
    native = _native()
    if native is not None:
        return native.simulate(path, outdir, end, dtout, steps, integrator, error, prefix)
    # repr() prints the shortest text that reads back as the same double.
    return _call("simulate", path, outdir, repr(float(end)), repr(float(dtout)), int(steps),
                 integrator, repr(float(error)), prefix)


def read_request_file_cpp(path):
    """The C++ reader's view of a .req (src/output/request_file_reader.cpp): ids, types and
    per step [time, values...]. For tests that check the Python reader against it."""
    return _call("read-req", path)
