#pragma once
#include <array>
#include <string>
#include <vector>

#include "gi/scene/scene.hpp"

namespace gi {

// The Cornell box (www.graphics.cornell.edu/online/box/data.html) as plain data, read
// by both halves of the course: radiosity meshes it (radiosity_scenes.hpp), the path
// tracer renders it, so the two solve exactly the same scene. Its measured geometry
// is in millimetres, as published:
//  - the camera looks along +z with +y up from (278, 273, -800); in our right-handed
//    camera, +x is then on the image's left, so the red wall at x ~ 556 is on the
//    left, as in the photographs;
//  - the floor, ceiling and left wall are not rectangles (x runs 549.6 to 556), kept
//    as given: every surface is a general quadrilateral, and the red wall is slightly
//    twisted (its fourth corner is 3.2 mm off the plane of the other three);
//  - the light is flush with the ceiling; the ceiling is cut into four pieces around
//    it so that nothing overlaps;
//  - the box is open at the front (z = 0), where the camera looks in. `closed` adds a
//    black front wall (rho = 0), which absorbs exactly what the opening lets out but
//    makes every row of form factors sum to 1: the form of the box to test
//    conservation on.

// A flat (or nearly flat) quadrilateral, ideally diffuse (Lambertian).
struct QuadSurface {
  std::string name;
  std::array<vec3, 4> corners;  // counter-clockwise seen from the lit side
  Color reflectance;            // rho in [0, 1]
  Color exitance{0.0};          // E, W/m^2 per channel; a Lambertian emitter's radiance is L = E / pi
};

// Every reflectance and the light's emission, in this one place: the surfaces below
// take theirs from here, so radiosity and the path tracer always see the same box.
struct CornellPalette {
  Color white, red, green;
  Color light_reflectance;  // the light's own surface
  Color light_exitance;     // E = pi L
  Color mirror;             // the mirror sphere's reflectance (the spheres variant)
  double glass_ior;         // the glass sphere's index of refraction
};

// Which published numbers the palette takes (cornell_spectra.hpp for the data):
//  - Published (the default): the band means of the measured spectra over
//    R = [600, 700], G = [500, 600], B = [400, 500] nm: white (0.734, 0.736, 0.706),
//    red (0.581, 0.088, 0.057), green (0.132, 0.348, 0.117);
//  - McGuire: the RGB set of Morgan McGuire's Computer Graphics Archive box, which
//    many renderers share: white (0.725, 0.71, 0.68), red (0.63, 0.065, 0.05),
//    green (0.14, 0.45, 0.091).
enum class CornellReflectances { Published, McGuire };
//  - Published (the default): the light's emission spectrum's band means taken as
//    radiance, L = (17.0, 11.8, 4.0), E = pi L (McGuire's light is these rounded);
//  - WhiteUnitExitance: E = 1 in every channel, for tests with round numbers.
enum class CornellLight { Published, WhiteUnitExitance };

struct CornellPaletteChoice {
  CornellReflectances reflectances = CornellReflectances::Published;
  CornellLight light = CornellLight::Published;
  // The data gives the light's surface a reflectance of 0.78; most renderings of the
  // box (and ours by default) make it black. With it on, the light also reflects the
  // light that falls on it back from the floor: the box is slightly brighter.
  bool light_reflects = false;
};
CornellPalette cornell_palette(const CornellPaletteChoice& choice = {});

// What stands on the floor: the two blocks of the data, or (for the lessons that
// need specular surfaces) a mirror sphere at the back left and a glass sphere at the
// front right instead.
enum class CornellContents { Blocks, Spheres };

struct CornellSphere {
  std::string name;
  vec3 centre;
  double radius;
  bool glass;  // false: a mirror
};

struct CornellBox {
  std::vector<QuadSurface> surfaces;
  std::vector<CornellSphere> spheres;  // CornellContents::Spheres only
  Camera camera;
};
CornellBox cornell_box_data(CornellContents contents = CornellContents::Blocks, bool closed = false,
                            const CornellPalette& palette = cornell_palette());

// The same box as a Scene of triangles, for the ray tracers: each quadrilateral with
// corners c0..c3 is the triangles (c0, c1, c2) and (c0, c2, c3), the split radiosity
// casts its rays into (form_factors.hpp). Materials: Lambertian reflectance
// `diffuse` = rho, emission = radiance L = E / pi (only the light), black background;
// the spheres' materials are `mirror` and `transmission` with `ior`.
Scene cornell_box_scene(const CornellBox& box, const CornellPalette& palette = cornell_palette());

}  // namespace gi
