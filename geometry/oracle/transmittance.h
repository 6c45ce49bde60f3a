#pragma once
// Coloured shadows: τ(P), the fraction of a point or directional light's
// intensity that reaches a sample through the tinted polygons between it
// and the light (DESIGN.md "Transmittance", docs/transmittance.md).
#include <umbra/geometry/oracle/shadow_oracle.h>

#include <cstdint>
#include <span>

namespace umbra::geometry {

/// A model and how many of its casting polygons shadow a point (their
/// surfaces crossed an odd number of times by the segment to the light).
struct ModelCount {
  std::uint32_t model = 0;
  int count = 0;
  friend bool operator==(const ModelCount&, const ModelCount&) = default;
};

/// τ = Π T_m^count over `counts`, which must be in increasing model order:
/// the channels multiplied one factor at a time in that order, so that
/// every method that finds the same counts gets the same doubles. An
/// opaque model (T = 0) crossed makes τ 0. Counts must be >= 0 (else
/// std::logic_error: a negative count is a broken volume).
Rgb transmittance_product(const Scene& scene, std::span<const ModelCount> counts);

/// The oracle's answer for τ at a sample.
struct TransmittanceAnswer {
  ShadowAnswer shadow;  ///< classify_sample's answer, the same in every case
  /// τ(P): 1 lit, 0 out of range, else transmittance_product of the
  /// shadowing polygons' models (with `boundary`, the value the
  /// tie-breaks chose).
  Rgb tau{1, 1, 1};
  /// τ has no single value under an arbitrarily small move: shadow.boundary,
  /// or shadowed through tinted polygons only while a polygon whose T is not
  /// 1 is touched or the light lies in a tinted hit polygon's plane. A
  /// robustly crossed opaque polygon makes τ 0 whatever else is touched.
  bool boundary = false;
  /// The casting polygons (indices into SceneIndex::polygons()) crossed an
  /// odd number of times, in increasing order; empty when lit or out of
  /// range. τ is the product of their models' T.
  std::vector<std::uint32_t> polygons;
};

/// The same sample as classify_sample, with τ: every shadowing polygon is
/// found, not only the first.
TransmittanceAnswer transmittance_sample(const SceneIndex& index, const SampleRay& ray,
                                         const SurfaceHit& hit, std::uint32_t light);

/// The shadowing polygons (shadowing_polygons' answer) grouped by model,
/// in increasing model order.
std::vector<ModelCount> count_by_model(const SceneIndex& index,
                                       std::span<const std::uint32_t> polygons);

}  // namespace umbra::geometry
