#include "gi/radiosity/display/element_values.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gi/image/diff.hpp"
#include "gi/radiosity/hierarchical/mesh_lines.hpp"

namespace gi {

Image render_element_values(const Mesh& mesh, const std::vector<double>& values, const Camera& camera, int width,
                            int height, double lo, double hi, bool log10, int threads, int highlight) {
  if (values.size() != mesh.elements.size()) throw std::invalid_argument("element values: one value per element");
  if (!(hi > lo) || (log10 && !(lo > 0))) throw std::invalid_argument("element values: need lo < hi (and lo > 0 on a log scale)");
  const auto shown = [&](double v) { return log10 ? std::log10(std::max(v, lo)) : v; };
  const std::vector<int> ids = visible_polygons(FormFactorScene(element_shapes(mesh)), camera, width, height, threads);
  std::vector<double> pixels(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) pixels[k] = ids[k] < 0 ? shown(lo) : shown(values[ids[k]]);
  Image image = false_colour(pixels, width, height, shown(lo), shown(hi));
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (ids[k] < 0) image.pixels[k] = Pixel(0);
    else if (ids[k] == highlight) image.pixels[k] = Pixel(1);
  return draw_mesh_lines(image, ids, Color(0.0), 0.8);
}

ElementSizes render_element_sizes(const Mesh& mesh, const Camera& camera, int width, int height, double top,
                                  int threads) {
  std::vector<double> surface_area(mesh.surfaces.size(), 0.0);
  for (const Element& e : mesh.elements) surface_area[e.surface] += e.shape.area;
  const double largest = surface_area.empty() ? 1 : *std::max_element(surface_area.begin(), surface_area.end());
  std::vector<double> cuts;  // log4(A_largest / A_element) = ln(ratio) / ln 4
  for (const Element& e : mesh.elements) cuts.push_back(std::max(0.0, std::log(largest / e.shape.area) / std::log(4.0)));
  if (top <= 0) top = cuts.empty() ? 1 : std::max(1.0, *std::max_element(cuts.begin(), cuts.end()));
  return {render_element_values(mesh, cuts, camera, width, height, 0, top, false, threads), top};
}

}  // namespace gi
