#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gi/core/math.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/samplers/sample_stream.hpp"
#include "gi/image/image.hpp"

namespace gi {

// A picture being estimated sample by sample, whatever the method estimates: per pixel
// its random stream, and the running sum and spread of its samples. The mean is the sum
// over the count; the spread is Welford's update, exact in any order of passes:
//   n += 1,  delta = x - mean_(n-1),  mean_n = sum / n,  m2 += delta (x - mean_n)
// so that the variance of the pixel's mean is s^2 / n = m2 / (n (n - 1)): each pixel's
// own error bar, measured from its samples. Pixel i draws from stream i of the seed, and
// every pass continues each pixel's stream where the last one left it: 1 + 3 samples
// are the same as 4, and the picture is the same for any number of threads.
// The film also names the number sequence its samples read (sample_stream.hpp): with
// the independent one, the default, they read the pixel's stream in the order they ask.
struct Film {
  int width = 0;
  int height = 0;
  long long samples = 0;    // per pixel, so far: every pixel has as many
  long long discarded = 0;  // samples that were not finite numbers: counted as 0, and reported
  std::vector<Rng> rng;     // pixel i draws from stream i of the seed
  std::vector<Color> sum;
  std::vector<Color> m2;
  SampleSequence sequence;  // its seed is the film's; a stratified one's N is the spp the picture will reach
};

// Throws std::invalid_argument for a size outside [1, 16384], or samples_per_pixel 0.
Film make_film(int width, int height, std::uint64_t seed, SamplerKind sequence = SamplerKind::Independent,
               std::uint32_t samples_per_pixel = 1);

// Adds x as the n-th sample (n counting it) of pixel i. A sample that is not a finite
// number is added as 0 and the function returns false, for the caller to count it.
inline bool add_sample(Film& film, std::size_t i, long long n, Color x) {
  const bool finite = is_finite(x);
  if (!finite) x = Color(0.0);
  const Color before = n > 1 ? film.sum[i] / static_cast<double>(n - 1) : Color(0.0);
  film.sum[i] += x;
  film.m2[i] += (x - before) * (x - film.sum[i] / static_cast<double>(n));
  return finite;
}

Image film_mean(const Film& film);            // radiance, linear
Image film_variance(const Film& film);        // variance of each pixel's mean, per channel (0 below 2 samples)
Image film_standard_error(const Film& film);  // its square root: the standard error of each pixel's mean

}  // namespace gi
