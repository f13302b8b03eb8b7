#include "gi/radiosity/form_factors/hemicube.hpp"

#include <cmath>
#include <stdexcept>

#include "gi/core/not_implemented.hpp"

namespace gi {

double delta_form_factor_top(double x, double y, double cell_area) {
  // BEGIN EXERCISE 7.1 delta form factor of a top cell
  const double d = x * x + y * y + 1;
  return cell_area / (pi * d * d);
  // END EXERCISE 7.1
}

double delta_form_factor_side(double u, double z, double cell_area) {
  // BEGIN EXERCISE 7.2 delta form factor of a side cell
  const double d = u * u + z * z + 1;
  return z * cell_area / (pi * d * d);
  // END EXERCISE 7.2
}

std::optional<HemicubeCell> project_to_hemicube(const vec3& d, int resolution) {
  // BEGIN EXERCISE 7.3 projecting a direction onto the hemicube
  if (!(d.z > 0)) return std::nullopt;  // below the horizon (or NaN)
  // The face is the axis the direction leans along most; dividing by that component
  // puts the point on the face, where the other two coordinates lie in [-1, 1].
  const auto cell = [&](double coordinate, int cells, double from) {
    return std::clamp(static_cast<int>((coordinate - from) / 2.0 * resolution), 0, cells - 1);
  };
  const double ax = std::abs(d.x), ay = std::abs(d.y);
  if (d.z >= ax && d.z >= ay)
    return HemicubeCell{HemicubeFace::Top, cell(d.x / d.z, resolution, -1), cell(d.y / d.z, resolution, -1)};
  const int half = resolution / 2;
  if (ax >= ay) {
    const double u = d.y / ax, z = d.z / ax;
    return HemicubeCell{d.x > 0 ? HemicubeFace::PlusX : HemicubeFace::MinusX, cell(u, resolution, -1),
                        cell(z, half, 0)};
  }
  const double u = d.x / ay, z = d.z / ay;
  return HemicubeCell{d.y > 0 ? HemicubeFace::PlusY : HemicubeFace::MinusY, cell(u, resolution, -1),
                      cell(z, half, 0)};
  // END EXERCISE 7.3
}

double HemicubeWeights::sum() const {
  // Neumaier's compensated sum: 10^7 cells at resolution 2000 would otherwise leave 1e-10.
  double sum = 0, lost = 0;
  const auto add = [&](double x) {
    const double t = sum + x;
    lost += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  };
  for (double dF : top) add(dF);
  for (int face = 0; face < 4; ++face)
    for (double dF : side) add(dF);
  return sum + lost;
}

HemicubeWeights hemicube_weights(int resolution) {
  if (resolution < 2 || resolution > 2000 || resolution % 2)
    throw std::invalid_argument("hemicube: the resolution must be even and lie in [2, 2000]");
  HemicubeWeights w{resolution, std::vector<double>(resolution * resolution),
                    std::vector<double>(resolution / 2 * resolution), 0.0};
  const double h = 2.0 / resolution, area = h * h;  // cell side and area
  for (int row = 0; row < resolution; ++row)
    for (int column = 0; column < resolution; ++column)
      w.top[row * resolution + column] = delta_form_factor_top(-1 + (column + 0.5) * h, -1 + (row + 0.5) * h, area);
  for (int row = 0; row < resolution / 2; ++row)
    for (int column = 0; column < resolution; ++column)
      w.side[row * resolution + column] = delta_form_factor_side(-1 + (column + 0.5) * h, (row + 0.5) * h, area);
  // The midpoint rule's sum is 1 + O(1/res^2) (1 + 5.4e-5 at res 100): scaled to 1, so
  // that a closed room's rows sum to 1 and energy is neither made nor lost.
  w.unnormalised_sum = w.sum();
  for (double& dF : w.top) dF /= w.unnormalised_sum;
  for (double& dF : w.side) dF /= w.unnormalised_sum;
  return w;
}

}  // namespace gi
