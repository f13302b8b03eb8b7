#pragma once
// Lesson 07, its steps beside main.cpp: the hemicube's pictures (hemicube_pictures.cpp),
// the matrix as a picture and between whole objects (objects.cpp), and the speed of
// one row (speed.cpp).
#include <vector>

#include "gi/radiosity/mesh/mesh.hpp"
#include "gi/radiosity/system/form_factor_matrix.hpp"
#include "gi/report/lesson.hpp"

namespace lesson07 {

// The floor element nearest (180, 0, 420): behind the short block, beside the tall one.
int floor_element(const gi::Mesh& mesh);

// 1. What one hemicube on the floor element sees, and the weights of its cells.
void hemicube_pictures(const gi::Mesh& mesh, int resolution, gi::Lesson& lesson);

// 2. The matrix as a heat map of log10 F_ij, white lines between objects.
void matrix_picture(const gi::Mesh& mesh, const gi::FormFactorMatrix& F, int resolution, gi::Lesson& lesson);

// 3. The matrix between whole objects, F_GH, with each row's sum.
void object_table(const gi::Mesh& mesh, const gi::FormFactorMatrix& F, const std::vector<double>& areas,
                  int resolution, gi::Lesson& lesson);

// 4. One row of a finely meshed box: the hemicube against rays, time and error.
void speed_table(const gi::Mesh& mesh, int element, int most_rays, gi::Lesson& lesson);

}  // namespace lesson07
