#include <umbra/geometry/oracle/lit_region.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace umbra::geometry::soft {

const PyramidFilter* LitRegions::find(const SceneIndex& index, std::uint32_t light,
                                      const SurfaceHit& hit, const Box& h_box) const {
  for (const Region& r : regions_)
    if (r.index == index.serial() && r.light == light && r.polygon == hit.polygon &&
        r.triangle == hit.triangle && holds(r.box, h_box))
      return &r.filter;
  return nullptr;
}

void LitRegions::learn(const SceneIndex& index, std::uint32_t light, const SurfaceHit& hit,
                       const Box& h_box, std::span<const LightPiece> pieces,
                       std::span<const Vec3> vertices, const HitPlane& hit_plane) {
  double reach = 0;  // H's distance to the light, the largest coordinate
  for (const Vec3& v : vertices)
    for (int k = 0; k < 3; ++k)
      reach = std::max({reach, std::abs(v[k] - h_box.lo[k]), std::abs(v[k] - h_box.hi[k])});
  thread_local std::vector<std::uint32_t> found;  // per-thread scratch
  Region& r = regions_[next_];
  for (const double part : {1.0 / 32, 1.0 / 256}) {
    const double delta = reach * part;
    Box g;
    g.lo = {h_box.lo.x - delta, h_box.lo.y - delta, h_box.lo.z - delta};
    g.hi = {h_box.hi.x + delta, h_box.hi.y + delta, h_box.hi.z + delta};
    if (!holds(g, h_box)) return;  // delta lost to rounding: no region
    // The local form (no magnitude): a region's normals are wide.
    r.filter.assign(pieces, g, 0, &hit_plane);
    found.clear();
    index.query_if(
        [&](const Box& b) {
          // Another polygon found: no region; the rest need not be walked.
          if (!found.empty() && found.back() != hit.polygon) return false;
          return !r.filter.misses(b);
        },
        found);
    bool others = false;
    for (const std::uint32_t p : found) others = others || p != hit.polygon;
    if (others) continue;
    r.index = index.serial();
    r.light = light;
    r.polygon = hit.polygon;
    r.triangle = hit.triangle;
    r.box = g;
    next_ = (next_ + 1) % kRegions;
    return;
  }
  r.index = 0;  // its filter was overwritten
}

}  // namespace umbra::geometry::soft
