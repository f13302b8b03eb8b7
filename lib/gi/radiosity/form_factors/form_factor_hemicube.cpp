#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gi/core/parallel.hpp"

namespace gi {

namespace {

void check_all(const std::vector<Polygon>& polygons) {
  for (std::size_t i = 0; i < polygons.size(); ++i) try {
      check(polygons[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("hemicube: polygon " + std::to_string(i) + ": " + e.what());
    }
}

// The row of valid polygons (checked once by the caller).
HemicubeRow row_of(const std::vector<Polygon>& polygons, const Polygon& from, const HemicubeWeights& weights,
                   ItemBuffer& buffer) {
  render_checked_item_buffer(polygons, lifted_centre(from), from.normal, weights.resolution, buffer);
  HemicubeRow row{std::vector<double>(polygons.size(), 0.0)};
  for (int f = 0; f < hemicube_faces; ++f) {
    const std::vector<double>& delta = f == 0 ? weights.top : weights.side;
    const std::vector<int>& items = buffer.items[f];
    for (std::size_t cell = 0; cell < items.size(); ++cell)
      if (items[cell] >= 0) row.F[items[cell]] += delta[cell];
  }
  for (std::size_t j = 0; j < polygons.size(); ++j)
    if (buffer.footprint[j] > 0 && buffer.footprint[j] < 1) {
      ++row.sub_cell_receivers;
      row.sub_cell_missed += row.F[j] == 0;
      row.sub_cell_share += buffer.footprint[j];
    }
  const double r = weights.resolution;
  row.sub_cell_share /= 3 * r * r;  // a top face of r x r cells and four half faces
  return row;
}

}  // namespace

HemicubeRow hemicube_row(const std::vector<Polygon>& polygons, const Polygon& from, const HemicubeWeights& weights,
                         ItemBuffer& buffer) {
  check(from);
  return row_of(polygons, from, weights, buffer);
}

std::vector<double> form_factor_row_hemicube(const std::vector<Polygon>& polygons, const Polygon& from,
                                             const HemicubeWeights& weights, ItemBuffer& buffer) {
  check_all(polygons);
  return hemicube_row(polygons, from, weights, buffer).F;
}

FormFactorMatrix form_factor_matrix_hemicube(const std::vector<Polygon>& polygons, int resolution, int threads,
                                             HemicubeMatrixStats* stats) {
  check_all(polygons);
  const HemicubeWeights weights = hemicube_weights(resolution);
  const int n = static_cast<int>(polygons.size());
  FormFactorMatrix F{n, std::vector<double>(static_cast<std::size_t>(n) * n)};
  std::vector<HemicubeRow> counts(n);  // the rows' diagnostics, F left empty
  // Rows in blocks, so that each task reuses one item buffer's memory.
  const int block = 16, blocks = (n + block - 1) / block;
  parallel_for(blocks, threads, [&](int b) {
    ItemBuffer buffer;
    for (int i = b * block; i < std::min(n, (b + 1) * block); ++i) {
      HemicubeRow row = row_of(polygons, polygons[i], weights, buffer);
      std::copy(row.F.begin(), row.F.end(), F.values.begin() + static_cast<std::ptrdiff_t>(i) * n);
      counts[i] = {{}, row.sub_cell_receivers, row.sub_cell_missed, row.sub_cell_share};
    }
  });
  if (stats) {
    *stats = {};
    for (const HemicubeRow& row : counts) stats->add_row(row.sub_cell_receivers, row.sub_cell_missed, row.sub_cell_share);
  }
  return F;
}

}  // namespace gi
