#pragma once
#include <vector>

#include "gi/radiosity/form_factor_matrix.hpp"

#include "gi/radiosity/item_buffer.hpp"

namespace gi {

// One row of the form-factor matrix by the hemicube: render every polygon into the
// item buffer of a hemicube on `from`'s centre, then add up the delta form factors
// of the cells each polygon covers: F_from,j = sum over j's cells of dF.
// `weights` must be of the resolution wanted; `buffer` is scratch memory kept between rows.
std::vector<double> form_factor_row_hemicube(const std::vector<Polygon>& polygons, const Polygon& from,
                                             const HemicubeWeights& weights, ItemBuffer& buffer);

// The whole matrix, one hemicube per polygon, rows in parallel on `threads` threads
// (0: all cores). Each row depends only on the geometry: the same matrix for any
// thread count.
FormFactorMatrix form_factor_matrix_hemicube(const std::vector<Polygon>& polygons, int resolution, int threads);

}  // namespace gi
