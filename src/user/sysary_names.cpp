#include "user/sysary_names.hpp"

#include <algorithm>
#include <map>

#include "expr/name_catalog.hpp"

namespace openmss::user {
namespace {

struct Group {
  std::vector<const char*> names;
  int maxArguments;  // of the group's functions; SYSARY passes the first ones to each
};

const std::map<std::string, std::vector<Group>>& groups() {
  // Translational parts take up to four markers (i, j, k, l), rotational displacement two,
  // angular velocity three, angular acceleration four, forces three (docs/expressions.md).
  static const std::map<std::string, std::vector<Group>> g = {
      {"DISP", {{{"DX", "DY", "DZ"}, 3}, {{"PSI", "THETA", "PHI"}, 2}}},
      {"TDISP", {{{"DX", "DY", "DZ"}, 3}}},
      {"RDISP", {{{"PSI", "THETA", "PHI"}, 2}}},
      {"VEL", {{{"VX", "VY", "VZ"}, 4}, {{"WX", "WY", "WZ"}, 3}}},
      {"TVEL", {{{"VX", "VY", "VZ"}, 4}}},
      {"RVEL", {{{"WX", "WY", "WZ"}, 3}}},
      {"ACC", {{{"ACCX", "ACCY", "ACCZ"}, 4}, {{"WDTX", "WDTY", "WDTZ"}, 4}}},
      {"TACC", {{{"ACCX", "ACCY", "ACCZ"}, 4}}},
      {"RACC", {{{"WDTX", "WDTY", "WDTZ"}, 4}}},
      {"FORCE", {{{"FX", "FY", "FZ"}, 3}, {{"TX", "TY", "TZ"}, 3}}},
      {"TFORCE", {{{"FX", "FY", "FZ"}, 3}}},
      {"RFORCE", {{{"TX", "TY", "TZ"}, 3}}},
  };
  return g;
}

}  // namespace

bool isSysaryName(const std::string& upperName) { return groups().count(upperName) > 0; }

bool sysfncCall(const std::string& name, const int* ipar, int nsize,
                std::vector<expr::HostCall>& calls, std::string& why) {
  const expr::NameInfo* n = expr::findName(name);
  if (!n || n->kind != expr::NameKind::HostFunction) {
    why =
        "not a function SYSFNC can read (it reads the expression functions whose arguments "
        "are ids and flags: DX, VX, ACCX, FX, JOINT, VARVAL, DIF, ARYVAL, ...)";
    return false;
  }
  if (nsize < n->minArguments || nsize > n->maxArguments) {
    why = "NSIZE = " + std::to_string(nsize) + " does not fit " + std::string(n->usage);
    return false;
  }
  calls.push_back({std::string(n->name), std::vector<long>(ipar, ipar + nsize), 0});
  return true;
}

bool sysaryCalls(const std::string& name, const int* ipar, int nsize,
                 std::vector<expr::HostCall>& calls, std::string& why) {
  auto it = groups().find(name);
  if (it == groups().end()) {
    why =
        "not a SYSARY name OpenMSS serves here (DISP, TDISP, RDISP, VEL, TVEL, RVEL, ACC, "
        "TACC, RACC, FORCE, TFORCE, RFORCE)";
    return false;
  }
  if (nsize < 1 || nsize > 4) {
    why = "NSIZE = " + std::to_string(nsize) + " must be 1 to 4";
    return false;
  }
  for (const Group& g : it->second) {
    const int count = std::min(nsize, g.maxArguments);
    for (const char* f : g.names) calls.push_back({f, std::vector<long>(ipar, ipar + count), 0});
  }
  return true;
}

}  // namespace openmss::user
