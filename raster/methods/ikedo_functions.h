#pragma once
// Ikedo's intensity modulator: the light-erosion function D, the penumbra
// half-width h and the penumbra-shade f(Qp, h) (his equations (1)–(3),
// images missing from the paper's text; the forms chosen here and why:
// docs/soft-shadows.md, "Ikedo's penumbra"). Every function is a plain
// float formula, a comparator's, judged by |V − V_exact| like the others.
#include <umbra/raster/render.h>

#include <array>

namespace umbra::raster {

/// His coefficients (k0, k1, k2) of the light-erosion function.
struct ErosionCoefficients {
  double k0 = 1.5, k1 = 1, k2 = 1;
};

/// The set a, b, c or d: (3/2, 1, 1), (7/6, 3, 3), (21/20, 20, 20),
/// (101/100, 50, 50), his curves (a) to (d).
ErosionCoefficients erosion_coefficients(IkedoCoefficients set);

/// Its name on the command line: "a" … "d".
const char* ikedo_coefficients_name(IkedoCoefficients set);

/// Light-erosion (equation (1)/(2)): the darkness of the shadow at ratio
/// x = ΔLz / L1z (occluder's rear to receiver over light to occluder),
///   D(x) = clamp(k0 − k1·x / (1 + k2·x), 0, 1):
/// 1 (full darkness) at contact, eroded by the light as the receiver
/// moves away from the occluder, towards k0 − k1/k2 (= 1/(2·k1) for his
/// sets a, b, d: the darkness left far away). x <= 0 gives D(0).
double light_erosion(double x, const ErosionCoefficients& k);

/// The penumbra's half-width on the receiver (equation (3), similar
/// triangles for a spherical light of radius r): h = r·x / cos θ, θ the
/// light's incidence on the receiver (cos θ in (0, 1]; smaller values
/// are taken as 1e-6). Seen from the light (in the buffer) the cos θ
/// stretch is not there: ikedo_lookup uses r·x.
double penumbra_half_width(double x, double light_radius, double cos_incidence);

/// The number of levels of Qp (his 6-bit shade-flag): Qp = k / 63.
inline constexpr int kQpLevels = 64;

/// Qp rounded to the nearest of the 64 levels k / 63 (clamped to [0, 1]).
double quantise_qp(double qp);

/// The filter's edge profile inverted (his "inverse transformation", a RAM
/// table): for level k, the signed distance in texels from a straight
/// shadow edge at which the IIR filter leaves Qp = k / 63 (positive
/// inside the shadow). Level 0 and 63 are −/+ infinity (outside the
/// filter's reach).
using EdgeDistances = std::array<double, kQpLevels>;

/// Penumbra-shade f(Qp, h): the distance d(Qp) from the shadow's edge that
/// Qp stands for, re-ramped linearly over the penumbra 2·h wide,
///   f = clamp(1/2 + d(Qp) / (2·h), 0, 1),
/// h in texels of the buffer (La = h over the filter's reach, normalised).
/// A small h gives a step at the filtered edge (the shadow polygon itself),
/// a large one a wide ramp; Qp is quantised first. 1 is full shadow.
double penumbra_shade(double qp, double half_width_texels, const EdgeDistances& table);

}  // namespace umbra::raster
