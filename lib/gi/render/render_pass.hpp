#pragma once
#include <memory>
#include <type_traits>

#include "gi/core/ray.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/samplers/sample_stream.hpp"
#include "gi/render/film.hpp"
#include "gi/render/pixel_samplers.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// Where every method of the course meets the pixel. Ray tracing, radiosity, two-pass and
// path tracing all estimate one quantity, the radiance L(x, w) arriving at the eye; each
// is a radiance function, called once per eye ray:
//   Color radiance(const Ray& ray, PixelSample& sample)
// One loop asks it for every sample of every pixel and keeps the mean and spread on a
// film. The pixel value is the box filter's: the mean of L over the pixel's area,
//   I(x, y) = integral over the pixel of L(ray through (x + u, y + v)) du dv,
// estimated by the mean over the sampler's points (pixel_samplers.hpp).

// What a radiance function knows of the sample it estimates, and the numbers it reads.
// A method that takes its decisions at fixed dimensions (path_dimension) reads them with
// get_1d(d) and get_2d(d): the film's number sequence (sample_stream.hpp) for this pixel
// and sample. With the independent sequence they are the pixel's stream, drawn in the
// order they are asked for, whatever d: every picture made before the sequences came to
// the pipeline stays the same. A 2D point draws its second coordinate first, the order
// the path tracer has always drawn its points in.
struct PixelSample {
  int x = 0, y = 0;     // the pixel
  vec2 position;        // where the eye ray crosses the image, in pixels: x + u, y + v
  long long index = 0;  // the sample's number in its pixel, counted over every pass: 0, 1, 2, ...
  Rng& rng;             // the pixel's random stream: whatever the method draws, it draws from here
  const SampleSequence& sequence;  // the film's number sequence
  std::uint64_t pixel = 0;         // y * width + x: which pixel's numbers

  double get_1d(std::uint32_t dimension);
  vec2 get_2d(std::uint32_t dimension);
};

// A sample outside any film, for a caller that holds a stream alone (a test, a probe of
// one ray): the independent sequence, whose numbers are `rng`'s in the order asked.
PixelSample stream_sample(Rng& rng);

// A radiance function, not owned: one indirect call per sample, and any callable will do
// (a lambda, a method's struct). It must outlive the render_pass it is given to.
class RadianceFunction {
 public:
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, RadianceFunction>)
  RadianceFunction(F&& f)
      : function_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_([](void* function, const Ray& ray, PixelSample& sample) -> Color {
          return (*static_cast<std::remove_reference_t<F>*>(function))(ray, sample);
        }) {}
  Color operator()(const Ray& ray, PixelSample& sample) const { return call_(function_, ray, sample); }

 private:
  void* function_;
  Color (*call_)(void*, const Ray&, PixelSample&);
};

// Adds one pass of `sampling` to every pixel of `film`: the pattern's eye rays through the
// camera (Centre 1, Grid, Random and Jittered n x n, Adaptive one estimate of the pixel from
// its corners and splits), each estimated by `radiance`. Random's and Jittered's points
// read the sequence's pixel dimension (pattern_numbers.hpp). The film's count grows by
// the pass's samples. The picture is cut into 32 x 32 tiles that `threads` (0 = all cores)
// take in turn; a pixel draws only from its own stream, so the film is the same for any
// thread count. Throws std::invalid_argument for bad sampling or camera settings.
void render_pass(Film& film, const Camera& camera, const Sampling& sampling, RadianceFunction radiance, int threads);

// The number of tiles of a film, which the threads take in turn. A method that keeps a
// tally (rays cast) keeps one per thread (core/per_thread.hpp), not per tile.
int render_tasks(const Film& film);

// The film's samples one pass of `sampling` adds: 1 for Centre and Adaptive, else n x n.
int samples_per_pass(const Sampling& sampling);

// Two methods' parts of the light along the same eye ray, added: the sum of two
// estimators is an estimator of the sum. (Direct light per pixel plus the light a
// radiosity mesh holds of what has bounced more than once, say.)
template <class A, class B>
auto sum_of(A a, B b) {
  return [a, b](const Ray& ray, PixelSample& sample) { return a(ray, sample) + b(ray, sample); };
}

// A radiance function's estimates clamped to `white` in every channel, before they are
// averaged: a picture to show, whose edges on a light far brighter than white stay smooth.
template <class A>
auto clamped(A a, double white) {
  return [a, white](const Ray& ray, PixelSample& sample) { return glm::min(a(ray, sample), Color(white)); };
}

}  // namespace gi
