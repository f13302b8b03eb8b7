#include "gi/render/film.hpp"

#include <stdexcept>

namespace gi {

Film make_film(int width, int height, std::uint64_t seed, SamplerKind sequence, std::uint32_t samples_per_pixel) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("film: width and height must lie in [1, 16384]");
  Film film;
  film.width = width;
  film.height = height;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  film.rng.reserve(pixels);
  for (std::size_t i = 0; i < pixels; ++i) film.rng.emplace_back(seed, i);
  film.sum.assign(pixels, Color(0.0));
  film.m2.assign(pixels, Color(0.0));
  film.sequence = make_sample_sequence(sequence, seed, samples_per_pixel);
  return film;
}

Image film_mean(const Film& film) {
  Image image(film.width, film.height);
  if (film.samples < 1) return image;
  const double n = static_cast<double>(film.samples);
  for (std::size_t i = 0; i < film.sum.size(); ++i) image.pixels[i] = Pixel(film.sum[i] / n);
  return image;
}

Image film_variance(const Film& film) {
  Image image(film.width, film.height);
  if (film.samples < 2) return image;
  const double n = static_cast<double>(film.samples);
  for (std::size_t i = 0; i < film.m2.size(); ++i) image.pixels[i] = Pixel(film.m2[i] / (n * (n - 1)));
  return image;
}

Image film_standard_error(const Film& film) {
  Image image = film_variance(film);
  for (Pixel& p : image.pixels) p = glm::sqrt(p);
  return image;
}

}  // namespace gi
