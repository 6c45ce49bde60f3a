#pragma once
// Far ends on a sphere about a point light: how a model's volume is closed
// when the light nearly touches one of its volume-casting surfaces.
//
// Why. The volume of a model is normally the model scaled about L by one
// factor 1 + k (geometry/volumes/far_ends.h), with k = reach / (distance from L to the
// model). That needs a distance well above rounding: with L a hair from a
// polygon (a light typed at an edge's midpoint lands ~1e-17 off the edge)
// k is unbounded, and a side's far edge a'b' — the edge scaled about L —
// passes as near L as the edge itself does. Such a side covers only a sliver
// of its wedge {L + s·(x − L) : x on ab, s ≥ 1}, and the picture is wrong.
//
// What. Every far point lies on the sphere of radius R about L, on its own
// ray: far(x) = L + R·(x − L)/|x − L|. A side over (a, b) runs a, b, far(b),
// [far(F)], far(a), where F, the foot of the perpendicular from L onto the
// line ab, is added when the angle a-L-b is not acute (decided exactly; F
// then lies strictly inside ab). Every far chord then spans an angle below
// 90° at L, so it stays farther than R·cos 45° from L. A far cap piece is a
// triangle of far points pairwise at most 90° apart seen from L, hence
// farther than R/√3 from L. So with R = 2 × the light's reach every far end
// clears the reach (geometry/volumes/far_ends.h), and within it each face is the ideal
// wedge or cap it stands for; far points are rounded, not ideal, but lie
// within a few ulps of R of points of the ideal plane, which the renderer's
// error bounds already allow for (raster/scanline/projected_polygon.h).
#include <umbra/geometry/vec3.h>

#include <optional>
#include <vector>

namespace umbra::geometry {

class SphereEnds {
 public:
  /// `radius` > 0: the sphere's radius R about the point light.
  SphereEnds(const Vec3& light, double radius) : light_(light), radius_(radius) {}

  double radius() const { return radius_; }

  /// L + R·(x − L)/|x − L|. Precondition: x != L.
  Vec3 far(const Vec3& x) const;

  /// far(F) for the foot F of L on line ab when the angle a-L-b is not
  /// acute, else nothing. Symmetric in a and b, so every face that shares
  /// the edge gets the same point. Preconditions: L is not on line ab.
  std::optional<Vec3> between(const Vec3& a, const Vec3& b) const;

  /// Appends the far ends of the side polygon over (a, b) in its vertex
  /// order after a and b: far(b), between(a, b) if any, far(a).
  void side_ends(const Vec3& a, const Vec3& b, std::vector<Vec3>& out) const;

  /// The far point on the ray from L perpendicular to the plane of the
  /// triangle (p, q, r), on the triangle's side: every point of the
  /// triangle is seen from L within 90° of it. Precondition: L is not in
  /// the plane.
  Vec3 toward_plane(const Vec3& p, const Vec3& q, const Vec3& r) const;

 private:
  Vec3 along(const Vec3& direction) const;

  Vec3 light_;
  double radius_;
};

}  // namespace umbra::geometry
