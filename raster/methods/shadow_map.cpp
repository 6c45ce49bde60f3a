// Depth views and a small even-odd polygon rasterizer for them: per row, the
// crossings of the polygon's edges with the row's centre line, sorted; texels
// whose centres lie between the 1st and 2nd, 3rd and 4th, ... crossing are
// covered. Depth is the occluder's plane along each texel's ray.
#include <umbra/raster/methods/shadow_map.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace umbra::raster {

using geometry::Vec3;

namespace {

constexpr int kBandRows = 16;  ///< rows a thread fills at a time

/// An occluder in one view: its texel-space outline and its plane.
struct Projected {
  std::vector<double> u, v;  ///< outline in continuous texel coordinates
  Vec3 normal;               ///< plane n·p = c in view space
  double c = 0;
  double zmin = 0, zmax = 0;  ///< depth range of the (clipped) outline
  int row0 = 0, row1 = 0;     ///< rows [row0, row1) whose centres it may cover
  std::uint32_t id = 0;
};

/// Sutherland–Hodgman against z >= near. For one half-space the even-odd
/// interior of the result is the clipped interior even for a concave
/// polygon: the extra edges on z = near come in opposite pairs.
std::vector<Vec3> clip_near(const std::vector<Vec3>& in, double near) {
  std::vector<Vec3> out;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Vec3& a = in[k];
    const Vec3& b = in[(k + 1) % in.size()];
    const bool a_in = a.z >= near, b_in = b.z >= near;
    if (a_in) out.push_back(a);
    if (a_in != b_in) out.push_back(a + ((near - a.z) / (b.z - a.z)) * (b - a));
  }
  return out;
}

std::optional<Projected> project_occluder(const MapView& view, const Occluder& occluder) {
  std::vector<Vec3> p;
  p.reserve(occluder.vertices.size());
  for (const Vec3& w : occluder.vertices) p.push_back(to_view(view, w));
  if (view.perspective) p = clip_near(p, view.near);
  if (p.size() < 3) return std::nullopt;
  Projected out;
  out.id = occluder.id;
  out.normal = geometry::newell(p);
  Vec3 centroid{0, 0, 0};
  for (const Vec3& q : p) centroid = centroid + q;
  out.c = geometry::dot(out.normal, centroid / static_cast<double>(p.size()));
  out.zmin = out.zmax = p[0].z;
  double vmin = 1e300, vmax = -1e300;
  const double s0 = view.origin_s(), texel = view.texel();
  for (const Vec3& q : p) {
    out.zmin = std::min(out.zmin, q.z);
    out.zmax = std::max(out.zmax, q.z);
    const double s = view.perspective ? q.x / q.z : q.x;
    const double t = view.perspective ? q.y / q.z : q.y;
    out.u.push_back((s - s0) / texel);
    out.v.push_back((t - s0) / texel);
    vmin = std::min(vmin, out.v.back());
    vmax = std::max(vmax, out.v.back());
  }
  // Rows whose centre j + 0.5 lies in [vmin, vmax].
  out.row0 = static_cast<int>(std::clamp(std::ceil(vmin - 0.5), 0.0, double(view.size())));
  out.row1 = static_cast<int>(std::clamp(std::floor(vmax - 0.5) + 1, 0.0, double(view.size())));
  if (out.row0 >= out.row1 || !std::isfinite(out.c)) return std::nullopt;
  return out;
}

/// What a texel keeps of the occluders covering it (Ikedo's buffers beside
/// the nearest depth: rasterize_layer).
enum class Keep : std::uint8_t { nearest, furthest_of_nearest, second_nearest };

