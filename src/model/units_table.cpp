#include "model/units_table.hpp"

#include <map>
#include <optional>

namespace openmss::model {
namespace {

// SI value of one unit of each name the UNITS statement accepts.
const std::map<std::string, double>& forceUnits() {
  static const std::map<std::string, double> m = {
      {"NEWTON", 1.0},           {"KNEWTON", 1e3},           {"MEGANEWTON", 1e6},
      {"MILLINEWTON", 1e-3},     {"MICRONEWTON", 1e-6},      {"NANONEWTON", 1e-9},
      {"CENTINEWTON", 1e-2},     {"DYNE", 1e-5},             {"KILOGRAM_FORCE", 9.80665},
      {"POUND_FORCE", 4.4482216152605}, {"KPOUND_FORCE", 4448.2216152605},
      {"OUNCE_FORCE", 0.27801385095378125}, {"POUNDAL", 0.138254954376}};
  return m;
}
const std::map<std::string, double>& massUnits() {
  static const std::map<std::string, double> m = {
      {"KILOGRAM", 1.0},        {"GRAM", 1e-3},           {"MILLIGRAM", 1e-6},
      {"MICROGRAM", 1e-9},      {"NANOGRAM", 1e-12},      {"TONNE", 1e3},
      {"POUND_MASS", 0.45359237}, {"KPOUND_MASS", 453.59237}, {"OUNCE_MASS", 0.028349523125},
      {"SLUG", 14.593902937206364}, {"SLINCH", 175.12683524647636}, {"US_TON", 907.18474}};
  return m;
}
const std::map<std::string, double>& lengthUnits() {
  static const std::map<std::string, double> m = {
      {"METER", 1.0},      {"KILOMETER", 1e3},  {"CENTIMETER", 1e-2}, {"MILLIMETER", 1e-3},
      {"MICROMETER", 1e-6}, {"NANOMETER", 1e-9}, {"ANGSTROM", 1e-10}, {"INCH", 0.0254},
      {"FOOT", 0.3048},    {"YARD", 0.9144},    {"MILE", 1609.344},   {"MILS", 2.54e-5},
      {"MICROINCH", 2.54e-8}};
  return m;
}
const std::map<std::string, double>& timeUnits() {
  static const std::map<std::string, double> m = {
      {"SECOND", 1.0},      {"MILLISECONDS", 1e-3}, {"MICROSECOND", 1e-6}, {"NANOSECOND", 1e-9},
      {"MINUTE", 60.0},     {"HOUR", 3600.0},       {"DAY", 86400.0}};
  return m;
}

std::optional<double> lookup(const language::Statement& s, const char* arg,
                             const std::map<std::string, double>& table, Diagnostics& diags) {
  const language::Argument* a = s.find(arg);
  if (!a) return std::nullopt;
  if (a->values.size() != 1) {
    diags.error(a->where, s.subject(), std::string(arg) + " needs one unit name");
    return std::nullopt;
  }
  const std::string& w = a->values[0].text;
  // Unique prefixes are accepted, as for every ADAMS keyword.
  std::optional<double> found;
  int matches = 0;
  for (const auto& [name, value] : table) {
    if (name == w) return value;
    if (name.rfind(w, 0) == 0) { found = value; ++matches; }
  }
  if (matches == 1) return found;
  std::string names;
  for (const auto& [name, value] : table) names += (names.empty() ? "" : ", ") + name;
  diags.error(a->values[0].where, s.subject(), std::string(arg) + "=" + w + " is not a unit",
              "Use one of " + names + ".");
  return std::nullopt;
}

}  // namespace

double unitInSi(const std::string& name) {
  for (const auto* table : {&forceUnits(), &massUnits(), &lengthUnits(), &timeUnits()})
    if (auto it = table->find(name); it != table->end()) return it->second;
  return 1.0;
}

std::string unitSymbol(const std::string& name) {
  static const std::map<std::string, std::string> symbols = {
      {"NEWTON", "N"},        {"KNEWTON", "kN"},       {"MEGANEWTON", "MN"},
      {"MILLINEWTON", "mN"},  {"MICRONEWTON", "uN"},   {"NANONEWTON", "nN"},
      {"CENTINEWTON", "cN"},  {"DYNE", "dyn"},         {"KILOGRAM_FORCE", "kgf"},
      {"POUND_FORCE", "lbf"}, {"KPOUND_FORCE", "klb"}, {"OUNCE_FORCE", "ozf"},
      {"POUNDAL", "pdl"},     {"KILOGRAM", "kg"},      {"GRAM", "g"},
      {"MILLIGRAM", "mg"},    {"MICROGRAM", "ug"},     {"NANOGRAM", "ng"},
      {"TONNE", "t"},         {"POUND_MASS", "lbm"},   {"KPOUND_MASS", "klm"},
      {"OUNCE_MASS", "oz"},   {"SLUG", "slg"},         {"SLINCH", "sli"},
      {"US_TON", "ton"},      {"METER", "m"},          {"KILOMETER", "km"},
      {"CENTIMETER", "cm"},   {"MILLIMETER", "mm"},    {"MICROMETER", "um"},
      {"NANOMETER", "nm"},    {"ANGSTROM", "A"},       {"INCH", "in"},
      {"FOOT", "ft"},         {"YARD", "yd"},          {"MILE", "mi"},
      {"MILS", "mil"},        {"MICROINCH", "uin"},    {"SECOND", "s"},
      {"MILLISECONDS", "ms"}, {"MICROSECOND", "us"},   {"NANOSECOND", "ns"},
      {"MINUTE", "min"},      {"HOUR", "h"},           {"DAY", "d"}};
  auto it = symbols.find(name);
  return it == symbols.end() ? name.substr(0, 3) : it->second;
}

void applyUnits(const language::Statement& s, Units& units, Diagnostics& diags) {
  units.given = true;
  double f = 1.0, m = 1.0, l = 1.0, t = 1.0;
  if (const language::Argument* sys = s.find("SYSTEM")) {
    const std::string w = sys->values.empty() ? "" : sys->values[0].text;
    auto set = [&](const char* len, const char* mass, const char* force) {
      units.length = len;
      units.mass = mass;
      units.force = force;
      units.time = "SECOND";
      f = forceUnits().at(force);
      m = massUnits().at(mass);
      l = lengthUnits().at(len);
    };
    if (w == "MKS") set("METER", "KILOGRAM", "NEWTON");
    else if (w == "CGS") set("CENTIMETER", "GRAM", "DYNE");
    else if (w == "FPS") set("FOOT", "POUND_MASS", "POUND_FORCE");
    else if (w == "IPS") set("INCH", "POUND_MASS", "POUND_FORCE");
    else if (w == "NONE") {
      units.ucf = 1.0;
      units.description = "consistent units (SYSTEM=NONE), UCF = 1";
      return;
    } else {
      diags.error(sys->where, s.subject(), "SYSTEM=" + w + " is not a unit system",
                  "Use CGS, FPS, IPS, MKS or NONE.");
      return;
    }
  } else {
    const char* names[4] = {"FORCE", "MASS", "LENGTH", "TIME"};
    int given = 0;
    for (const char* n : names) given += s.has(n) ? 1 : 0;
    if (given > 0 && given < 4)
      diags.error(s.where, s.subject(), "FORCE, MASS, LENGTH and TIME must be given together",
                  "Give all four, or SYSTEM=, or UCF=.");
    auto pick = [&](const char* arg, const std::map<std::string, double>& table,
                    std::string& name, double& factor) {
      if (auto v = lookup(s, arg, table, diags)) {
        factor = *v;
        for (const auto& [n, value] : table)
          if (value == *v) name = n;
      }
    };
    pick("FORCE", forceUnits(), units.force, f);
    pick("MASS", massUnits(), units.mass, m);
    pick("LENGTH", lengthUnits(), units.length, l);
    pick("TIME", timeUnits(), units.time, t);
  }
  // F[f] * f  = m[m] * m * a[l/t^2] * l / t^2   =>   F * UCF = m * a with UCF = f t^2 / (m l)
  units.ucf = f * t * t / (m * l);
  if (const language::Argument* u = s.find("UCF"); u && !u->values.empty())
    units.ucf = u->values[0].number;
  units.description = units.length + ", " + units.mass + ", " + units.time + ", " + units.force;
}

}  // namespace openmss::model
