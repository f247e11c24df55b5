#pragma once
// A data set with one moving part per constraint element, generically placed (three markers per
// part at odd positions and orientations): even elements hold their part to a ground marker, odd
// ones to the previous part, so both sides of every equation move. Used by the constraint-row
// tests (constraint_rows_test.cpp, residual_rows_test.cpp).

#include <sstream>
#include <string>
#include <vector>

namespace openmss::test {

// `elements` are statement heads ("JOINT/1, REVOLUTE"); element i gets PART/i+2 and markers
// 100 (i+2) + 0..2, and I = marker 100 (i+2) + 1. `tail` is written before END.
inline std::string partPerElementDataSet(const std::string& title,
                                         const std::vector<std::string>& elements,
                                         const std::string& tail) {
  std::ostringstream o;
  o << title << "\nPART/1, GROUND\nMARKER/10, PART=1\n"
    << "MARKER/11, PART=1, QP=0.3,-0.2,0.5, REULER=0.4,0.7,-0.2\n";
  for (size_t i = 0; i < elements.size(); ++i) {
    const int part = static_cast<int>(i) + 2;
    const double x = 0.1 * static_cast<double>(i);
    o << "PART/" << part << ", MASS=2, CM=" << 100 * part << ", IP=1,2,3\n"
      << "MARKER/" << 100 * part << ", PART=" << part << ", QP=" << x
      << ",0.1,-0.3, REULER=0.3,0.2,0.1\n"
      << "MARKER/" << 100 * part + 1 << ", PART=" << part << ", QP=" << x + 0.3
      << ",-0.2,0.5, REULER=0.5,0.6,-0.1\n"
      << "MARKER/" << 100 * part + 2 << ", PART=" << part << ", QP=" << x - 0.2
      << ",0.4,0.1, REULER=-0.3,1.1,0.7\n";
    const int jMarker = i % 2 == 0 ? 11 : 100 * (part - 1) + 2;
    o << elements[i] << ", I=" << 100 * part + 1 << ", J=" << jMarker << "\n";
  }
  o << tail << "END\n";
  return o.str();
}

}  // namespace openmss::test
