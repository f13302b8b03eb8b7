#include "gi/pathtrace/roulette.hpp"

#include "gi/core/not_implemented.hpp"

namespace gi {

bool russian_roulette(Color& beta, double u) {
  // BEGIN EXERCISE 14.3 the Russian roulette weight
  const double q = std::min(1.0, max_component(beta));
  if (!(u < q)) return false;
  beta /= q;
  return true;
  // END EXERCISE 14.3
}

}  // namespace gi
