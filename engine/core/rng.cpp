#include "engine/core/rng.h"

#include <cmath>
#include <numbers>

namespace linesurf {

double Rng::Normal() {
  const double u1 = 1.0 - Uniform();  // (0, 1]: log stays finite
  const double u2 = Uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace linesurf
