// The two passes together: the furnace's closed form, the path-traced Cornell box, and
// the same bytes for any thread count.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "gi/core/hash.hpp"
#include "gi/pathtrace/path_scenes.hpp"
#include "gi/pathtrace/path_truth.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/twopass/picture_mask.hpp"
#include "gi/twopass/radiosity_pass.hpp"
#include "gi/twopass/two_pass.hpp"

namespace {

// The closed unit cube, every wall reflecting rho = 0.5 and emitting E = 1, seen from
// its centre: L = E / (pi (1 - rho)) = 2 / pi everywhere. Every wall is a light, so
// the shadow rays, the direct part D and the mesh's B - E - D all take part.
gi::TwoPassScene furnace() {
  gi::TwoPassScene s;
  s.name = "furnace";
  s.surfaces = gi::closed_box(1.0).surfaces;
  for (gi::Surface& f : s.surfaces) f.reflectance = gi::Color(0.5), f.emission = gi::Color(1.0);
  s.camera = gi::Camera{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.0}, {0, 1, 0}, 90};
  return s;
}

gi::RadiosityPassSettings small_pass(int elements) {
  gi::RadiosityPassSettings p;
  p.elements = elements;
  p.tolerance = 1e-6;
  return p;
}

TEST(TwoPass, TheFurnaceGivesItsClosedFormEitherWay) {
  // Each pixel is an independent estimate; their mean within 5 standard errors plus
  // the solver's 1e-4 (a false failure about once in 10^6 runs). Counting the direct
  // light twice would add rho E / pi = 0.16, about 25%.
  const gi::TwoPassScene scene = furnace();
  const gi::RadiosityPass pass = gi::radiosity_pass(scene, small_pass(150), 0);
  ASSERT_EQ(pass.status, gi::SolveStatus::Converged);
  for (gi::IndirectLight indirect : {gi::IndirectLight::Mesh, gi::IndirectLight::FinalGather}) {
    gi::TwoPassSettings s;
    s.width = s.height = 24, s.samples = 1, s.gather_strata = 2, s.indirect = indirect;
    const gi::Image picture = gi::render_two_pass(scene, pass.handoff, s, 1, 0);
    double sum = 0, sum2 = 0;
    for (const gi::Pixel& p : picture.pixels) sum += p.x, sum2 += double(p.x) * p.x;
    const double n = picture.pixels.size(), mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    EXPECT_NEAR(mean, 2 / gi::pi, 5 * se + 1e-4 * 2 / gi::pi) << gi::name(indirect);
  }
}

TEST(TwoPass, TheDiffuseBoxAgreesWithThePathTracedReference) {
  // The stored reference (11 264 spp) averaged down to 64 x 64, over the 86 interior
  // 4 x 4 blocks: measured 1.2% (mesh) and 1.5% (gather) with 600 elements. A bound of
  // 3% still catches direct light counted twice (tens of per cent), a missing cosine or
  // a wrong B - E - D.
  const gi::TwoPassScene scene = gi::make_two_pass_scene("cornell");
  const gi::Truth small = gi::stored_truth(std::string(GI_SOURCE_DIR) + "/lessons/references", "cornell", 64, 64);
  const gi::BlockMask mask = gi::diffuse_interior_blocks(scene, 64, 64, 4);
  ASSERT_GE(mask.count(), 10);
  gi::RadiosityPassSettings p = small_pass(600);
  p.tolerance = 1e-4;
  const gi::RadiosityPass pass = gi::radiosity_pass(scene, p, 0);
  for (gi::IndirectLight indirect : {gi::IndirectLight::Mesh, gi::IndirectLight::FinalGather}) {
    gi::TwoPassSettings s;
    s.width = s.height = 64, s.indirect = indirect;
    const gi::PictureError e = gi::picture_error(gi::render_two_pass(scene, pass.handoff, s, 1, 0), small.mean, mask);
    EXPECT_LT(e.relative_rms, 0.03) << gi::name(indirect);
  }
}

TEST(TwoPass, SameBytesForAnyThreadCount) {
  const gi::TwoPassScene scene = gi::make_two_pass_scene("cornell-spheres");
  gi::RadiosityPassSettings p = small_pass(200);
  p.tolerance = 1e-3;
  const gi::RadiosityPass one = gi::radiosity_pass(scene, p, 1);
  const gi::RadiosityPass three = gi::radiosity_pass(scene, p, 3);
  ASSERT_EQ(one.handoff.B, three.handoff.B) << "the radiosity pass";
  gi::TwoPassSettings s;
  s.width = s.height = 20, s.gather_strata = 2;
  const gi::Image a = gi::render_two_pass(scene, one.handoff, s, 1, 1);
  const gi::Image b = gi::render_two_pass(scene, one.handoff, s, 1, 3);
  EXPECT_EQ(a.pixels, b.pixels) << "the eye pass";
}

}  // namespace

// The eye pass's shadow rays and gather rays read the film's number sequence; with the
// independent one, the default, they are the pixel's stream in the order drawn before,
// and the picture is the one it always was. The hash was taken before the sequences
// reached the eye pass (strict floating point: -ffp-contract=off).
TEST(TwoPass, IndependentNumbersGiveThePictureMadeBefore) {
  const gi::TwoPassScene scene = gi::make_two_pass_scene("cornell-spheres");
  gi::RadiosityPassSettings p = small_pass(200);
  p.tolerance = 1e-3;
  const gi::RadiosityPass pass = gi::radiosity_pass(scene, p, 2);
  gi::TwoPassSettings s;
  s.width = s.height = 24, s.gather_strata = 2;
  const gi::Image picture = gi::render_two_pass(scene, pass.handoff, s, 1, 2);
  const char* bytes = reinterpret_cast<const char*>(picture.pixels.data());
  EXPECT_EQ(gi::hex(gi::fnv1a({bytes, picture.pixels.size() * sizeof(gi::Pixel)})), "94de07a98578a743");
}

TEST(TwoPass, StratifiedAndSobolGiveTheSameBytesOnOneAndThreeThreads) {
  const gi::TwoPassScene scene = gi::make_two_pass_scene("cornell-spheres");
  gi::RadiosityPassSettings p = small_pass(200);
  p.tolerance = 1e-3;
  const gi::RadiosityPass pass = gi::radiosity_pass(scene, p, 2);
  for (const gi::SamplerKind kind : {gi::SamplerKind::Stratified, gi::SamplerKind::Sobol}) {
    gi::TwoPassSettings s;
    s.width = s.height = 20, s.gather_strata = 2, s.sequence = kind;
    const gi::Image a = gi::render_two_pass(scene, pass.handoff, s, 1, 1);
    const gi::Image b = gi::render_two_pass(scene, pass.handoff, s, 1, 3);
    EXPECT_EQ(a.pixels, b.pixels) << gi::sequence_name(kind);
  }
}
