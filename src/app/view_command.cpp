#include "app/view_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/print_diagnostics.hpp"
#include "app/python_tool.hpp"
#include "language/reader.hpp"
#include "model/graphics_builder.hpp"
#include "model/model_builder.hpp"
#include "output/scene_json.hpp"

namespace fs = std::filesystem;

namespace openmss::app {

const char* const kViewHelp =
    "openmss view RESULT [--model FILE.adm] [--port P] [--outdir DIR]\n"
    "  Serves the 3-D viewer of a run on http://127.0.0.1:P/ (P = 0 or absent: a free port)\n"
    "  and prints its URL; Ctrl-C stops it. RESULT is a results file (.res) or the command\n"
    "  file of the run (.acf: line 1 names the model, line 2 the output prefix; the .res is\n"
    "  looked for in --outdir, default the current directory). The model defaults to the .adm\n"
    "  beside the .res with its base name. The page draws the GRAPHICS, animates the parts\n"
    "  from the .res and plots its requests; nothing is fetched from the internet.\n"
    "openmss view RESULT [--model FILE.adm] --write-scene FILE\n"
    "  Writes the model's scene (parts, graphics, markers; docs/viewer.md) and exits.\n";

namespace {

struct ViewOptions {
  std::string result, model, outdir = ".", port = "0", writeScene;
};

std::string trimmed(std::string s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// The model and the .res of an .acf: line 1 the model (relative to the command file's folder,
// .adm supplied when missing), line 2 the prefix (blank: the model's base name).
bool resolveCommandFile(ViewOptions& o) {
  std::ifstream in(o.result);
  std::string modelLine, prefix;
  if (!in || !std::getline(in, modelLine)) {
    std::fprintf(stderr, "openmss view: %s: cannot read the command file\n", o.result.c_str());
    return false;
  }
  std::getline(in, prefix);
  fs::path model = fs::path(o.result).parent_path() / trimmed(modelLine);
  if (!model.has_extension()) model += ".adm";
  if (o.model.empty()) o.model = model.string();
  prefix = trimmed(prefix);
  if (prefix.empty()) prefix = model.stem().string();
  o.result = (fs::path(o.outdir) / (prefix + ".res")).string();
  return true;
}

bool parse(int argc, char** argv, ViewOptions& o) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--model" && hasValue)
      o.model = argv[++i];
    else if (a == "--port" && hasValue)
      o.port = argv[++i];
    else if (a == "--outdir" && hasValue)
      o.outdir = argv[++i];
    else if (a == "--write-scene" && hasValue)
      o.writeScene = argv[++i];
    else if (!a.starts_with("--") && o.result.empty())
      o.result = a;
    else {
      std::fprintf(stderr, "openmss view: unexpected argument %s\n%s", a.c_str(), kViewHelp);
      return false;
    }
  }
  if (o.result.empty()) {
    std::fprintf(stderr, "%s", kViewHelp);
    return false;
  }
  if (o.port.find_first_not_of("0123456789") != std::string::npos || o.port.size() > 5) {
    std::fprintf(stderr, "openmss view: --port %s is not a port number\n", o.port.c_str());
    return false;
  }
  return true;
}

// Reads and builds the model and writes its scene to `path`; false after printed errors.
bool writeScene(const std::string& modelFile, const std::string& path) {
  Diagnostics diags;
  language::Dataset ds;
  language::readDatasetFile(modelFile, ds, diags);
  model::Model m;
  const bool built = model::buildModel(ds, m, diags);
  if (!built || diags.hasErrors()) {
    printDiagnostics(diags);
    return false;
  }
  Diagnostics ignored;  // the same diagnostics as buildModel's check, already printed
  const std::vector<model::Graphic> graphics = model::buildGraphics(ds, m, ignored);
  printDiagnostics(diags);  // warnings (kinds not drawn, ...)
  std::ofstream out(path, std::ios::binary);
  output::writeSceneJson(m, graphics, out);
  return static_cast<bool>(out);
}

}  // namespace

int runView(int argc, char** argv) {
  ViewOptions o;
  if (!parse(argc, argv, o)) return 64;
  const std::string ext = fs::path(o.result).extension().string();
  if ((ext == ".acf" || ext == ".ACF") && !resolveCommandFile(o)) return 1;
  if (o.model.empty()) o.model = fs::path(o.result).replace_extension(".adm").string();
  if (!fs::exists(o.model)) {
    std::fprintf(stderr, "openmss view: model %s not found; name it with --model FILE.adm\n",
                 o.model.c_str());
    return 1;
  }
  if (!o.writeScene.empty()) return writeScene(o.model, o.writeScene) ? 0 : 1;
  if (!fs::exists(o.result)) {
    std::fprintf(stderr,
                 "openmss view: results file %s not found (RESULTS/ in the model writes it)\n",
                 o.result.c_str());
    return 1;
  }
  // The page, its modules and the server are copied beside the program by the build.
  const fs::path viewer = fs::read_symlink("/proc/self/exe").parent_path() / "viewer";
  if (!fs::exists(viewer / "serve.py") || !fs::exists(viewer / "three.module.js")) {
    std::fprintf(stderr,
                 "openmss view: the viewer files are missing from %s (rebuild: npm "
                 "installs three.js, docs/viewer.md)\n",
                 viewer.c_str());
    return 1;
  }
  char folder[] = "/tmp/openmss-view-XXXXXX";
  if (!mkdtemp(folder)) {
    std::perror("openmss view: temporary folder");
    return 1;
  }
  const std::string scene = std::string(folder) + "/scene.json";
  if (!writeScene(o.model, scene)) return 1;
  const std::string server = (viewer / "serve.py").string();
  const std::string result = fs::absolute(o.result).string();
  // The package's interpreter (app/python_tool.hpp: $OPENMSS_PYTHON, else /usr/bin/python3);
  // the server needs only its standard library.
  const std::string python = pythonInterpreter();
  const std::vector<const char*> args = {
      python.c_str(), server.c_str(), "--root", viewer.c_str(), "--scene",     scene.c_str(),
      "--result",     result.c_str(), "--port", o.port.c_str(), "--temporary", nullptr};
  std::fflush(stdout);
  execv(args[0], const_cast<char* const*>(args.data()));
  std::fprintf(stderr, "openmss view: cannot start %s: %s\n", python.c_str(), std::strerror(errno));
  return 1;
}

}  // namespace openmss::app
