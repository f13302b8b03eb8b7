// Lesson 06, step 6: one row of the Cornell box's form-factor matrix, painted on the
// room (studies.hpp).
#include <cmath>
#include <string>
#include <vector>

#include "gi/image/diff.hpp"
#include "gi/radiosity/display/element_values.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/report/table.hpp"
#include "studies.hpp"

namespace lesson06 {

// From a floor element in the open, between the blocks and in front of the tall one
// (white), F to every element of a 1000-element Cornell box, by the hemicube (which sees what the blocks hide) and by the
// analytic contour integral (exact for each pair, blind to what stands between). The
// pictures differ only where a block stands between the white element and a wall, and
// the row sums say by how much: 1 for a closed room, more where light is counted twice.
void one_row(const gi::FormFactorSettings& base, gi::Lesson& lesson) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 1000, 1), 1});
  const gi::FormFactorScene shapes(gi::element_shapes(mesh));
  // The floor's extent, and the element nearest the point 70% of the way across it and
  // 20% of the way back from its front edge: in the camera's view, under no block.
  gi::vec3 lo(1e300), hi(-1e300);
  for (const gi::Element& e : mesh.elements)
    if (mesh.surfaces[e.surface].name == "floor") lo = glm::min(lo, e.shape.centre), hi = glm::max(hi, e.shape.centre);
  const gi::vec3 open_floor = lo + gi::vec3(0.7, 0, 0.2) * (hi - lo);
  int from = -1;
  for (int i = 0; i < static_cast<int>(mesh.elements.size()); ++i)
    if (mesh.surfaces[mesh.elements[i].surface].name == "floor" &&
        (from < 0 || gi::length(mesh.elements[i].shape.centre - open_floor) <
                         gi::length(mesh.elements[from].shape.centre - open_floor)))
      from = i;

  std::vector<gi::Image> pictures;
  std::string sums;
  for (gi::FormFactorMethod method : {gi::FormFactorMethod::Hemicube, gi::FormFactorMethod::Analytic}) {
    gi::FormFactorSettings settings = base;
    settings.method = method;
    const std::vector<double> F = gi::form_factor_row(shapes, mesh.elements[from].shape, from, settings);
    double sum = 0;
    for (double f : F) sum += f;
    sums += (sums.empty() ? "" : ", ") + gi::name(method) + " " + gi::format_number(sum, 3, gi::Format::Fixed);
    pictures.push_back(gi::render_element_values(mesh, F, scene.camera, 320, 320, 1e-5, 1e-2, true, lesson.threads(),
                                                 from));
  }
  lesson.say("one row of the Cornell box's matrix, from floor element " + std::to_string(from) + " of " +
             std::to_string(mesh.elements.size()) + ": row sums " + sums);
  lesson.diagram(gi::side_by_side(pictures), "one_row",
                 "F from the white floor element to every element of the Cornell box: by the hemicube (left), "
                 "which sees what the blocks hide, and by the analytic integral (right), exact for each pair but "
                 "blind to what stands between",
                 gi::ColourScale{1e-5, 1e-2, "form factor F_ij", true});
}

}  // namespace lesson06
