#pragma once
// The polynomial weights of the BDF predictor-corrector (solvers/bdf_integrator.cpp): Lagrange
// interpolation through past solutions (predictor, GSTIFF's re-sampled history, interpolation
// between steps) and the BDF weights (the derivative at the newest node of the polynomial through
// all nodes). Nodes may be unequally spaced (WSTIFF's variable coefficients).

namespace openmss::solvers::bdf {

// Weights of the value (w) and derivative (dw) at x of the polynomial through (nodes, values):
// p(x) = sum w_j y_j, p'(x) = sum dw_j y_j. x must differ from every node.
void lagrangeAt(const double* nodes, int n, double x, double* w, double* dw);

// BDF weights: derivative at nodes[0] of the polynomial through all n nodes, p'(nodes[0]) =
// sum a_j y_j; a[0] is the leading coefficient cj.
void bdfWeights(const double* nodes, int n, double* a);

}  // namespace openmss::solvers::bdf
