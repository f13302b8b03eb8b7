#pragma once
// Lesson 14: what each picture is measured against -- the converged Cornell box kept in
// the tree, a reference rendered here once for any other scene, or the white furnace's
// closed form (reference.cpp).
#include "converge.hpp"
#include "gi/pathtrace/path_scene.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/report/lesson.hpp"

namespace lesson14 {

// The Cornell box, square at a size that divides 256, to the default depth, is measured against
// the converged picture kept in the tree (lessons/references/), averaged down.
bool uses_stored_reference(const Settings& s);

// Any other scene or size: a reference rendered here once and kept in the output folder
// (render/truth.hpp), reused while the scene, the sample count and the path tracer's
// code are the same.
gi::Truth own_reference(const gi::PathScene& scene, const Settings& s, gi::Lesson& lesson);

// The white furnace (a closed box, every wall rho = 0.5 emitting L_e = 1): its exact
// picture is L_e (1 + rho + ... + rho^D) everywhere, an independent reference.
gi::Truth furnace_truth(const Settings& s);

}  // namespace lesson14
