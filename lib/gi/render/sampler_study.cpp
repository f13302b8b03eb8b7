#include "gi/render/sampler_study.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gi/core/sampling.hpp"
#include "gi/core/samplers/seeds.hpp"

namespace gi {

namespace {

// The square light of the irradiance estimators: side 1, centred at height 1 above the
// point x = 0, whose normal is +z; it faces down, radiance 1.
constexpr double light_side = 1, light_height = 1, light_radiance = 1;

// Where the sample's eye ray crosses its pixel, in the pixel's unit square.
vec2 in_pixel(const PixelSample& sample) { return sample.position - vec2(sample.x, sample.y); }

double smooth_bump(PixelSample& sample) {
  const vec2 u = in_pixel(sample);
  return std::exp(-(u.x * u.x + u.y * u.y));
}

double disk_indicator(PixelSample& sample) {
  const vec2 u = in_pixel(sample) - vec2(0.5);
  return u.x * u.x + u.y * u.y < 1 / (2 * pi) ? 1.0 : 0.0;  // area pi r^2 = 1/2
}

// E = integral over the light of L cos(theta_x) cos(theta_y) / d^2 dA, with y uniform on
// the light (p_A = 1 / A): one sample is L cos(theta_x) cos(theta_y) / d^2 * A, and both
// cosines are h / d here.
double irradiance_by_light_point(PixelSample& sample) {
  const vec2 u = sample.get_2d(path_dimension(0, Decision::LightPoint));
  const vec3 y((u.x - 0.5) * light_side, (u.y - 0.5) * light_side, light_height);
  const double d2 = length_squared(y), cos_both = light_height * light_height / d2;
  return light_radiance * cos_both / d2 * (light_side * light_side);
}

// E = integral over the hemisphere of L_i cos(theta) dw, with w drawn with p = cos(theta) / pi:
// one sample is L_i cos(theta) / p = pi L_i, where the ray meets the light.
double irradiance_by_cosine_direction(PixelSample& sample) {
  const vec3 w = sample_cosine_hemisphere(sample.get_2d(path_dimension(0, Decision::BsdfDirection)));
  if (w.z <= 0) return 0;
  const double t = light_height / w.z, half = light_side / 2;
  return std::abs(t * w.x) < half && std::abs(t * w.y) < half ? pi * light_radiance : 0.0;
}

void check(const StudySettings& s) {
  if (s.pixels < 2 || s.pixels > 16384)
    throw std::invalid_argument("sampler study: pixels must lie in [2, 16384], got " + std::to_string(s.pixels));
  if (s.sample_counts.size() < 2) throw std::invalid_argument("sampler study: at least 2 sample counts to fit a slope");
  for (std::uint32_t n : s.sample_counts)
    if (n == 0) throw std::invalid_argument("sampler study: a sample count of 0");
}

}  // namespace

double form_factor_point_to_centred_square(double a, double h) {
  const double A = a / (2 * h), B = A;
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  const double corner = (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * pi);
  return 4 * corner;
}

std::vector<Estimator> study_estimators() {
  const double bump_1d = std::sqrt(pi) / 2 * std::erf(1.0);  // integral of exp(-x^2) over [0, 1]
  const double irradiance = pi * light_radiance * form_factor_point_to_centred_square(light_side, light_height);
  return {
      {"smooth", bump_1d * bump_1d, true, smooth_bump},
      {"disk", 0.5, false, disk_indicator},
      {"light", irradiance, true, irradiance_by_light_point},
      {"cosine", irradiance, false, irradiance_by_cosine_direction},
  };
}

double expected_slope(SamplerKind kind, bool smooth) {
  switch (kind) {
    case SamplerKind::Independent: return -0.5;
    case SamplerKind::Stratified: return smooth ? -1.0 : -0.75;
    case SamplerKind::Sobol: return smooth ? -1.5 : -0.75;
  }
  return 0;
}

Slope fit_log_log_slope(const std::vector<LogLogPoint>& points) {
  if (points.size() < 2) throw std::invalid_argument("log-log fit: at least 2 points");
  for (const LogLogPoint& p : points)
    if (!(p.samples > 0) || !(p.error > 0) || !std::isfinite(p.error))
      throw std::invalid_argument("log-log fit: samples and errors must be positive and finite, got N = " +
                                  std::to_string(p.samples) + ", error " + std::to_string(p.error));
  double mean_x = 0, mean_y = 0;
  for (const LogLogPoint& p : points) {
    mean_x += std::log(p.samples) / points.size();
    mean_y += std::log(p.error) / points.size();
  }
  double sxx = 0, sxy = 0, variance = 0;
  for (const LogLogPoint& p : points) {
    const double dx = std::log(p.samples) - mean_x, s = p.standard_error / p.error;
    sxx += dx * dx;
    sxy += dx * (std::log(p.error) - mean_y);
    variance += dx * dx * s * s;
  }
  if (!(sxx > 0)) throw std::invalid_argument("log-log fit: the sample counts must not all be the same");
  return {sxy / sxx, std::sqrt(variance) / sxx};
}

std::vector<double> pixel_estimates(const Estimator& estimator, SamplerKind kind, std::uint64_t seed,
                                    std::uint32_t samples, int pixels, int threads) {
  if (pixels < 1 || pixels > 16384)
    throw std::invalid_argument("sampler study: pixels must lie in [1, 16384], got " + std::to_string(pixels));
  Film film = make_film(pixels, 1, seed, kind, samples);
  // The eye rays are not looked at: an estimator's decisions are its sample's numbers.
  const auto radiance = [&](const Ray&, PixelSample& sample) { return Color(estimator.sample(sample)); };
  // N samples in passes of side^2, side the largest that divides N and that a pass takes (64).
  int side = 64;
  while (samples % static_cast<std::uint32_t>(side * side) != 0) --side;
  for (std::uint32_t done = 0; done < samples; done += side * side)
    render_pass(film, Camera{}, {Sampler::Random, side}, radiance, threads);
  std::vector<double> estimates;
  for (const Color& sum : film.sum) estimates.push_back(sum.x / samples);
  return estimates;
}

SamplerStudy sampler_study(const std::vector<Estimator>& estimators, const std::vector<SamplerKind>& samplers,
                           const StudySettings& settings, int threads) {
  check(settings);
  SamplerStudy study;
  for (const Estimator& estimator : estimators)
    for (const SamplerKind kind : samplers) {
      std::vector<LogLogPoint> points;
      for (const std::uint32_t n : settings.sample_counts) {
        std::vector<double> squared_error;
        for (const double estimate : pixel_estimates(estimator, kind, child_seed(settings.seed, n), n, settings.pixels,
                                                     threads)) {
          const double error = (estimate - estimator.exact) / estimator.exact;
          squared_error.push_back(error * error);
        }
        // RMS = sqrt(mean e^2); its standard error from the spread of e^2 (the delta
        // method: se(sqrt m) = se(m) / (2 sqrt m)).
        double mean = 0, m2 = 0;
        for (double e2 : squared_error) mean += e2 / settings.pixels;
        for (double e2 : squared_error) m2 += (e2 - mean) * (e2 - mean);
        const double se_mean = std::sqrt(m2 / (settings.pixels - 1) / settings.pixels);
        const double rms = std::sqrt(mean);
        study.rows.push_back({estimator.name, kind, n, rms, se_mean / (2 * rms)});
        points.push_back({double(n), rms, se_mean / (2 * rms)});
      }
      const Slope fit = fit_log_log_slope(points);
      study.slopes.push_back({estimator.name, kind, fit.slope, fit.standard_error, expected_slope(kind, estimator.smooth)});
    }
  return study;
}

}  // namespace gi
