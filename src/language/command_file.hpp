#pragma once
// A command file (.acf) as read: the model and output names of its first two lines and the
// commands that follow, each a Statement with its source location.

#include <string>
#include <vector>

#include "language/dataset.hpp"

namespace openmss::language {

struct CommandFile {
  std::string file;  // path of the file read
  // Line 1: the data set to load, as written (ADAMS supplies the .adm extension when absent).
  // Empty when line 1 is blank, as in ADAMS/View-written files that load the model with a
  // FILE/MODEL= command instead.
  std::string modelFile;
  // Line 2: the base name of the output files. When line 2 is blank it is the model file's
  // base name (directory and extension removed). Empty when line 1 is blank: line 2 is then an
  // ordinary command and the prefix comes from FILE/MODEL= (or its OUTPUT_PREFIX=).
  std::string outputPrefix;
  std::vector<Statement> commands;  // canonical command names, in file order
};

}  // namespace openmss::language
