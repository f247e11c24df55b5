#pragma once
// SAVE and RELOAD (Session::saveOrReload in save_reload_command.cpp; the file format in
// analysis/save_file.hpp and docs/save-format.md).

#include <string>

namespace openmss::commands {

// The whole file as bytes ("" when it cannot be read).
std::string readTextFile(const std::string& path);

}  // namespace openmss::commands
