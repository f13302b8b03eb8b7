#include "gi/twopass/final_gather.hpp"

#include "gi/core/not_implemented.hpp"
#include "gi/core/onb.hpp"
#include "gi/core/sampling.hpp"

namespace gi {

Color final_gather(const EyeWorld& eye, const RadiosityHandoff& handoff, const vec3& x, const vec3& n, int strata,
                   Rng& rng) {
  const Onb frame(n);
  const int rays = strata * strata;
  Color sum(0.0);
  // BEGIN EXERCISE 16.2 the final-gather estimate
  for (int k = 0; k < rays; ++k) {
    const vec2 u((k % strata + rng.uniform()) / strata, (k / strata + rng.uniform()) / strata);
    const vec3 w = frame.to_world(sample_cosine_hemisphere(u));
    const auto y = first_hit(eye, Ray{x, w});
    if (!y || y->element < 0 || dot(w, y->hit.normal) >= 0) continue;  // the void, a sphere, a back face
    // L_r cos / p with p = cos / pi: (B - E)(y) / pi * pi = (B - E)(y)
    sum += reflected_radiosity_at(handoff, y->element, y->hit.point);
  }
  // END EXERCISE 16.2
  return sum / double(rays);
}

}  // namespace gi
