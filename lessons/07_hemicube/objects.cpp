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
// lists them surface by surface.
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
}

}  // namespace lesson07
