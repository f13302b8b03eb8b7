#include "gi/radiosity/form_factor_hemicube.hpp"

#include <algorithm>

#include "gi/core/parallel.hpp"

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

FormFactorMatrix form_factor_matrix_hemicube(const std::vector<Polygon>& polygons, int resolution, int threads) {
  const HemicubeWeights weights = hemicube_weights(resolution);
  const int n = static_cast<int>(polygons.size());
  FormFactorMatrix F{n, std::vector<double>(static_cast<std::size_t>(n) * n)};
  // Rows in blocks, so that each task reuses one item buffer's memory.
  const int block = 16, blocks = (n + block - 1) / block;
  parallel_for(blocks, threads, [&](int b) {
    ItemBuffer buffer;
    for (int i = b * block; i < std::min(n, (b + 1) * block); ++i) {
      const std::vector<double> row = form_factor_row_hemicube(polygons, polygons[i], weights, buffer);
      std::copy(row.begin(), row.end(), F.values.begin() + static_cast<std::ptrdiff_t>(i) * n);
    }
  });
  return F;
}

}  // namespace gi
