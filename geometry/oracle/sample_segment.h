#pragma once
// What the oracle settles about a sample before it looks at any polygon:
// shared by classify_sample (the first shadowing polygon decides) and
// transmittance_sample (every one counts). Internal to geometry/oracle/.
#include <umbra/geometry/exact/segment_crossing.h>
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/oracle/scene_index.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

struct SampleSegment {
  SamplePoint p;  ///< the sample point P = H - ε·d
  HPoint light;   ///< the light's homogeneous point
  bool out_of_range = false;
  /// A boundary whatever the polygons do: the hit's own (hit.boundary) or
  /// |H - L| = light_end or H on a spot's cone, exactly.
  bool hard_boundary = false;
  /// The light lies in the plane of the shadow-casting hit polygon.
  bool light_in_hit_plane = false;
  /// Polygons whose box may meet the segment from (about) H to the light,
  /// in no particular order (classify_sample's answer does not depend on
  /// it); empty when out of range.
  std::vector<std::uint32_t> candidates;
};

SampleSegment sample_segment(const SceneIndex& index, const SampleRay& ray, const SurfaceHit& hit,
                             std::uint32_t light);

}  // namespace umbra::geometry
