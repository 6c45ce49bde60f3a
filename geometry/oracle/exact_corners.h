#pragma once
// Internal to geometry/oracle/: certified_fraction.h's ExactCorners in
// exact rationals, for the retry of a sample the interval corners could not
// certify (visible_fraction.cpp).
#include <umbra/geometry/oracle/area_light_pieces.h>
#include <umbra/geometry/oracle/certified_fraction.h>
#include <umbra/geometry/oracle/rational_geometry.h>

namespace umbra::geometry::soft {

/// Far blockers' corners from the exact H, which lies off the plane of the
/// piece's first fan triangle.
class RationalCorners final : public ExactCorners {
 public:
  RationalCorners(const LightPiece& piece, const P3& h);
  void ring(const std::array<Vec3, 3>& t, const ClipChoice& choice, int u, int v,
            std::vector<std::pair<Interval, Interval>>& out) const override;

 private:
  P3 h_, f0_, normal_;  ///< the light's plane: normal_·(x − f0_) = 0
  FT h_height_;         ///< normal_·(H − f0_), not 0
  FT h_side_;           ///< its sign, ±1
};

}  // namespace umbra::geometry::soft
