#include "gi/pathtrace/path_scene.hpp"

#include <stdexcept>
#include <utility>

namespace gi {

PathScene make_path_scene(Scene scene, Acceleration acceleration) {
  check(scene);
  if (!scene.lights.empty() || !scene.area_lights.empty())
    throw std::invalid_argument("scene '" + scene.name +
                                "': the path tracer's lights are emitting surfaces, not point lights or QuadLights "
                                "(make the light a quad or sphere with an emission; see path_scenes.hpp)");
  Lights lights = find_lights(scene);  // before the World takes the scene: it gives lights materials
  return PathScene{make_world(std::move(scene), acceleration), std::move(lights)};
}

}  // namespace gi
