#include "gi/radiosity/display/element_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/radiosity/hierarchical/mesh_lines.hpp"

namespace gi {

ElementSizes render_element_sizes(const Mesh& mesh, const Camera& camera, int width, int height, double top,
                                  int threads) {
  std::vector<double> surface_area(mesh.surfaces.size(), 0.0);
  for (const Element& e : mesh.elements) surface_area[e.surface] += e.shape.area;
  const double largest = surface_area.empty() ? 1 : *std::max_element(surface_area.begin(), surface_area.end());
  std::vector<double> cuts;  // log4(A_largest / A_element) = ln(ratio) / ln 4
  for (const Element& e : mesh.elements) cuts.push_back(std::max(0.0, std::log(largest / e.shape.area) / std::log(4.0)));
  if (top <= 0) top = cuts.empty() ? 1 : std::max(1.0, *std::max_element(cuts.begin(), cuts.end()));

  const std::vector<int> ids = visible_polygons(FormFactorScene(element_shapes(mesh)), camera, width, height, threads);
  std::vector<double> values(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) values[k] = ids[k] < 0 ? 0 : cuts[ids[k]];
  Image image = false_colour(values, width, height, 0, top);
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (ids[k] < 0) image.pixels[k] = Pixel(0);
  return {draw_mesh_lines(image, ids, Color(0.0), 0.8), top};
}

}  // namespace gi
