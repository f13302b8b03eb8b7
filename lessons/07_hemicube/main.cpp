// Lesson 07 -- the hemicube. What a hemicube on a Cornell-box floor element sees (its
// item buffer, unfolded), the delta form factors of its cells, the whole form-factor
// matrix as a heat map and between whole objects, and how row sums, receivers smaller than a cell and
// reciprocity change with resolution.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/timer.hpp"
#include "gi/image/diff.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/form_factors/hemicube_image.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/progress.hpp"
#include "gi/report/table.hpp"

namespace {

// The floor element nearest (180, 0, 420): behind the short block, beside the tall one.
int floor_element(const gi::Mesh& mesh) {
  const gi::vec3 spot(180, 0, 420);
  int best = 0;
  for (int i = 0; i < static_cast<int>(mesh.elements.size()); ++i)
    if (mesh.elements[i].surface == 0 &&
        gi::length(mesh.elements[i].shape.centre - spot) < gi::length(mesh.elements[best].shape.centre - spot))
      best = i;
  return best;
}

// Each element in its surface's colour, brightness varied per element so that
// neighbours differ; the light white.
gi::Pixel element_colour(const gi::Mesh& mesh, int element) {
  if (element < 0) return gi::Pixel(0);
  const gi::Element& e = mesh.elements[element];
  if (gi::max_component(mesh.emission(e)) > 0) return gi::Pixel(1.0f, 0.85f, 0.2f);
  const unsigned hash = static_cast<unsigned>(element) * 2654435761u;
  const double shade = 0.25 + 0.5 * ((hash >> 16) & 255) / 255.0;
  const gi::Color rho = mesh.reflectance(e);
  return gi::Pixel(gi::max_component(rho) > 0 ? shade * rho / gi::max_component(rho) : gi::Color(0.15 * shade));
}

// 1. What one hemicube sees, and the weights of its cells.
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

// 4000000 as "4M", 40000 as "40000".
std::string rays_text(int rays) {
  return rays % 1'000'000 == 0 ? std::to_string(rays / 1'000'000) + "M" : std::to_string(rays);
}

// The L1 distance between two rows, relative to the reference's sum.
double row_error(const std::vector<double>& row, const std::vector<double>& reference) {
  double difference = 0, total = 0;
  for (std::size_t j = 0; j < row.size(); ++j) difference += std::abs(row[j] - reference[j]), total += reference[j];
  return difference / total;
}

// One row of a finely meshed box: the hemicube at resolution 100 against rays cast
// from the element (Monte Carlo: a tenth, a third and all of `most_rays`), both
// measured against a row of 40/3 as many rays (4 million for the default 300 000).
void speed_table(const gi::Mesh& mesh, int element, int most_rays, gi::Lesson& lesson) {
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const gi::Polygon& from = scene.polygons()[element];
  gi::FormFactorSettings reference_settings;
  reference_settings.method = gi::FormFactorMethod::MonteCarlo;
  reference_settings.rays = most_rays / 3 * 40;
  reference_settings.seed = lesson.seed();
  const std::vector<double> reference = gi::form_factor_row(scene, from, 999, reference_settings);
  gi::Table table("One row against " + std::to_string(scene.polygons().size()) +
                      " elements, one thread: time and L1 error against " + rays_text(reference_settings.rays) +
                      " rays (median of 7 rows)",
                  {{"method"}, {"samples"}, {"ms per row", 2}, {"rows per second", 0}, {"row error", 2, gi::Format::Scientific}});
  const auto measure = [&](const std::string& label, long long samples, const gi::FormFactorSettings& s) {
    std::vector<double> times;
    std::vector<double> row;
    for (int run = 0; run < 7; ++run) {
      const gi::Timer timer;
      row = gi::form_factor_row(scene, from, run, s);
      times.push_back(timer.milliseconds());
    }
    table.add_row({label, samples, gi::median(times), 1e3 / gi::median(times), row_error(row, reference)});
  };
  gi::FormFactorSettings hemicube;
  measure("hemicube, resolution 100", 3 * 100 * 100, hemicube);
  for (int rays : {most_rays / 10, most_rays / 3, most_rays}) {
    gi::FormFactorSettings mc = reference_settings;
    mc.rays = rays;
    measure("rays (Monte Carlo)", rays, mc);
  }
  std::cout << '\n';
  lesson.table(table, "speed");
}

// The object each element belongs to, named by its surface's first word: "short" for
// the short block's five faces, "ceiling" for the four pieces around the light.
std::vector<int> objects_of(const gi::Mesh& mesh, std::vector<std::string>& names) {
  std::vector<int> object;
  for (const gi::Element& e : mesh.elements) {
    const std::string& surface = mesh.surfaces[e.surface].name;
    const std::string name = surface.substr(0, surface.find(' '));
    const auto at = std::find(names.begin(), names.end(), name);
    object.push_back(static_cast<int>(at - names.begin()));
    if (at == names.end()) names.push_back(name);
  }
  return object;
}

// 2. The matrix as a heat map of log10 F_ij, white lines where one object's elements
// end and the next's begin (the mesh lists them surface by surface).
void matrix_picture(const gi::Mesh& mesh, const gi::FormFactorMatrix& F, int resolution, gi::Lesson& lesson) {
  std::vector<double> logs(F.values.size());
  for (std::size_t k = 0; k < logs.size(); ++k) logs[k] = F.values[k] > 0 ? std::log10(F.values[k]) : -8;
  gi::Image picture = gi::false_colour(logs, F.n, F.n, -6, -1);
  std::vector<std::string> names;
  const std::vector<int> object = objects_of(mesh, names);
  for (int i = 1; i < F.n; ++i)
    if (object[i] != object[i - 1])
      for (int k = 0; k < F.n; ++k) picture.at(i, k) = picture.at(k, i) = gi::Pixel(1);
  std::string order;
  for (const std::string& name : names) order += (order.empty() ? "" : ", ") + name;
  lesson.diagram(picture, "form_factor_matrix",
                 "log10 F_ij of the whole matrix (hemicube " + std::to_string(resolution) +
                     "), black below 1e-6 to red at 0.1; rows (from) and columns (to) in the order " + order +
                     ", white lines between them",
                 gi::ColourScale{1e-6, 0.1, "form factor F_ij", true});
}

// 3. The same matrix between whole objects: F_GH, the share of what leaves object G
// that lands on H (between_groups), and each row's sum: 1 in the closed box, less for
// the floor, whose elements buried under the blocks send nothing anywhere.
void object_table(const gi::Mesh& mesh, const gi::FormFactorMatrix& F, const std::vector<double>& areas,
                  int resolution, gi::Lesson& lesson) {
  std::vector<std::string> names;
  const std::vector<int> object = objects_of(mesh, names);
  const gi::FormFactorMatrix objects = gi::between_groups(F, areas, object, static_cast<int>(names.size()));
  std::vector<gi::Column> columns{{"from \\ to"}};
  for (const std::string& name : names) columns.push_back({name, 3});
  columns.push_back({"sum", 3});
  gi::Table table("Form factors between the closed box's objects (hemicube " + std::to_string(resolution) +
                      "): the share of the light leaving the row's object that lands on the column's",
                  columns);
  for (int g = 0; g < objects.n; ++g) {
    std::vector<gi::Cell> row(objects.n + 2, gi::Cell(names[g]));
    double sum = 0;
    for (int h = 0; h < objects.n; ++h) {
      row[h + 1] = objects(g, h);
      sum += objects(g, h);
    }
    row.back() = sum;
    table.add_row(row);
  }
  std::cout << '\n';
  lesson.table(table, "object_form_factors");
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

    hemicube_pictures(mesh, resolution, lesson);

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
    matrix_picture(mesh, shown, resolution, lesson);
    object_table(mesh, shown, areas, resolution, lesson);

    // 4. The speed figure: one row against a finely meshed box, one thread, and the
    // ray-cast rows that reach the same accuracy on the floor element of part 1.
    const gi::Mesh fine = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, speed_elements, 1), 1});
    speed_table(fine, floor_element(fine), speed_rays, lesson);
    lesson.say("\nimages: " + lesson.out().string() + "/ (item_buffer.png, delta_form_factors.png, form_factor_matrix.png)");
  });
}
