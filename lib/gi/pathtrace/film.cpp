#include "gi/pathtrace/film.hpp"

#include <atomic>
#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

Film make_film(int width, int height, std::uint64_t seed) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("path tracer: width and height must lie in [1, 16384]");
  Film film;
  film.width = width;
  film.height = height;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  film.rng.reserve(pixels);
  for (std::size_t i = 0; i < pixels; ++i) film.rng.emplace_back(seed, i);
  film.mean.assign(pixels, Color(0.0));
  film.m2.assign(pixels, Color(0.0));
  return film;
}

void render_pass(Film& film, const PathScene& scene, const PathSettings& settings, int spp, int threads) {
  check(settings);
  if (spp < 0) throw std::invalid_argument("path tracer: samples per pixel must be >= 0");
  const CameraFrame frame = camera_frame(scene.scene().camera, film.width, film.height);
  std::atomic<long long> discarded{0};
  parallel_for(film.height, threads, [&](int y) {
    for (int x = 0; x < film.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * film.width + x;
      Rng& rng = film.rng[i];
      double n = static_cast<double>(film.samples);
      for (int k = 0; k < spp; ++k) {
        const double px = x + rng.uniform(), py = y + rng.uniform();
        Color sample = path_radiance(scene, primary_ray(frame, px, py), settings, rng);
        if (!is_finite(sample)) {
          sample = Color(0.0);
          ++discarded;
        }
        n += 1;
        const Color delta = sample - film.mean[i];
        film.mean[i] += delta / n;
        film.m2[i] += delta * (sample - film.mean[i]);
      }
    }
  });
  film.samples += spp;
  film.discarded += discarded;
}

Image film_mean(const Film& film) {
  Image image(film.width, film.height);
  for (std::size_t i = 0; i < film.mean.size(); ++i) image.pixels[i] = Pixel(film.mean[i]);
  return image;
}

Image film_variance(const Film& film) {
  Image image(film.width, film.height);
  if (film.samples < 2) return image;
  const double n = static_cast<double>(film.samples);
  for (std::size_t i = 0; i < film.m2.size(); ++i) image.pixels[i] = Pixel(film.m2[i] / (n * (n - 1)));
  return image;
}

}  // namespace gi
