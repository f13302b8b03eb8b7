#include "gi/radiosity/radiosity_system.hpp"

#include <stdexcept>

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

}  // namespace gi
