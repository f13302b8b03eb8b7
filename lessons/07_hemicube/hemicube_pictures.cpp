// Lesson 07, step 1: what a hemicube on a floor element sees, and its cells' weights (steps.hpp).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "steps.hpp"
#include "gi/image/diff.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/form_factors/hemicube_image.hpp"

namespace lesson07 {
namespace {

// Each element in its surface's colour, brightness varied per element so that
// neighbours differ; the light yellow.
gi::Pixel element_colour(const gi::Mesh& mesh, int element) {
  if (element < 0) return gi::Pixel(0);
  const gi::Element& e = mesh.elements[element];
  if (gi::max_component(mesh.emission(e)) > 0) return gi::Pixel(1.0f, 0.85f, 0.2f);
  const unsigned hash = static_cast<unsigned>(element) * 2654435761u;
  const double shade = 0.25 + 0.5 * ((hash >> 16) & 255) / 255.0;
  const gi::Color rho = mesh.reflectance(e);
  return gi::Pixel(gi::max_component(rho) > 0 ? shade * rho / gi::max_component(rho) : gi::Color(0.15 * shade));
}

}  // namespace

int floor_element(const gi::Mesh& mesh) {
  const gi::vec3 spot(180, 0, 420);
  int best = 0;
  for (int i = 0; i < static_cast<int>(mesh.elements.size()); ++i)
    if (mesh.elements[i].surface == 0 &&
        gi::length(mesh.elements[i].shape.centre - spot) < gi::length(mesh.elements[best].shape.centre - spot))
      best = i;
  return best;
}

void hemicube_pictures(const gi::Mesh& mesh, int resolution, gi::Lesson& lesson) {
  const std::vector<gi::Polygon> shapes = gi::element_shapes(mesh);
  const int from = floor_element(mesh);
  gi::ItemBuffer buffer;
  gi::render_item_buffer(shapes, gi::lifted_centre(shapes[from]), shapes[from].normal, resolution, buffer);
  const auto cell = [&](int column, int row) { return static_cast<std::size_t>(row) * resolution + column; };
  const gi::Image items = gi::unfold_hemicube(resolution, [&](gi::HemicubeFace face, int column, int row) {
    return element_colour(mesh, buffer.items[int(face)][cell(column, row)]);
  });
  lesson.diagram(gi::enlarge(items, std::max(1, 300 / resolution)), "item_buffer",
                 "the item buffer of a floor element's hemicube, unfolded: each element in its wall's colour");
  const gi::HemicubeWeights w = gi::hemicube_weights(resolution);
  const double top = w.top[cell(resolution / 2, resolution / 2)];
  const gi::Image weights = gi::unfold_hemicube(resolution, [&](gi::HemicubeFace face, int column, int row) {
    const double dF = face == gi::HemicubeFace::Top ? w.top[cell(column, row)] : w.side[cell(column, row)];
    return gi::false_colour({dF}, 1, 1, 0, top).pixels[0];
  });
  lesson.diagram(gi::enlarge(weights, std::max(1, 300 / resolution)), "delta_form_factors",
                 "the delta form factor of every hemicube cell in false colour, red at the top face's centre",
                 gi::ColourScale{0, top, "delta form factor of a cell"});
}

}  // namespace lesson07
