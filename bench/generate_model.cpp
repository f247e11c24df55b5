// openmss-generate: writes a benchmark model as an ADAMS data set (or its command file) to
// standard output, e.g. `openmss-generate chain-planar 100 > chain.adm`.

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "model_generators.hpp"

namespace {

int usage() {
  std::cerr << "Usage:\n"
               "  openmss-generate KIND N               ADAMS data set on standard output\n"
               "  openmss-generate acf DATASET OUTPUT END STEPS ERROR [INTEGRATOR]\n"
               "                                        command file on standard output\n"
               "KIND: chain-planar | chain-spatial | chain-stiff4 | chain-stiff8 | fourbar |\n"
               "bushing; "
               "N: links (loops for fourbar)\n";
  return 64;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace openmss::bench;
  try {
    if ((argc == 7 || argc == 8) && std::string(argv[1]) == "acf") {
      std::cout << chainAcf(argv[2], argv[3], std::stod(argv[4]), std::stoi(argv[5]),
                            std::stod(argv[6]), argc == 8 ? argv[7] : "GSTIFF");
      return 0;
    }
    if (argc != 3) return usage();
    std::cout << adamsDataset(modelByName(argv[1], std::stoi(argv[2])));
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "openmss-generate: " << e.what() << "\n";
    return usage();
  }
}
