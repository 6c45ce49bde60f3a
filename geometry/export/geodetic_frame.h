#pragma once
// World points of a scene with a site as WGS84 longitude, latitude and
// ellipsoidal height, through PROJ (docs/sun.md, "GeoJSON").
//
// Frames: world units are metres. A world point p is first put in the
// site's local east-north-up frame, e = (p − origin)·Ê, n = (p − origin)·N̂,
// u = (p − origin)·Û, with Û = up/|up|, Ê = (north × up)/|north × up| and
// N̂ = Û × Ê (right-handed; N̂ is the site's north made exactly
// perpendicular to up, which it already is to a relative 1e-12). The ENU
// frame is PROJ's topocentric frame of the WGS84 ellipsoid at the site's
// latitude, longitude and elevation_m, taken as the origin's ellipsoidal
// height: its east-north plane is tangent to the ellipsoid there, so a
// horizontal world plane is a tangent plane, not a surface of constant
// height (it rises by d²/(2R), 8 cm at 1 km). PROJ then inverts the
// topocentric conversion and the geocentric one (closed-form, no grids, no
// network) and converts radians to degrees.
#include <umbra/geometry/scene.h>
#include <umbra/geometry/vec3.h>

#include <memory>

namespace umbra::geometry {

/// WGS84 geodetic coordinates: degrees east, degrees north, metres above
/// the ellipsoid.
struct Geodetic {
  double longitude_deg = 0;
  double latitude_deg = 0;
  double height_m = 0;
};

/// One site's world-to-WGS84 conversion. It owns its PROJ context, so
/// frames on different threads are independent; one frame must not be
/// used by two threads at once (PROJ's objects keep state per call).
class GeodeticFrame {
 public:
  /// Throws std::runtime_error, one line, when PROJ cannot build the
  /// pipeline (a latitude or longitude out of range).
  explicit GeodeticFrame(const Site& site);
  ~GeodeticFrame();
  GeodeticFrame(GeodeticFrame&&) noexcept;
  GeodeticFrame& operator=(GeodeticFrame&&) noexcept;
  GeodeticFrame(const GeodeticFrame&) = delete;
  GeodeticFrame& operator=(const GeodeticFrame&) = delete;

  /// The world point in the site's east-north-up frame, metres (doubles:
  /// each coordinate within a few ulps of |p − origin|).
  Vec3 to_enu(const Vec3& world) const;

  /// The world point in WGS84. Throws std::runtime_error, one line, on a
  /// PROJ error or a non-finite result (a point too far from the site).
  Geodetic to_wgs84(const Vec3& world);

  /// The PROJ pipeline this frame runs (for messages and docs).
  const std::string& pipeline() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace umbra::geometry