/// Fills rows [j0, j1) of `map` with `o`'s depth where it is nearer (Keep::
/// nearest); or, given the nearest layer `first`, where `o` is the texel's
/// nearest object and farther, or is another object and nearer.
template <Keep keep>
void fill_rows(const MapView& view, const Projected& o, int j0, int j1, std::vector<double>& xs,
               DepthMap& map, const DepthMap* first = nullptr) {
  const int n = static_cast<int>(o.u.size());
  const double s0 = view.origin_s(), texel = view.texel();
  for (int j = std::max(j0, o.row0); j < std::min(j1, o.row1); ++j) {
    const double yc = j + 0.5;
    xs.clear();
    for (int k = 0; k < n; ++k) {
      int a = k, b = (k + 1) % n;
      if ((o.v[a] <= yc) == (o.v[b] <= yc)) continue;
      // The lower end first, so that an edge and its reverse (the pairs
      // clip_near makes) give the same crossing.
      if (o.v[a] > o.v[b]) std::swap(a, b);
      xs.push_back(o.u[a] + (yc - o.v[a]) * (o.u[b] - o.u[a]) / (o.v[b] - o.v[a]));
    }
    std::sort(xs.begin(), xs.end());
    const double t = s0 + yc * texel;
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Texels whose centre i + 0.5 lies in [x0, x1).
      const int i0 = static_cast<int>(std::clamp(std::ceil(xs[k] - 0.5), 0.0, double(map.size)));
      const int i1 =
          static_cast<int>(std::clamp(std::ceil(xs[k + 1] - 0.5), 0.0, double(map.size)));
      float* row = map.depth.data() + static_cast<std::size_t>(j) * map.size;
      std::uint32_t* ids =
          map.id.empty() ? nullptr : map.id.data() + static_cast<std::size_t>(j) * map.size;
      for (int i = i0; i < i1; ++i) {
        const double s = s0 + (i + 0.5) * texel;
        // The plane along the texel's ray; the clamp keeps an edge-on
        // occluder's depth inside the occluder (every point of a planar
        // polygon has a z between its vertices').
        const double z = view.perspective ? o.c / (o.normal.x * s + o.normal.y * t + o.normal.z)
                                          : (o.c - o.normal.x * s - o.normal.y * t) / o.normal.z;
        const float depth =
            static_cast<float>(std::isnan(z) ? o.zmin : std::clamp(z, o.zmin, o.zmax));
        if constexpr (keep == Keep::nearest) {
          if (!ids) {
            row[i] = std::min(row[i], depth);
          } else if (depth < row[i] || (depth == row[i] && o.id < ids[i])) {
            row[i] = depth;
            ids[i] = o.id;
          }
        } else {
          const std::uint32_t nearest = first->id_at(i, j);
          if (keep == Keep::furthest_of_nearest && o.id == nearest) {
            row[i] = std::max(row[i], depth);
          } else if (keep == Keep::second_nearest && o.id != nearest &&
                     (depth < row[i] || (depth == row[i] && o.id < ids[i]))) {
            row[i] = depth;
            ids[i] = o.id;
          }
        }
      }
    }
  }
}

}  // namespace

Vec3 to_view(const MapView& view, const Vec3& p) {
  const Vec3 w = p - view.origin;
  return {geometry::dot(w, view.right), geometry::dot(w, view.up), geometry::dot(w, view.axis)};
}

std::optional<ViewPoint> project(const MapView& view, const Vec3& p) {
  const Vec3 q = to_view(view, p);
  if (view.perspective && !(q.z > 0)) return std::nullopt;
  const double s = view.perspective ? q.x / q.z : q.x;
  const double t = view.perspective ? q.y / q.z : q.y;
  const double s0 = view.origin_s(), texel = view.texel();
  return ViewPoint{(s - s0) / texel, (t - s0) / texel, q.z};
}

std::array<MapView, 6> cube_views(const Vec3& light, int resolution, int margin, double near) {
  // (axis, right, up) per face; any orthonormal pair serves, lookups use the
  // same frame as rasterizing.
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  const std::array<std::array<Vec3, 3>, 6> frames{
      {{x, -z, y}, {-x, z, y}, {y, x, -z}, {-y, x, z}, {z, x, y}, {-z, -x, y}}};
  std::array<MapView, 6> views;
  for (int f = 0; f < 6; ++f) {
    MapView& v = views[f];
    v.perspective = true;
    v.origin = light;
    v.axis = frames[f][0];
    v.right = frames[f][1];
    v.up = frames[f][2];
    v.half_extent = 1;  // tan 45°
    v.resolution = resolution;
    v.margin = margin;
    v.near = near;
  }
  return views;
}

