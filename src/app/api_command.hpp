#pragma once
// `openmss api ...`: the embeddable API (src/api) as a machine interface, one JSON document on
// stdout per call. The Python package runs it in a child process (python/openmss/_core.py,
// docs/python.md): a run that crashes or leaks cannot take the interpreter with it, and the
// solver libraries need not be compiled position-independent for a Python extension.
//
//   openmss api load FILE.adm
//   openmss api run-acf FILE.acf OUTDIR
//   openmss api simulate FILE.adm OUTDIR END DTOUT STEPS INTEGRATOR ERROR PREFIX
//   openmss api read-req FILE.req        (the C++ reader's values, for the Python tests)
// Exit status 0 when the JSON was written (whatever the run's outcome, which it states), 64
// on a usage error.

namespace openmss::app {

int apiCommand(int argc, char** argv);

}  // namespace openmss::app
