// Lesson 07, steps 2 and 3: the form-factor matrix as a picture and between whole objects (steps.hpp).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "steps.hpp"
#include "gi/image/diff.hpp"
#include "gi/report/table.hpp"

namespace lesson07 {
namespace {

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

}  // namespace

// The white lines sit where one object's elements end and the next's begin: the mesh
// lists them surface by surface, so each object's elements are one run of rows (and
// columns), named beside them.
void matrix_picture(const gi::Mesh& mesh, const gi::FormFactorMatrix& F, int resolution, gi::Lesson& lesson) {
  std::vector<double> logs(F.values.size());
  for (std::size_t k = 0; k < logs.size(); ++k) logs[k] = F.values[k] > 0 ? std::log10(F.values[k]) : -8;
  gi::MatrixChart chart;
  chart.title = "The form-factor matrix, element by element (hemicube " + std::to_string(resolution) + ")";
  chart.picture = gi::false_colour(logs, F.n, F.n, -6, -1);
  std::vector<std::string> names;
  const std::vector<int> object = objects_of(mesh, names);
  for (int i = 0; i < F.n; ++i)
    if (i == 0 || object[i] != object[i - 1]) {
      chart.groups.push_back(names[object[i]]);
      chart.starts.push_back(i);
      for (int k = 0; k < F.n && i > 0; ++k) chart.picture.at(i, k) = chart.picture.at(k, i) = gi::Pixel(1);
    }
  lesson.diagram(chart, "form_factor_matrix",
                 "F_ij of the whole matrix (hemicube " + std::to_string(resolution) + ", " + std::to_string(F.n) +
                     " elements): row i is what leaves element i, column j where it lands; black below 1e-6, white "
                     "lines between objects",
                 gi::ColourScale{1e-6, 0.1, "form factor F_ij", true});
}

// F_GH, the share of what leaves object G
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

  // The same table as a heat map, each cell's value written in it.
  double largest = 0;
  for (double f : objects.values) largest = std::max(largest, f);
  const double top = std::max(0.1, std::ceil(10 * largest) / 10);
  gi::MatrixChart chart;
  chart.title = "Form factors between objects (hemicube " + std::to_string(resolution) + ")";
  chart.picture = gi::false_colour(objects.values, objects.n, objects.n, 0, top);
  chart.groups = names;
  for (int g = 0; g < objects.n; ++g) {
    chart.starts.push_back(g);
    for (int h = 0; h < objects.n; ++h) chart.cells.push_back(gi::format_number(objects(g, h), 3, gi::Format::Fixed));
  }
  lesson.diagram(chart, "object_form_factors_map",
                 "F_GH between the closed box's objects, the share of what leaves the row's object that lands on the "
                 "column's: the table above as a heat map",
                 gi::ColourScale{0, top, "form factor F_GH", false});
}

}  // namespace lesson07
