#pragma once
// Internal to geometry/footprint/: one receiver's surface, cut along the
// segments where a light's shadow may begin or end, into maximal lit and
// shadowed simple polygons (CGAL's Arrangement_2 on exact segments).
#include <umbra/geometry/footprint/footprint.h>
#include <umbra/geometry/footprint/receiver_plane.h>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace umbra::geometry::detail {

/// A receiver in its plane's coordinates: its outline and the fan
/// triangles (indices into the outline) whose parity is its surface.
struct ReceiverOutline {
  std::vector<Point2> vertices;
  std::vector<std::array<std::uint32_t, 3>> fan;
};

struct PartitionRegion {
  FootprintClass cls = FootprintClass::lit;
  int key = 0;               ///< the Classifier's key of the region's points (0: lit)
  std::vector<Point2> ring;  ///< counter-clockwise, a simple polygon
  FT area = 0;               ///< in the plane's 2D coordinates, exact
};

/// Answers what a point strictly inside the surface, off every boundary
/// segment, receives, as a key: 0 lit, anything above shadowed (one key per
/// distinct shadow: 1 alone for hard shadows; with coloured shadows one per
/// set of tinted polygons crossed); nullopt when it cannot be decided there
/// (the partition then asks another point of the same face). Faces of one
/// key merge into maximal regions.
using Classifier = std::function<std::optional<int>(const Point2&)>;

struct PartitionCounts {
  std::uint64_t classified_faces = 0;
};

/// The maximal regions of one key on the receiver's surface, each a
/// simple polygon: regions with holes are cut by vertical segments from
/// their holes' extreme vertices. `boundary` may reach outside the surface.
std::vector<PartitionRegion> partition_receiver(const ReceiverOutline& outline,
                                                const std::vector<Segment2>& boundary,
                                                const Classifier& classify,
                                                PartitionCounts& counts);

}  // namespace umbra::geometry::detail
