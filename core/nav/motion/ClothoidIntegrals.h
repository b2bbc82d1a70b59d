// ClothoidIntegrals: the Fresnel-type integrals behind clothoid positions (thesis 5.5.3),
//   X + iY = integral_0^L exp(i (theta0 + kappa0 u + sharpness u^2 / 2)) du,
// by composite Gauss-Legendre quadrature (10 nodes per sub-interval, sub-intervals short enough
// that the phase turns by at most one radian on each): far below 1e-9 m for any length a robot
// drives, in about a microsecond. Bertolazzi & Frego (2015) evaluate the same integrals by
// series expansions; quadrature is simpler and as accurate at these lengths.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace rgnav {

struct PlanarVector {
  double x = 0.0;
  double y = 0.0;
};

namespace gauss_legendre {

// Nodes (on [-1, 1], the positive half) and weights of the 10-point rule.
inline constexpr std::array<double, 5> kNodes = {0.1488743389816312, 0.4333953941292472,
                                                 0.6794095682990244, 0.8650633666889845,
                                                 0.9739065285171717};
inline constexpr std::array<double, 5> kWeights = {0.2955242247147529, 0.2692667193099963,
                                                   0.2190863625159820, 0.1494513491505806,
                                                   0.0666713443086881};

// Integral over [a, b] of f, a callable returning PlanarVector, on `pieces` equal sub-intervals.
template <class F>
PlanarVector integrate(double a, double b, int pieces, const F& f) {
  PlanarVector sum;
  const double h = (b - a) / pieces;
  for (int p = 0; p < pieces; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
      const double d = 0.5 * h * kNodes[k];
      const PlanarVector lo = f(mid - d), hi = f(mid + d);
      sum.x += kWeights[k] * (lo.x + hi.x);
      sum.y += kWeights[k] * (lo.y + hi.y);
    }
  }
  return {0.5 * h * sum.x, 0.5 * h * sum.y};
}

// Sub-intervals for a phase theta0 + kappa0 u + sharpness u^2/2 over [0, length]: one per
// radian of turning (|kappa| at either end bounds the rate) and per radian of the quadratic term.
inline int piecesFor(double length, double kappa0, double sharpness) {
  const double rate = std::max(std::abs(kappa0), std::abs(kappa0 + sharpness * length));
  const double turning = rate * length + std::abs(sharpness) * length * length;
  return 1 + static_cast<int>(std::min(turning, 1e6));
}

}  // namespace gauss_legendre

// The displacement of a clothoid (or arc, or straight) of `length` from its start.
inline PlanarVector clothoidDisplacement(double length, double theta0, double kappa0, double sharpness) {
  return gauss_legendre::integrate(
      0.0, length, gauss_legendre::piecesFor(length, kappa0, sharpness), [&](double u) {
        const double phase = theta0 + u * (kappa0 + 0.5 * sharpness * u);
        return PlanarVector{std::cos(phase), std::sin(phase)};
      });
}

}  // namespace rgnav
