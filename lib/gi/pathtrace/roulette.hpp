#pragma once
#include "gi/core/math.hpp"

namespace gi {

// Russian roulette (Arvo and Kirk 1990) ends long paths without bias. A path whose
// throughput beta is small goes on with probability q = min(1, max component of beta)
// and, if it does, carries beta / q from then on; otherwise it stops and carries 0:
//   E[beta'] = q (beta / q) + (1 - q) 0 = beta.
// Bright paths (q = 1) always go on; dim ones rarely, but count for more when they do.
// u is uniform in [0, 1); the path goes on when u < q. Returns false when the path
// ends (beta is then left as it was).
bool russian_roulette(Color& beta, double u);

}  // namespace gi
