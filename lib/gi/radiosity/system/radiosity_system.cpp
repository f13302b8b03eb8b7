#include "gi/radiosity/system/radiosity_system.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "gi/core/not_implemented.hpp"

namespace gi {

RadiositySystem make_system(const Mesh& mesh, FormFactorMatrix F) {
  if (F.n != static_cast<int>(mesh.elements.size()) && F.n != 0)
    throw std::invalid_argument("radiosity system: the form-factor matrix does not match the mesh");
  RadiositySystem system;
  for (const Element& e : mesh.elements) {
    system.area.push_back(e.shape.area);
    system.rho.push_back(mesh.reflectance(e));
    system.emission.push_back(mesh.emission(e));
  }
  system.F = std::move(F);
  return system;
}

std::vector<Color> residual(const RadiositySystem& s, const std::vector<Color>& B) {
  const int n = s.size();
  std::vector<Color> r(n);
  for (int i = 0; i < n; ++i) {
    Color gathered(0.0);
    for (int j = 0; j < n; ++j) gathered += s.F(i, j) * B[j];
    r[i] = s.emission[i] + s.rho[i] * gathered - B[i];
  }
  return r;
}

Color power(const std::vector<double>& area, const std::vector<Color>& B) {
  Color sum(0.0);
  for (std::size_t i = 0; i < area.size(); ++i) sum += area[i] * B[i];
  return sum;
}

SpectralRadius spectral_radius(const RadiositySystem& s, int channel, double tolerance, int max_iterations) {
  if (channel < 0 || channel > 2) throw std::invalid_argument("spectral radius: the channel must be 0, 1 or 2");
  // BEGIN EXERCISE 12.1 the spectral radius by power iteration
  const int n = s.size();
  std::vector<double> x(n, 1.0), y(n);
  SpectralRadius result;
  for (int k = 1; k <= max_iterations && n > 0; ++k) {
    double top = 0, largest = 0;
    for (int i = 0; i < n; ++i) {
      double gathered = 0;
      for (int j = 0; j < n; ++j) gathered += s.F(i, j) * x[j];
      y[i] = s.rho[i][channel] * gathered + x[i];  // (R F + I) x
      top = std::max(top, y[i]);
      largest = std::max(largest, x[i]);
    }
    double lower = std::numeric_limits<double>::infinity(), upper = 0;
    for (int i = 0; i < n; ++i)
      if (x[i] > 1e-9 * largest) lower = std::min(lower, y[i] / x[i]), upper = std::max(upper, y[i] / x[i]);
    result = {lower - 1, upper - 1, k, upper - lower <= tolerance * upper};
    if (result.converged) break;
    for (int i = 0; i < n; ++i) x[i] = y[i] / top;
  }
  return result;
  // END EXERCISE 12.1
}

}  // namespace gi
