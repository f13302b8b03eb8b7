// Lesson 16 -- two-pass rendering: radiosity for the view-independent diffuse
// interreflection, ray tracing for what depends on the view (Chen, Rushmeier, Miller
// and Turner 1991). Pass 1 solves the diffuse surfaces by progressive radiosity; pass 2
// traces eye rays through mirror and glass and, at the first diffuse surface, adds
// direct light by shadow rays to the indirect light from the mesh -- read off it, or
// gathered one bounce later. Every picture against the converged path-traced one.
#include <optional>
#include <string>
#include <vector>

#include "gi/core/samplers/sample_stream.hpp"
#include "gi/core/timer.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/display/display.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"
#include "gi/twopass/picture_mask.hpp"
#include "gi/twopass/radiosity_pass.hpp"
#include "gi/twopass/two_pass.hpp"
#include "pictures.hpp"
#include "where_each_fails.hpp"

namespace {

using lesson16::Picture;
using lesson16::Settings;

gi::View view_of(const gi::TwoPassScene& scene, const Settings& s) {
  const std::string n = std::to_string(s.eye.samples);
  return {scene.camera, s.width, s.height, n + " x " + n + " jittered eye rays, box filter"};
}

// The converged path-traced picture kept in lessons/references/ (14_make_reference),
// averaged down to the lesson's size; nothing if there is none of that size (its side
// is not a multiple of the picture's). Throws std::runtime_error if it is damaged.
std::optional<gi::Truth> stored_truth(const Settings& s) {
  const int side = gi::stored_truth_side(s.scene).value();
  if (s.width != s.height || side % s.width != 0) return std::nullopt;
  return gi::stored_truth(s.references, s.scene, s.width, s.height);
}

// Radiosity alone: the mesh's B / pi through every pixel (display.hpp), smooth shading.
// The mesh has no spheres: they are shadows on the walls and nothing else.
Picture radiosity_alone(const Settings& s, const gi::TwoPassScene& scene, const gi::RadiosityPass& pass) {
  gi::DisplaySettings display;
  display.width = s.width, display.height = s.height, display.samples = s.eye.samples;
  const gi::Timer timer;
  const gi::FormFactorScene elements(gi::element_shapes(pass.handoff.mesh));
  gi::Image radiosity =
      gi::render_radiosity_picture(elements, pass.handoff.mesh, pass.handoff.B, scene.camera, display, s.seed,
                                   s.threads)
          .radiance;
  return {"radiosity alone", std::move(radiosity), pass.seconds(), timer.seconds()};
}

// 1. The four pictures: the ray tracer alone, radiosity alone, and the two passes with
//    the indirect light read off the mesh and gathered. Pass 1 is shared by the last three.
std::vector<Picture> render_all(const Settings& s, const gi::TwoPassScene& scene, const gi::RadiosityPass& pass,
                                gi::Lesson& lesson) {
  std::vector<Picture> pictures;
  const auto eye_pass = [&](gi::IndirectLight indirect, double pass1) {
    gi::TwoPassSettings eye = s.eye;
    eye.indirect = indirect;
    const gi::Timer timer;
    gi::Image picture = gi::render_two_pass(scene, pass.handoff, eye, s.seed, s.threads);
    return Picture{"", std::move(picture), pass1, timer.seconds()};
  };
  pictures.push_back(eye_pass(gi::IndirectLight::Ambient, 0));
  pictures.back().method = "ray traced, constant ambient";

  pictures.push_back(radiosity_alone(s, scene, pass));

  pictures.push_back(eye_pass(gi::IndirectLight::Mesh, pass.seconds()));
  pictures.back().method = "two-pass, indirect from the mesh";
  pictures.push_back(eye_pass(gi::IndirectLight::FinalGather, pass.seconds()));
  pictures.back().method = "two-pass, final gather";

  const gi::View view = view_of(scene, s);
  const char* stems[] = {"ray_traced", "radiosity", "two_pass_mesh", "two_pass_gather"};
  for (std::size_t i = 0; i < pictures.size(); ++i)
    lesson.picture(pictures[i].radiance, s.scene + "_" + stems[i], pictures[i].method, view, 2);
  return pictures;
}

// 2. Each picture against the path-traced truth: over the interior blocks of the
//    diffuse surfaces (picture_mask.hpp), and over the whole picture in 8 x 8 blocks
//    (edges, the light and the spheres included).
void score(const Settings& s, const gi::TwoPassScene& scene, const std::vector<Picture>& pictures,
           const gi::Truth& truth, const gi::BlockMask& mask, gi::Lesson& lesson) {
  const gi::PictureError noise = gi::reference_noise(truth.standard_error, truth.mean, mask);
  gi::Table table("The " + scene.name + " box against the path-traced truth (" + std::to_string(truth.spp) +
                      " spp; its own noise " + gi::format_number(100 * noise.relative_rms, 2, gi::Format::Fixed) +
                      "% on the " + std::to_string(mask.count()) + " interior 8x8 blocks)",
                  {{"method"}, {"pass 1 s", 2}, {"pass 2 s", 2}, {"total s", 2},
                   {"interior relative RMS %", 2}, {"interior block relative %", 2}, {"whole picture 8x8 %", 2}});
  for (const Picture& p : pictures) {
    const gi::PictureError e = gi::picture_error(p.radiance, truth.mean, mask);
    table.add_row({p.method, p.pass1_seconds, p.pass2_seconds, p.pass1_seconds + p.pass2_seconds,
                   100 * e.relative_rms, 100 * e.block_relative,
                   100 * gi::relative_rms_error(p.radiance, truth.mean, 8)});
  }
  lesson.table(table, s.scene + "_against_truth");
}

// 3. The claim: on the diffuse box, two-pass with the final gather is closer to the
//    truth than radiosity alone given the same time. Radiosity alone on twice the
//    elements takes about as long as the gather does on this box (pass 1's time grows a
//    little faster than n), so the two rows set side by side are an equal-time
//    comparison whose times the table shows; a search for the mesh that takes exactly
//    as long would make the rows depend on the machine's load, and cost several passes.
void equal_time(const Settings& s, const gi::TwoPassScene& scene, const Picture& gather, int elements,
                const gi::Image& truth, const gi::BlockMask& mask, gi::Lesson& lesson) {
  gi::Table table("About equal time on the diffuse box: radiosity alone on twice the elements beside two-pass with "
                  "the final gather",
                  {{"method"}, {"elements"}, {"total s", 2}, {"interior relative RMS %", 2}});
  const gi::PictureError g = gi::picture_error(gather.radiance, truth, mask);
  table.add_row({gather.method, elements, gather.pass1_seconds + gather.pass2_seconds, 100 * g.relative_rms});
  gi::RadiosityPassSettings finer = s.radiosity;
  finer.elements *= 2;
  const gi::RadiosityPass pass = gi::radiosity_pass(scene, finer, s.threads);
  const Picture alone = radiosity_alone(s, scene, pass);
  table.add_row({alone.method, static_cast<int>(pass.handoff.mesh.elements.size()),
                 alone.pass1_seconds + alone.pass2_seconds,
                 100 * gi::picture_error(alone.radiance, truth, mask).relative_rms});
  lesson.table(table, "equal_time");
}

// Everything above for one scene.
void two_pass_lesson(const Settings& s, const std::optional<gi::Truth>& truth, gi::Lesson& lesson) {
  const gi::TwoPassScene scene = gi::make_two_pass_scene(s.scene);
  const gi::RadiosityPass pass = gi::radiosity_pass(scene, s.radiosity, s.threads);
  lesson.say(s.scene + ", pass 1: " + std::to_string(pass.handoff.mesh.elements.size()) + " elements, hemicube " +
             std::to_string(pass.hemicube_resolution) + ", " + std::to_string(pass.shots) + " shots, " +
             gi::status_name(pass.status));
  const std::vector<Picture> pictures = render_all(s, scene, pass, lesson);
  if (!truth) {
    const std::string side = std::to_string(gi::stored_truth_side(s.scene).value());
    lesson.say("no path-traced picture of " + s.scene + " to score against (the stored truth is " + side + " x " +
               side + ": a square size that divides it is scored)");
    return;
  }
  const gi::View view{scene.camera, s.width, s.height, "the stored reference, averaged down"};
  lesson.picture(truth->mean, s.scene + "_path_traced", "the path-traced truth (lessons/references/)", view, 2);
  const gi::BlockMask mask = gi::diffuse_interior_blocks(scene, s.width, s.height, 8);
  if (mask.count() == 0) {
    lesson.say("no 8x8 block of " + s.scene + " lies inside one diffuse surface at this size: nothing to score");
    return;
  }
  score(s, scene, pictures, *truth, mask, lesson);
  if (scene.spheres.empty())
    equal_time(s, scene, pictures.back(), static_cast<int>(pass.handoff.mesh.elements.size()), truth->mean, mask,
               lesson);
  lesson16::where_each_fails(s, pictures, truth->mean, lesson);  // 4. where_each_fails.cpp
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("16_two_pass", "Two-pass rendering: radiosity for the diffuse interreflection, ray tracing for "
                                   "mirrors, glass and sharp shadows, scored against the path-traced truth.");
  Settings s;
  std::string sequence = "independent";  // --sampler: sample_stream.hpp
  lesson.add_image_size(s.width, s.height);
  lesson.options()
      .add("--scene", s.scene, "what to render: both boxes, or one", {"both", "cornell", "cornell-spheres"})
      .add("--elements", s.radiosity.elements, "about how many radiosity elements", 10, 20000)
      .add("--samples", s.eye.samples, "n x n eye rays per pixel", 1, 16)
      .add("--light-cells", s.eye.light_cells, "n x n shadow rays per light at each diffuse hit", 1, 64)
      .add("--gather", s.eye.gather_strata, "n x n final-gather rays at each diffuse hit", 1, 64)
      .add("--references", s.references, "the folder of the stored path-traced truths (SCENE_SIDExSIDE.*)")
      .add("--sampler", sequence,
           "the numbers the eye rays and shadow rays read (the final gather, exercise 16.2, reads the pixel's own)",
           gi::sequence_option_names());
  // Before any work: a damaged or stale truth stops the lesson in one line.
  std::vector<std::pair<Settings, std::optional<gi::Truth>>> boxes;
  lesson.add_check([&] {
    s.eye.sequence = gi::sequence_from_name(sequence);
    for (const std::string& name : s.scene == "both" ? gi::two_pass_scene_names() : std::vector<std::string>{s.scene}) {
      Settings one = s;
      one.scene = name;
      boxes.emplace_back(one, stored_truth(one));
    }
  });
  return lesson.run(argc, argv, [&] {
    for (auto& [one, truth] : boxes) {
      one.threads = lesson.threads();
      one.seed = one.radiosity.seed = lesson.seed();
      one.eye.width = one.width, one.eye.height = one.height;
      one.radiosity.form_factors.hemicube_resolution = 0;  // from the mesh
      two_pass_lesson(one, truth, lesson);
    }
  });
}
