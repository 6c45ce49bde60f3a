#pragma once
// Does the segment from a point to a light cross a polygon's surface an odd
// number of times, and does it touch the polygon (an edge, a vertex, its
// plane)? The one test behind the oracle (from a sample point P = H - ε·d)
// and behind the eye's starting counts (from a finite point).
#include <umbra/geometry/exact/predicates.h>
#include <umbra/geometry/oracle/scene_index.h>

namespace umbra::geometry {

struct Crossing {
  bool odd = false;      ///< the segment crosses the surface an odd number of times
  bool touches = false;  ///< it touches an edge or vertex, or runs in a face's plane
};

/// Is the finite point x, which must lie in the plane of the triangle
/// (a, b, c) of nonzero area, inside the closed triangle? Exact.
bool in_closed_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x);

/// From the sample point P of `p` to `light`. Touches are judged on the limit
/// segment from H (DESIGN.md's boundary).
Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const SamplePoint& p);

/// From the finite point `x` to `light`.
Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const Vec3& x);

/// A point moved off every plane by a symbolic perturbation (Edelsbrunner
/// and Mücke's simulation of simplicity): x + δ·w1 + δ²·w2 + δ³·w3 for an
/// infinitesimal δ > 0 and three linearly independent directions. Which
/// side of a plane it lies on is the side of x, or where x is in the plane
/// that of w1, then w2, then w3: decided for every plane.
struct PerturbedPoint {
  explicit PerturbedPoint(const Vec3& point) : x(point) {}
  Vec3 x;
  Vec3 w1{0.6211928176390351, -0.2473081263749925, 0.7436927350927313};
  Vec3 w2{-0.3162051537302773, 0.8831170532681531, 0.2683925017243017};
  Vec3 w3{0.7170524880390317, 0.3978023462911037, -0.5722716402281053};
};

/// The side of plane (a, b, c) on which the perturbed point lies,
/// orientation's sign; ZERO only when (a, b, c) spans no plane.
Sign side_of(const Vec3& a, const HPoint& b, const HPoint& c, const PerturbedPoint& x);

/// From the perturbed point to `light`: it touches a polygon only where the
/// light itself lies on the polygon's surface.
Crossing cross_polygon(const SceneIndex& index, const IndexedPolygon& polygon, const HPoint& light,
                       const PerturbedPoint& x);

}  // namespace umbra::geometry
