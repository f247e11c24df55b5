#pragma once
// The cubic Hermite basis on [0, 1] at x and its derivatives: the interpolant between two
// states with their derivatives, used by HHT, DSTIFF (over steps handed over together) and
// MERSON. value = h00 y0 + h h10 y0' + h01 y1 + h h11 y1'; derivative = (d00 y0 + d01 y1) / h +
// d10 y0' + d11 y1'.

namespace openmss::solvers {

struct HermiteWeights {
  double h00, h10, h01, h11;  // values
  double d00, d10, d01, d11;  // derivatives with respect to x
};

inline HermiteWeights hermiteWeights(double x) {
  HermiteWeights w;
  w.h00 = (1 + 2 * x) * (1 - x) * (1 - x);
  w.h10 = x * (1 - x) * (1 - x);
  w.h01 = x * x * (3 - 2 * x);
  w.h11 = x * x * (x - 1);
  w.d00 = 6 * x * x - 6 * x;
  w.d10 = 3 * x * x - 4 * x + 1;
  w.d01 = -w.d00;
  w.d11 = 3 * x * x - 2 * x;
  return w;
}

}  // namespace openmss::solvers
