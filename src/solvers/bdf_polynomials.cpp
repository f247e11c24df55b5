#include "solvers/bdf_polynomials.hpp"

namespace openmss::solvers::bdf {

void lagrangeAt(const double* nodes, int n, double x, double* w, double* dw) {
  for (int j = 0; j < n; ++j) {
    double num = 1.0, den = 1.0, s = 0.0;
    for (int m = 0; m < n; ++m) {
      if (m == j) continue;
      num *= x - nodes[m];
      den *= nodes[j] - nodes[m];
      s += 1.0 / (x - nodes[m]);
    }
    w[j] = num / den;
    dw[j] = w[j] * s;
  }
}

void bdfWeights(const double* nodes, int n, double* a) {
  a[0] = 0.0;
  for (int m = 1; m < n; ++m) a[0] += 1.0 / (nodes[0] - nodes[m]);
  for (int j = 1; j < n; ++j) {
    double num = 1.0, den = 1.0;
    for (int m = 0; m < n; ++m) {
      if (m == j) continue;
      if (m != 0) num *= nodes[0] - nodes[m];
      den *= nodes[j] - nodes[m];
    }
    a[j] = num / den;
  }
}

}  // namespace openmss::solvers::bdf