int cube_face(const Vec3& d) {
  const double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
  if (ax >= ay && ax >= az) return d.x >= 0 ? 0 : 1;
  if (ay >= az) return d.y >= 0 ? 2 : 3;
  return d.z >= 0 ? 4 : 5;
}

MapView directional_view(const Vec3& direction, const geometry::Box& bounds, int resolution,
                         int margin) {
  MapView v;
  v.perspective = false;
  v.axis = geometry::normalize(direction);
  // Any vector not parallel to the axis gives the frame.
  const Vec3 helper = std::fabs(v.axis.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  v.right = geometry::normalize(geometry::cross(v.axis, helper));
  v.up = geometry::cross(v.right, v.axis);
  const Vec3 centre = bounds.centre();
  double half = 0, depth = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{(k & 1) ? bounds.hi.x : bounds.lo.x, (k & 2) ? bounds.hi.y : bounds.lo.y,
                      (k & 4) ? bounds.hi.z : bounds.lo.z};
    const Vec3 w = corner - centre;
    half =
        std::max({half, std::fabs(geometry::dot(w, v.right)), std::fabs(geometry::dot(w, v.up))});
    depth = std::max(depth, std::fabs(geometry::dot(w, v.axis)));
  }
  // Depth counted from a plane just behind the scene, so that every stored
  // depth is positive and its float spacing grows with its distance.
  v.origin = centre - (depth * 1.01) * v.axis;
  v.half_extent = half > 0 ? half * 1.0001 : 1;
  v.resolution = resolution;
  v.margin = margin;
  return v;
}

namespace {

/// Projects every occluder into `view`, then calls fill(p, j0, j1, xs) for
/// each that may cover a band of kBandRows rows, bands on up to `threads`
/// threads.
template <class Fill>
void fill_bands(const MapView& view, std::span<const Occluder> occluders, unsigned threads,
                int size, Fill&& fill) {
  std::vector<Projected> projected;
  projected.reserve(occluders.size());
  for (const Occluder& o : occluders)
    if (std::optional<Projected> p = project_occluder(view, o)) projected.push_back(std::move(*p));
  const int bands = (size + kBandRows - 1) / kBandRows;
  util::parallel_for(bands, threads, [&](int band) {
    const int j0 = band * kBandRows, j1 = std::min(size, j0 + kBandRows);
    std::vector<double> xs;
    for (const Projected& p : projected)
      if (p.row0 < j1 && p.row1 > j0) fill(p, j0, j1, xs);
  });
}

}  // namespace

DepthMap rasterize_depth(const MapView& view, std::span<const Occluder> occluders, unsigned threads,
                         bool with_ids) {
  DepthMap map;
  map.size = view.size();
  map.depth.assign(static_cast<std::size_t>(map.size) * map.size, kNoOccluder);
  if (with_ids) map.id.assign(map.depth.size(), kNoId);
  fill_bands(view, occluders, threads, map.size,
             [&](const Projected& p, int j0, int j1, std::vector<double>& xs) {
               fill_rows<Keep::nearest>(view, p, j0, j1, xs, map);
             });
  return map;
}

DepthMap rasterize_layer(const MapView& view, std::span<const Occluder> occluders, unsigned threads,
                         DepthLayer layer, const DepthMap& nearest) {
  DepthMap map;
  map.size = view.size();
  const bool furthest = layer == DepthLayer::furthest_of_nearest;
  if (furthest) {
    map.depth = nearest.depth;  // the furthest is at least the nearest
  } else {
    map.depth.assign(static_cast<std::size_t>(map.size) * map.size, kNoOccluder);
    map.id.assign(map.depth.size(), kNoId);
  }
  fill_bands(view, occluders, threads, map.size,
             [&](const Projected& p, int j0, int j1, std::vector<double>& xs) {
               if (furthest)
                 fill_rows<Keep::furthest_of_nearest>(view, p, j0, j1, xs, map, &nearest);
               else
                 fill_rows<Keep::second_nearest>(view, p, j0, j1, xs, map, &nearest);
             });
  return map;
}

}  // namespace umbra::raster
