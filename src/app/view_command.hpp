#pragma once
// `openmss view RESULT [--model X.adm] [--port P]`: the browser viewer of a run's results
// (docs/viewer.md). Writes the model's scene (output/scene_json.hpp) and serves it with the
// page and the .res on 127.0.0.1 through viewer/serve.py.

namespace openmss::app {

extern const char* const kViewHelp;

// argv[0] is the program, argv[1] "view". Returns the exit status (does not return once the
// server runs: the process becomes the server).
int runView(int argc, char** argv);

}  // namespace openmss::app
