// Lesson 13, step 2: the uniform meshes beside the hierarchy (steps.hpp).
#include "steps.hpp"

#include <vector>

#include "gi/core/timer.hpp"
#include "gi/radiosity/display/direct_display.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"
#include "gi/radiosity/recipe.hpp"
#include "gi/report/table.hpp"

namespace lesson13 {

// 3. Uniform meshes as lesson 12 seats them (exact direct light, hemicube sized to the
// mesh, Gauss-Seidel), shown both ways: error against whole time, mesh to B.
void uniform_meshes(const Setup& s, gi::Chart& chart, gi::Lesson& lesson) {
  gi::Table table("Uniform meshes, exact direct + hemicube, Gauss-Seidel to 1e-5; against the same truth",
                  {{"elements"}, {"light"}, {"s", 2}, {"error %", 2}});
  gi::Series exact{"uniform, exact direct", {}, {}}, pixel{"uniform, direct per pixel", {}, {}};
  for (const int elements : {s.uniform_elements / 4, s.uniform_elements}) {
    gi::Recipe recipe;
    recipe.elements = elements;
    recipe.form_factors.hemicube_resolution = 0;  // from the mesh
    const gi::RecipeResult r = gi::solve_recipe(s.scene.surfaces, recipe, s.threads);
    const gi::FormFactorScene shapes(gi::element_shapes(r.mesh));
    const gi::Image mesh_picture =
        gi::render_radiosity_picture(shapes, r.mesh, r.B, s.scene.camera, s.display, s.seed, s.threads).radiance;
    const gi::Timer timer;
    const std::vector<gi::Color> rest = gi::indirect_part(r.mesh, r.B, r.direct), at_vertices = gi::vertex_radiosity(r.mesh, rest);
    const gi::MeshRadiance bounced{shapes, r.mesh, rest, at_vertices, gi::Shading::Smooth};
    const gi::Image picture =
        gi::render_display(gi::sum_of(*s.direct, bounced), s.scene.camera, s.display, s.seed, s.threads).radiance;
    const double per_pixel = timer.seconds();
    const int n = static_cast<int>(r.mesh.elements.size());
    const double e_mesh = gi::picture_error(mesh_picture, s.truth, s.mask).relative_rms;
    const double e_pixel = gi::picture_error(picture, s.truth, s.mask).relative_rms;
    table.add_row({n, "exact direct", r.seconds(), 100 * e_mesh});
    table.add_row({n, "direct per pixel", r.seconds() + per_pixel, 100 * e_pixel});
    exact.x.push_back(r.seconds()), exact.y.push_back(100 * e_mesh);
    pixel.x.push_back(r.seconds() + per_pixel), pixel.y.push_back(100 * e_pixel);
  }
  lesson.table(table, "uniform");
  chart.series.push_back(exact), chart.series.push_back(pixel);
}

}  // namespace lesson13
