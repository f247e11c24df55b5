#include "analysis/eigen_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace openmss::analysis {

std::vector<EigenMode> eigenModes(const LinearSystem& linear) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(linear.a, true);
  const int n = linear.degreesOfFreedom;
  const int states = static_cast<int>(linear.a.rows());
  std::vector<EigenMode> modes;
  for (int i = 0; i < states; ++i) {
    EigenMode mode;
    mode.value = solver.eigenvalues()(i);
    const double size = std::abs(mode.value);
    mode.dampingRatio = size > 0.0 ? -mode.value.real() / size : 0.0;
    mode.naturalFrequency = size / (2.0 * std::numbers::pi);
    mode.dampedFrequency = std::abs(mode.value.imag()) / (2.0 * std::numbers::pi);
    const Eigen::VectorXcd v = solver.eigenvectors().col(i);
    // Positions of every part, then the user states.
    Eigen::VectorXcd shape(linear.positionBasis.rows() + linear.userStates);
    shape.head(linear.positionBasis.rows()) =
        linear.positionBasis.cast<std::complex<double>>() * v.head(n);
    shape.tail(linear.userStates) = v.tail(linear.userStates);
    Eigen::Index at = 0;
    shape.cwiseAbs().maxCoeff(&at);
    if (std::abs(shape(at)) > 0.0) shape /= shape(at);
    for (auto& c : shape) {  // round-off zeros print as zeros
      if (std::abs(c.real()) < 1e-12) c.real(0.0);
      if (std::abs(c.imag()) < 1e-12) c.imag(0.0);
    }
    mode.shape = shape;
    modes.push_back(mode);
  }
  std::sort(modes.begin(), modes.end(), [](const EigenMode& a, const EigenMode& b) {
    const double sa = std::abs(a.value), sb = std::abs(b.value);
    if (std::abs(sa - sb) > 1e-12 * std::max(sa, sb)) return sa < sb;
    return a.value.imag() < b.value.imag();
  });
  return modes;
}

std::vector<std::string> eigenReport(const std::vector<EigenMode>& modes,
                                     const LinearSystem& linear, const model::Model& model,
                                     double time, bool withoutShapes) {
  std::vector<std::string> out;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                " Eigenvalues at time %.6E (%d degrees of freedom, %d user states)", time,
                linear.degreesOfFreedom, linear.userStates);
  out.push_back(buf);
  out.emplace_back("");
  out.emplace_back(
      "   Mode          Real           Imaginary      Damping ratio  "
      "Undamped freq (Hz)  Damped freq (Hz)");
  for (size_t i = 0; i < modes.size(); ++i) {
    const EigenMode& m = modes[i];
    std::snprintf(buf, sizeof buf, "   %4zu  %16.9E  %16.9E  %13.6E  %18.9E  %16.9E", i + 1,
                  m.value.real(), m.value.imag(), m.dampingRatio, m.naturalFrequency,
                  m.dampedFrequency);
    out.emplace_back(buf);
  }
  if (withoutShapes) return out;
  const int nb = model.bodyCount();
  for (size_t i = 0; i < modes.size(); ++i) {
    const EigenMode& m = modes[i];
    if (m.value.imag() < 0.0) continue;  // its conjugate's shape is the conjugate
    out.emplace_back("");
    std::snprintf(buf, sizeof buf,
                  " Mode shape %zu (eigenvalue %.9E %+.9E i): ground axes, rotations in rad, "
                  "largest component 1",
                  i + 1, m.value.real(), m.value.imag());
    out.emplace_back(buf);
    out.emplace_back(
        "   Part              X            Y            Z            RX           "
        "RY           RZ");
    for (int b = 0; b < nb; ++b) {
      const long id = model.parts[model.movingParts[b]].id;
      for (int part = 0; part < 2; ++part) {
        std::string line;
        std::snprintf(buf, sizeof buf, "   %-10s %-4s",
                      part == 0 ? ("PART/" + std::to_string(id)).c_str() : "",
                      part ? "imag" : "real");
        line = buf;
        for (int k = 0; k < 6; ++k) {
          const std::complex<double> c = m.shape(6 * b + k);
          std::snprintf(buf, sizeof buf, " %12.5E", part ? c.imag() : c.real());
          line += buf;
        }
        out.push_back(line);
      }
    }
    for (int k = 0; k < linear.userStates; ++k) {
      const std::complex<double> c = m.shape(6 * nb + k);
      std::snprintf(buf, sizeof buf, "   %-20s %12.5E %+12.5E i",
                    linear.stateNames[static_cast<size_t>(2 * linear.degreesOfFreedom + k)].c_str(),
                    c.real(), c.imag());
      out.emplace_back(buf);
    }
  }
  return out;
}

}  // namespace openmss::analysis
