#pragma once
// Upper- and lower-case copies of ASCII text: ADAMS names, keywords, FORTRAN CHARACTER
// arguments and units words are ASCII, so the C locale's toupper/tolower are exact for them.

#include <cctype>
#include <string>
#include <string_view>

namespace openmss {

inline std::string toUpperAscii(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

inline std::string toLowerAscii(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace openmss
