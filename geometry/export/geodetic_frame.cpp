// PROJ's C API behind GeodeticFrame (the only file that includes proj.h).
// Accuracy: the inverse geocentric conversion is closed-form and the rest
// are rotations. Within 5 km of a site, PROJ's answer is within 1e-12
// degrees (0.1 µm) and 1e-7 m of height of an independent long-double
// iteration (tests/geometry/export/geodetic_frame_test.cpp; measured worst
// 3.6e-13 degrees, 4e-8 m, and 3.2e-8 m of height); the doubles written
// add 1e-14 degrees (a nanometre).
#include <umbra/geometry/export/geodetic_frame.h>
#include <umbra/geometry/export/mesh_text.h>

#include <proj.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace umbra::geometry {

struct GeodeticFrame::Impl {
  PJ_CONTEXT* context = nullptr;
  PJ* pipeline = nullptr;
  std::string definition;
  Vec3 origin, east, north, up;

  ~Impl() {
    if (pipeline) proj_destroy(pipeline);
    if (context) proj_context_destroy(context);
  }

  [[noreturn]] void fail(const std::string& what, int error) const {
    const char* text = proj_context_errno_string(context, error);
    throw std::runtime_error("PROJ: " + what + ": " + (text ? text : "unknown error") + " (" +
                             definition + ")");
  }
};

namespace {

std::string number(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

}  // namespace

GeodeticFrame::GeodeticFrame(const Site& site) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.origin = site.origin;
  m.up = normalize(site.up);
  m.east = normalize(cross(site.north, site.up));
  m.north = cross(m.up, m.east);
  // Inverse topocentric: ENU metres at the site to geocentric X, Y, Z;
  // inverse cart: geocentric to longitude, latitude (radians) and
  // ellipsoidal height; unitconvert: radians to degrees. x is longitude.
  m.definition = "+proj=pipeline +step +inv +proj=topocentric +ellps=WGS84 +lat_0=" +
                 number(site.latitude_deg) + " +lon_0=" + number(site.longitude_deg) +
                 " +h_0=" + number(site.elevation_m) +
                 " +step +inv +proj=cart +ellps=WGS84"
                 " +step +proj=unitconvert +xy_in=rad +xy_out=deg";
  // A context of its own (thread safety), silent (errors become exceptions
  // here, not lines on stderr), never on the network (no grids are needed).
  m.context = proj_context_create();
  if (!m.context) throw std::runtime_error("PROJ: cannot create a context");
  proj_log_level(m.context, PJ_LOG_NONE);
  proj_context_set_enable_network(m.context, 0);
  m.pipeline = proj_create(m.context, m.definition.c_str());
  if (!m.pipeline) m.fail("cannot build the site's pipeline", proj_context_errno(m.context));
}

GeodeticFrame::~GeodeticFrame() = default;
GeodeticFrame::GeodeticFrame(GeodeticFrame&&) noexcept = default;
GeodeticFrame& GeodeticFrame::operator=(GeodeticFrame&&) noexcept = default;

Vec3 GeodeticFrame::to_enu(const Vec3& world) const {
  const Vec3 d = world - impl_->origin;
  return {dot(d, impl_->east), dot(d, impl_->north), dot(d, impl_->up)};
}

Geodetic GeodeticFrame::to_wgs84(const Vec3& world) {
  const Vec3 enu = to_enu(world);
  proj_errno_reset(impl_->pipeline);
  const PJ_COORD out = proj_trans(impl_->pipeline, PJ_FWD, proj_coord(enu.x, enu.y, enu.z, 0));
  if (const int error = proj_errno(impl_->pipeline))
    impl_->fail("cannot convert (" + number(world.x) + ", " + number(world.y) + ", " +
                    number(world.z) + ")",
                error);
  const Geodetic g{out.xyz.x, out.xyz.y, out.xyz.z};
  if (!std::isfinite(g.longitude_deg) || !std::isfinite(g.latitude_deg) ||
      !std::isfinite(g.height_m))
    throw std::runtime_error("PROJ: (" + number(world.x) + ", " + number(world.y) + ", " +
                             number(world.z) + ") has no finite longitude and latitude (" +
                             impl_->definition + ")");
  return g;
}

const std::string& GeodeticFrame::pipeline() const { return impl_->definition; }

}  // namespace umbra::geometry
