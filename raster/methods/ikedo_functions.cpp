#include <umbra/raster/methods/ikedo_functions.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster {

ErosionCoefficients erosion_coefficients(IkedoCoefficients set) {
  switch (set) {
    case IkedoCoefficients::a:
      return {1.5, 1, 1};
    case IkedoCoefficients::b:
      return {7.0 / 6.0, 3, 3};
    case IkedoCoefficients::c:
      return {21.0 / 20.0, 20, 20};
    case IkedoCoefficients::d:
      return {101.0 / 100.0, 50, 50};
  }
  return {};
}

const char* ikedo_coefficients_name(IkedoCoefficients set) {
  switch (set) {
    case IkedoCoefficients::a:
      return "a";
    case IkedoCoefficients::b:
      return "b";
    case IkedoCoefficients::c:
      return "c";
    case IkedoCoefficients::d:
      return "d";
  }
  return "a";
}

double light_erosion(double x, const ErosionCoefficients& k) {
  x = std::max(x, 0.0);
  return std::clamp(k.k0 - k.k1 * x / (1 + k.k2 * x), 0.0, 1.0);
}

double penumbra_half_width(double x, double light_radius, double cos_incidence) {
  return light_radius * std::max(x, 0.0) / std::max(cos_incidence, 1e-6);
}

namespace {

/// The nearest of the 64 levels, k in [0, 63].
int qp_level(double qp) {
  return static_cast<int>(std::lround(std::clamp(qp, 0.0, 1.0) * (kQpLevels - 1)));
}

}  // namespace

double quantise_qp(double qp) { return static_cast<double>(qp_level(qp)) / (kQpLevels - 1); }

double penumbra_shade(double qp, double half_width_texels, const EdgeDistances& table) {
  const int level = qp_level(qp);
  if (level == 0) return 0;
  if (level == kQpLevels - 1) return 1;
  const double d = table[level];
  if (!(half_width_texels > 1e-9)) return d > 0 ? 1 : d < 0 ? 0 : 0.5;
  return std::clamp(0.5 + d / (2 * half_width_texels), 0.0, 1.0);
}

}  // namespace umbra::raster
