#pragma once
// How the `openmss` program starts a tool of the Python package (`openmss plot`, and `view`,
// `study`): Debian's interpreter runs `python3 -m openmss.<module> ARGS...` with the package
// built beside the program first on PYTHONPATH (docs/python.md).

#include <string>
#include <vector>

namespace openmss::app {

// The interpreter: $OPENMSS_PYTHON when set, else /usr/bin/python3 (the one the package's
// extension is built for; python/CMakeLists.txt).
std::string pythonInterpreter();
// The folder holding the built package `openmss`: $OPENMSS_PYTHONPATH when set, else
// <folder of this program>/python when it holds the package (build/openmss ->
// build/python), else the build folder compiled in.
std::string pythonPackageDirectory();

// Runs `python3 -m openmss.<module> args...` and returns its exit status (128 + signal when
// it was killed; 127 when the interpreter cannot be started, with a message on stderr).
int runPythonTool(const std::string& module, const std::vector<std::string>& args);

}  // namespace openmss::app
