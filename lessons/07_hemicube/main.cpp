// Lesson 07 -- the hemicube. What a hemicube on a Cornell-box floor element sees (its
// item buffer, unfolded), the delta form factors of its cells, the whole form-factor
// matrix as a heat map and between whole objects, how row sums, receivers smaller
// than a cell and reciprocity change with resolution, and the speed of one row.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "steps.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"

namespace {

// Reciprocity over the whole matrix: sum |A_i F_ij - A_j F_ji| / sum A_i F_ij. The
// worst single pair (gi::reciprocity_error) is ruled by pairs one centre sees and the
// other does not -- point sampling's error, not the rasteriser's.
double total_reciprocity_error(const gi::FormFactorMatrix& F, const std::vector<double>& areas) {
  double difference = 0, total = 0;
  for (int i = 0; i < F.n; ++i)
    for (int j = 0; j < F.n; ++j) {
      difference += std::abs(areas[i] * F(i, j) - areas[j] * F(j, i));
      total += areas[i] * F(i, j);
    }
  return difference / total;
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("07_hemicube", "The hemicube: item buffer, delta form factors, the form-factor matrix, and "
                                   "row sums and reciprocity against resolution (Cornell box).");
  int elements = 600, resolution = 100, max_resolution = 200, speed_elements = 10000, speed_rays = 300'000;
  lesson.options()
      .add("--elements", elements, "about how many elements to mesh the Cornell box into", 20, 5000)
      .add("--resolution", resolution, "hemicube resolution for the pictures", 10, 1000, gi::even)
      .add("--max-resolution", max_resolution, "largest resolution in the table (400 adds a row that takes longer than all the others)", 10, 1000, gi::even)
      .add("--speed-elements", speed_elements, "elements for the one-row timing", 100, 100000)
      .add("--speed-rays", speed_rays, "most rays of a Monte Carlo row in the timing (also a tenth and a third of it; the reference row 40/3 of it)", 300, 1'000'000);
  return lesson.run(argc, argv, [&] {
    const gi::RadiosityScene scene = gi::cornell_box(true);  // closed: rows must sum to 1
    const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, elements, 1), 1});
    const std::vector<gi::Polygon> shapes = gi::element_shapes(mesh);
    std::vector<double> areas;
    for (const gi::Polygon& p : shapes) areas.push_back(p.area);

    lesson07::hemicube_pictures(mesh, resolution, lesson);

    gi::Table table("Hemicube resolution against row sums (1 in a closed room), receivers smaller than a cell, and "
                    "reciprocity; closed Cornell box, " + std::to_string(shapes.size()) + " elements",
                    {{"resolution"}, {"cells"}, {"matrix ms", 0}, {"buried"}, {"max |1 - sum|", 1, gi::Format::Scientific},
                     {"dF sum before scaling", 6}, {"sub-cell receivers"}, {"in rows"}, {"got nothing"},
                     {"reciprocity", 2, gi::Format::Scientific}});
    std::vector<int> resolutions;
    for (int r : {10, 20, 50, 100, 200, 400})
      if (r <= max_resolution) resolutions.push_back(r);
    gi::FormFactorMatrix shown;  // the matrix at the pictures' resolution
    gi::Progress progress("hemicubes", static_cast<long long>(resolutions.size()));
    for (int r : resolutions) {
      const gi::Timer timer;
      gi::HemicubeMatrixStats stats;
      const gi::FormFactorMatrix F = gi::form_factor_matrix_hemicube(shapes, r, lesson.threads(), &stats);
      const double ms = timer.milliseconds();
      progress.advance();
      // Floor elements whose centre lies under a block see only the block's inside
      // (back faces): their rows are 0. The statistics leave them out.
      std::vector<double> sums;
      for (double s : gi::row_sums(F))
        if (s > 0.5) sums.push_back(s);
      double deviation = 0;
      for (double s : sums) deviation = std::max(deviation, std::abs(1 - s));
      table.add_row({r, 3 * r * r, ms, static_cast<long long>(F.n - sums.size()), std::max(deviation, 1e-17),
                     gi::hemicube_weights(r).unnormalised_sum, stats.sub_cell_receivers,
                     stats.rows_with_sub_cell_receivers, stats.sub_cell_missed, total_reciprocity_error(F, areas)});
      if (r == resolution) shown = F;
    }
    progress.finish();
    // The picture's resolution is not one of the table's: its matrix is made for the picture alone.
    if (std::find(resolutions.begin(), resolutions.end(), resolution) == resolutions.end())
      shown = gi::form_factor_matrix_hemicube(shapes, resolution, lesson.threads());
    lesson.table(table, "resolution");
    lesson07::matrix_picture(mesh, shown, resolution, lesson);
    lesson07::object_table(mesh, shown, areas, resolution, lesson);

    // 4. The speed figure: one row against a finely meshed box, one thread, and the
    // ray-cast rows that reach the same accuracy on the floor element of part 1.
    const gi::Mesh fine = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, speed_elements, 1), 1});
    lesson07::speed_table(fine, lesson07::floor_element(fine), speed_rays, lesson);
    lesson.say("\nimages: " + lesson.out().string() +
               "/ (item_buffer.png, delta_form_factors.png, form_factor_matrix.svg, object_form_factors_map.svg)");
  });
}
