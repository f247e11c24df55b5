#pragma once
// One design-study variant run inside the calling process (python/openmss/study/runner.py,
// docs/studies.md "In-process solver"): what `openmss run MODEL --quiet --outdir DIR
// --set ...` does in a child process, without the program's start-up.

#include <string>
#include <vector>

namespace openmss::pybind {

struct VariantRun {
  int exitStatus = 1;     // as the program's: 0 completed, 1 input error, 2 failed
  std::string errorText;  // what the program would have printed on stderr
};

// `model`: an .acf (run as a command file) or a data set (SIMULATE/TRANSIENT with `end` and
// `dtout` when > 0, else `steps`; the defaults of `openmss run` are end 1, steps 100).
VariantRun runVariant(const std::string& model, const std::string& outdir,
                      const std::vector<std::string>& overrides, double end, long steps,
                      double dtout);

}  // namespace openmss::pybind
