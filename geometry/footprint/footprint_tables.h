#pragma once
// Internal to geometry/footprint/: what footprints need of a scene that does
// not depend on its lights (every model's tables, the caster index), made once so that a series of
// suns (sun_footprints.h) pays for them once; and the per-light side edges.
#include <umbra/geometry/exact/polygon_surface.h>
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/receiver_partition.h>
#include <umbra/geometry/footprint/receiver_plane.h>
#include <umbra/geometry/footprint/receiver_units.h>
#include <umbra/geometry/oracle/bvh.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/volumes/model_tables.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace umbra::geometry::detail {

/// One light's side polygons as the edges they come from, with boxes that
/// hold each side's part inside the scene (its vertices reach past it).
struct LightSides {
  std::vector<std::array<Vec3, 2>> edges;
  Bvh bvh;
};

struct FootprintTables {
  /// `scene` copied (with ignore_light_end its lights made unlimited);
  /// `receivers` the receiving models' indices, sorted.
  FootprintTables(const Scene& scene, std::vector<std::uint32_t> receivers, bool ignore_light_end,
                  unsigned threads);
  FootprintTables(const FootprintTables&) = delete;  // the index points at `scene`
  FootprintTables& operator=(const FootprintTables&) = delete;

  /// The models as given; the lights are the caller's to replace (a series
  /// sets its sun here before each step).
  Scene scene;
  std::vector<std::uint32_t> receivers;
  std::vector<ModelTables> tables;  ///< per model (the receivers' surfaces too)
  std::unique_ptr<SceneIndex> index;
  unsigned threads = 0;
  bool tinted = false;  ///< some casting model lets light through
};

/// A receiver piece in its plane: the plane, its outline and its boxes.
struct UnitFrame {
  std::span<const Vec3> vertices;  ///< the piece's (its ReceiverUnit's, which outlives the frame)
  ReceiverPlane plane;
  ReceiverOutline outline;
  Box box3;
  Box2 box2;
};
UnitFrame unit_frame(const ReceiverUnit& unit);

/// The segments where `light`'s shadow may begin or end on the piece: its
/// side polygons' traces in the plane, clipped to the piece's box.
void add_light_segments(const UnitFrame& frame, const LightSides& sides, const HPoint& light,
                        std::vector<Segment2>& segments, std::vector<std::uint32_t>& scratch);
/// Where casting polygons pierce the piece's plane (a shadow may begin
/// there whatever the light).
void add_piercing_segments(const UnitFrame& frame, const SceneIndex& index,
                           std::vector<Segment2>& segments, std::vector<std::uint32_t>& scratch);

/// The partition's regions in an order no run or thread count changes.
void canonical_order(std::vector<PartitionRegion>& parts);
/// A region's ring lifted to 3D and rounded to the nearest doubles.
std::vector<Vec3> rounded_ring(const ReceiverPlane& plane, const std::vector<Point2>& ring);

/// The receiving models' indices, sorted: options.receivers by name, else
/// every model with `receives`. Throws std::invalid_argument naming an
/// unknown name, or when nothing receives.
std::vector<std::uint32_t> receiving_models(const Scene& scene, const FootprintOptions& options);

/// The side edges of each light in `lights` of tables.scene, indexed by
/// light (others empty), from volumes built without caps.
std::vector<LightSides> light_sides(const FootprintTables& tables,
                                    std::span<const std::uint32_t> lights);

/// The footprints of `lights` of tables.scene (none dark, none an area
/// light), regions in light, model, polygon order.
Footprints footprints_of(const FootprintTables& tables, std::span<const std::uint32_t> lights);

}  // namespace umbra::geometry::detail
