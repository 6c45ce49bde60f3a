#pragma once
// The scene as every part of umbra sees it after loading: world-space
// coordinates (transforms already applied, in doubles), validated values.
// Field meanings follow ../shared/DESIGN.md and docs/scene-format.md.
#include <umbra/geometry/vec3.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace umbra::geometry {

struct Rgb {
  double r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// A model's light passes through it (some channel of its transmittance
/// above 0) while it casts shadows: its shadows are coloured.
inline bool tinted(const Rgb& transmittance) {
  return transmittance.r > 0 || transmittance.g > 0 || transmittance.b > 0;
}

struct Camera {
  Vec3 eye{0, 0, 1};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov_y_deg = 40;
  int width = 640;
  int height = 480;
};

/// point and directional lights cast hard shadows (shadow.<i>); an area
/// light casts soft ones (visibility.<i>, the exact visible fraction V(P):
/// DESIGN.md "Area lights", docs/soft-shadows.md).
enum class LightType { point, directional, area };

/// Where the scene stands on Earth (DESIGN.md "Site and sun", docs/sun.md):
/// for lights of type "sun".
struct Site {
  double latitude_deg = 0;   ///< north positive
  double longitude_deg = 0;  ///< east positive
  double elevation_m = 0;
  double pressure_mbar = 1010;  ///< for refraction
  double temperature_c = 10;
  Vec3 up{0, 1, 0};      ///< the world axis pointing up (to the zenith)
  Vec3 north{0, 0, -1};  ///< the world axis pointing north, perpendicular to up
  Vec3 origin{0, 0, 0};  ///< the world point at the latitude and longitude
};

/// A sun light as the scene gave it, and where SPA put the sun.
struct SunInfo {
  std::string time;  ///< the ISO 8601 text
  double zenith_deg = 0, azimuth_deg = 0;
  /// The sun's centre below the horizon (elevation < 0 after refraction):
  /// it gives no light (Light::dark).
  bool below_horizon = false;
};

/// A spot light's cone (DESIGN.md "Spot lights", docs/spot-lights.md): a
/// point light that reaches only the samples H with
/// dot(H - L, axis) >= cos_outer·|H - L|·|axis| (the closed cone, decided
/// exactly on the doubles below; equality is a boundary). Between the inner
/// and the outer cone its light fades in shading only (glTF's falloff).
struct SpotCone {
  Vec3 axis;             ///< where the spot points: finite, non-zero, not normalized
  double inner_rad = 0;  ///< 0 <= inner_rad <= outer_rad (JSON: <)
  double outer_rad = 0.7853981633974483;  ///< <= pi/2 (glTF's default pi/4)
  double cos_inner = 1;                   ///< std::cos(inner_rad), for shading only
  double cos_outer = 0.7071067811865476;  ///< std::cos(outer_rad): THE number the range uses
};  // made by make_spot_cone (spot_cone.h), which computes both cosines once

/// Bergeron's light: full intensity up to dec_begin, then
/// ((light_end - d) / (light_end - dec_begin))^decrease, zero from light_end on.
/// A light without light_end is unlimited and never falls off.
struct Light {
  LightType type = LightType::point;
  Vec3 position;   ///< point lights: where the light is
  Vec3 direction;  ///< directional lights: the direction light travels (not normalized)
  /// Area lights: the light's polygon, at least three vertices. Its surface
  /// follows the rule for model polygons (polygon_surface.h): planar, its
  /// even-odd interior; non-planar, its fan triangles. Never empty for an
  /// area light, always empty for the others.
  std::vector<Vec3> vertices;
  Rgb intensity{1, 1, 1};
  /// Range (point lights only: an area light has none, a scene giving one is
  /// refused).
  double dec_begin = 0;
  std::optional<double> light_end;
  int decrease = 1;
  /// A sun light (`"type": "sun"`): a directional light whose direction
  /// is the sun's there and then; the rest of the struct as for any
  /// directional light.
  std::optional<SunInfo> sun;
  /// A spot light (`"type": "spot"`, glTF's spot): a point light (type
  /// point, `position`, the same range fields) limited to this cone.
  std::optional<SpotCone> spot;
  /// Gives no light at all (a sun below the horizon): every sample is out
  /// of range for it, it casts no volume and no footprint.
  bool dark = false;
};

/// One polygon: indices into its model's vertex list, in the file's order.
/// Its front side is the one from which the vertices run counter-clockwise.
using Polygon = std::vector<std::uint32_t>;

struct Model {
  std::string name;
  std::vector<Vec3> vertices;  ///< world space
  std::vector<Polygon> polygons;
  /// What each polygon is, from the file: empty when the format names
  /// nothing (meshes, inline polygons, glTF), else exactly one per polygon
  /// (polygon_names[k] names polygons[k]). A CityJSON model's are its
  /// surfaces' semantic types ("RoofSurface", "WallSurface", "GroundSurface",
  /// ...; "" for a surface without semantics), shared by the triangles of a
  /// surface with holes. Whatever copies or filters `polygons` keeps this in
  /// step.
  std::vector<std::string> polygon_names;
  Rgb color{0.8, 0.8, 0.8};
  /// Blinn-Phong highlight, added only for lights that reach the sample
  /// (never in shadow: Williams' remark on highlights). Black: none.
  Rgb specular{0, 0, 0};
  double shininess = 32;
  bool casts_shadows = true;
  /// The fraction of a point or directional light's intensity, per channel,
  /// that passes through one of its polygons (DESIGN.md "Transmittance",
  /// docs/transmittance.md): each in [0, 1]; black (the default) is opaque.
  Rgb transmittance{0, 0, 0};
  /// Whether `umbra footprint` partitions its polygons by default.
  bool receives = true;
};

/// Polygon p's name (a CityJSON surface's semantic type), or "" when the
/// model names none.
inline const std::string& polygon_name(const Model& model, std::size_t p) {
  static const std::string none;
  return p < model.polygon_names.size() ? model.polygon_names[p] : none;
}

/// Some receiving polygon of `models` has a name: the tables that list
/// receivers then carry a polygon_name column.
inline bool names_polygons(const std::vector<Model>& models) {
  for (const Model& m : models)
    for (const std::string& n : m.polygon_names)
      if (!n.empty()) return true;
  return false;
}

struct Scene {
  Camera camera;
  /// false: the file has no camera and `camera` is a placeholder nobody may
  /// use (loaded with SceneLoadOptions::require_camera false: shadow volumes
  /// need no eye; rendering and validating do).
  bool has_camera = true;
  Rgb ambient{0.08, 0.08, 0.08};
  std::optional<Site> site;  ///< needed by sun lights
  std::vector<Light> lights;
  std::vector<Model> models;
  std::filesystem::path source;  ///< the file it was read from (for messages)
  /// Every file read to load it: the scene file, its mesh files and glTF
  /// external buffers and images (outputs must not overwrite any of them).
  std::vector<std::filesystem::path> inputs;
};

/// Some shadow-casting model of `scene` lets light through (tinted): its
/// renders carry transmittance.<i> AOVs (docs/transmittance.md).
inline bool has_transmittance(const Scene& scene) {
  for (const Model& m : scene.models)
    if (m.casts_shadows && tinted(m.transmittance)) return true;
  return false;
}

/// How load_scene treats optional parts of a scene file.
struct SceneLoadOptions {
  /// true: a scene without a camera is refused (render, validate); false:
  /// it loads with Scene::has_camera false (umbra volume).
  bool require_camera = true;
};

}  // namespace umbra::geometry
