#pragma once
#include "gi/accel/world.hpp"
#include "gi/pathtrace/lights.hpp"

namespace gi {

// What the path tracer renders: a World to cast rays into and the lights in it. A
// physical scene: surfaces reflect by their BSDF (bsdf.hpp), lights are surfaces with
// an emitted radiance (lights.hpp), rays that leave the scene see the sky, a constant
// radiance (the Scene's background). The Whitted model's point lights, no-falloff area
// lights and ambient term have no physical meaning; path_scenes.hpp translates the
// ray-tracing lessons' scenes.
struct PathScene {
  World world;
  Lights lights;
  const Scene& scene() const { return world.scene; }
};

// Throws std::invalid_argument for a scene with point lights or QuadLights (give the
// light an emitting surface instead), an emitting plane, or an invalid scene.
PathScene make_path_scene(Scene scene, Acceleration acceleration = Acceleration::Bvh);

}  // namespace gi
