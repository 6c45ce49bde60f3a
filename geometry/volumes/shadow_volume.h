#pragma once
// Shadow volumes as plain values: what geometry/ hands to raster/ and to the
// exporters. No CGAL types cross this header.
#include <umbra/geometry/vec3.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

/// Bergeron's closing types.
enum class ShadowPolygonType : std::uint8_t {
  model_cap = 1,      ///< type 1: a polygon of the model (near end)
  side = 2,           ///< type 2: extruded from a contour edge, away from the light
  projected_cap = 3,  ///< type 3: the model projected to the far end
};

/// One face of a light's shadow volume.
///
/// `nb_c` is view-independent: it is the count added when the face is crossed
/// from the side on which `vertices` run counter-clockwise (the side its
/// right-handed normal points to); crossing from the other side adds -nb_c.
/// A renderer turns it into Bergeron's view-dependent Nb_C by asking from
/// which side the eye ray crosses.
///
/// A side polygon (type 2) of edge (a, b) of a point light L has the
/// vertices a, b, b', a' with x' = x + k·(x - L) for one k > 0 per model
/// (FarEnds::past_reach), or with a k_x per far vertex that ends the side
/// just past the scene's bounding box (FarEnds::leaving_bounds,
/// geometry/volumes/builder.h), or — when L nearly touches the model — a, b, far(b),
/// [far(F)], far(a) on a sphere about L (sphere_ends.h); its exact support
/// is the plane through L, a and b, and decisions are taken on that ideal
/// geometry (the wedge from a, b away from L), not on the rounded far
/// vertices. For a directional light travelling along D, x' = x + k·D.
/// A far cap (type 3) on a sphere comes as several triangles per fan
/// triangle of its polygon.
struct ShadowPolygon {
  std::vector<Vec3> vertices;
  std::uint32_t light = 0;
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;  ///< source polygon within its model
  /// type 2: the contour edge is polygon's edge (edge, edge + 1 mod n); for
  /// a side of a twisted polygon's own volume, edge >= n names the fan
  /// diagonal (v0, v_k) with k = edge - n + 2 (geometry/volumes/builder.cpp).
  std::uint32_t edge = 0;
  ShadowPolygonType type = ShadowPolygonType::side;
  std::int32_t nb_c = 0;
  /// A face of an L-twisted polygon's own volume (Bergeron's Fig. 11/12):
  /// crossing it toggles the In_Shadow flag of the pair (light, polygon)
  /// instead of adding nb_c; its nb_c is 1.
  bool twisted = false;
  /// twisted only: index into ShadowVolumes::twisted; -1 otherwise.
  std::int32_t group = -1;
};

/// A (light, polygon) pair whose polygon is L-twisted.
struct TwistedPolygon {
  std::uint32_t light = 0;
  std::uint32_t model = 0;
  std::uint32_t polygon = 0;
};

/// Contour-edge statistics of one light's volumes.
struct VolumeStats {
  std::uint32_t light = 0;
  std::uint64_t contour_edges = 0;
  std::uint64_t boundary_contour_edges = 0;    ///< |Nb_C| = 1
  std::uint64_t silhouette_contour_edges = 0;  ///< |Nb_C| = 2 (or more, non-manifold)
  std::uint64_t side_polygons = 0;             ///< type 2, twisted polygons' sides included
  std::uint64_t near_caps = 0;                 ///< type 1
  std::uint64_t far_caps = 0;                  ///< type 3
  std::uint64_t twisted_polygons = 0;
  std::uint64_t crow_all_edges_polygons = 0;  ///< Crow's baseline: one per edge of every polygon
  /// Sphere of influence (point lights with light_end): models wholly
  /// outside it get no volume; these are those models and their polygons
  /// (faces of the model, none of them examined for this light: a model
  /// whose box lies outside is skipped before any facing is decided).
  std::uint64_t culled_models = 0;
  std::uint64_t culled_polygons = 0;
  /// Models whose volumes end at the sphere rather than past the scene.
  std::uint64_t truncated_models = 0;
  /// Models the light is too close to for the model scaled about it: their
  /// far ends lie on a sphere about the light (sphere_ends.h).
  std::uint64_t sphere_ended_models = 0;
  /// Bytes the light's shadow polygons take (struct and vertices), and what
  /// Crow's all-edges volumes extruded past the scene would take.
  std::uint64_t bytes = 0;
  std::uint64_t crow_bytes = 0;
  double seconds = 0;  ///< time to build this light's volumes
};

struct ShadowVolumes {
  std::vector<ShadowPolygon> polygons;
  std::vector<VolumeStats> stats;       ///< one per light
  std::vector<TwistedPolygon> twisted;  ///< the In_Shadow flags' pairs
  /// [light][model]: the extrusion factor k of the model's volume for the
  /// light (see ShadowPolygon; with FarEnds::leaving_bounds the most any of
  /// its sides is extruded); 0 where the model casts no volume for it
  /// (casts_shadows false, or wholly outside the light's sphere).
  std::vector<std::vector<double>> extrusion;
};

}  // namespace umbra::geometry
