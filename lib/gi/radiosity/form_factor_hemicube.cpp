#include "gi/radiosity/form_factor_hemicube.hpp"

namespace gi {

std::vector<double> form_factor_row_hemicube(const std::vector<Polygon>& polygons, const Polygon& from,
                                             const HemicubeWeights& weights, ItemBuffer& buffer) {
  render_item_buffer(polygons, from.centre, from.normal, weights.resolution, buffer);
  std::vector<double> row(polygons.size(), 0.0);
  for (int f = 0; f < hemicube_faces; ++f) {
    const std::vector<double>& delta = f == 0 ? weights.top : weights.side;
    const std::vector<int>& items = buffer.items[f];
    for (std::size_t cell = 0; cell < items.size(); ++cell)
      if (items[cell] >= 0) row[items[cell]] += delta[cell];
  }
  return row;
}

}  // namespace gi
