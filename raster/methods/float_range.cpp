#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/raster/methods/float_range.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

namespace umbra::raster {

void check_float_range(const geometry::Scene& scene, std::string_view method) {
  const std::string file = scene.source.empty() ? "scene" : scene.source.string();
  const auto refuse = [&](const std::string& what, double magnitude) {
    throw util::InputError(
        file + ": " + what,
        fmt::format("coordinates up to {:g} are beyond what --method {} computes in float "
                    "(at most 2^60, ~1.15e18); use --method volume or exact",
                    magnitude, method));
  };
  const auto check_direction = [&](const geometry::Vec3& direction, std::size_t i) {
    const double m = geometry::max_abs(direction);
    if (m > kMaxFloatCoordinate) refuse(fmt::format("lights[{}].direction", i), m);
    if (m < kMinFloatDirectionComponent)
      throw util::InputError(
          file + ": " + fmt::format("lights[{}].direction", i),
          fmt::format("is too small for --method {} to normalize in float (its largest "
                      "component must be at least 2^-60); use --method volume or exact",
                      method));
  };
  for (std::size_t m = 0; m < scene.models.size(); ++m) {
    double largest = 0;
    for (const geometry::Vec3& p : scene.models[m].vertices)
      largest = std::max(largest, geometry::max_abs(p));
    if (largest > kMaxFloatCoordinate)
      refuse(fmt::format("models[{}] ({})", m, scene.models[m].name), largest);
  }
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const geometry::Light& light = scene.lights[i];
    if (light.type == geometry::LightType::point) {
      if (geometry::max_abs(light.position) > kMaxFloatCoordinate)
        refuse(fmt::format("lights[{}].position", i), geometry::max_abs(light.position));
      // A spot's axis is normalized in float, as a directional light's direction.
      if (light.spot) check_direction(light.spot->axis, i);
    } else if (light.type == geometry::LightType::area) {
      double largest = 0;
      for (const geometry::Vec3& v : light.vertices)
        largest = std::max(largest, geometry::max_abs(v));
      if (largest > kMaxFloatCoordinate) refuse(fmt::format("lights[{}].vertices", i), largest);
    } else {
      check_direction(light.direction, i);
    }
  }
  for (const auto& [field, p] : {std::pair{"camera.eye", scene.camera.eye},
                                 std::pair{"camera.look_at", scene.camera.look_at}})
    if (geometry::max_abs(p) > kMaxFloatCoordinate) refuse(field, geometry::max_abs(p));
}

}  // namespace umbra::raster
