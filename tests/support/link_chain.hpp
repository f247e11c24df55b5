#pragma once
// The links of the mixed-joint test chains (the HHT and SI2 sparse tests): link i is PART/p,
// p = i + 2, with its CM marker 10p at x = i + 0.5, its joint marker 10p+1 at x = i (turned for a
// UNIVERSAL), its tip marker 10p+2 at x = i + 1, a joint of kind joints[i] to the parent's tip
// (ground marker 10 for the first), and from the third link on a translational SPRINGDAMPER to
// the CM of the part two back.

#include <ostream>
#include <string>
#include <vector>

namespace openmss::testing {

inline void writeLinkChain(std::ostream& s, const std::vector<std::string>& joints, double massStep,
                           const char* inertia, double k, double c) {
  for (int i = 0; i < static_cast<int>(joints.size()); ++i) {
    const int p = i + 2;
    s << "PART/" << p << ", MASS=" << 1.0 + massStep * i << ", CM=" << 10 * p << ", IP=" << inertia
      << "\n"
      << "MARKER/" << 10 * p << ", PART=" << p << ", QP=" << i + 0.5 << ",0,0\n"
      << "MARKER/" << 10 * p + 1 << ", PART=" << p << ", QP=" << i << ",0,0"
      << (joints[i] == "UNIVERSAL" ? ", REULER=0D,90D,0D" : "") << "\n"
      << "MARKER/" << 10 * p + 2 << ", PART=" << p << ", QP=" << i + 1 << ",0,0\n";
    const int parentTip = i == 0 ? 10 : 10 * (p - 1) + 2;
    s << "JOINT/" << p << ", " << joints[i] << ", I=" << 10 * p + 1 << ", J=" << parentTip << "\n";
    if (i >= 2)
      s << "SPRINGDAMPER/" << p << ", TRANSLATIONAL, I=" << 10 * p << ", J=" << 10 * (p - 2)
        << ", K=" << k << ", C=" << c << ", LENGTH=2\n";
  }
}

}  // namespace openmss::testing
