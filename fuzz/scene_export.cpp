#include <fuzz/scene_export.h>
#include <umbra/geometry/exact/visible_surface.h>
#include <umbra/geometry/io/scene_json.h>
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/geometry/sample_ray.h>
#include <umbra/raster/image_io.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <fstream>
#include <stdexcept>

namespace umbra::fuzz {

namespace fs = std::filesystem;
using nlohmann::json;

TruthMasks oracle_truth(const geometry::Scene& scene) {
  TruthMasks t;
  t.width = scene.camera.width;
  t.height = scene.camera.height;
  const std::size_t total = static_cast<std::size_t>(t.width) * t.height;
  t.cls.assign(scene.lights.size(), std::vector<std::uint8_t>(total, TruthMasks::kBackground));
  t.boundary.assign(scene.lights.size(), std::vector<std::uint8_t>(total, 0));
  const geometry::SceneIndex index(scene);
  const geometry::CameraFrame camera = geometry::camera_frame(scene.camera);
  for (int j = 0; j < t.height; ++j) {
    for (int i = 0; i < t.width; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * t.width + i;
      const geometry::SampleRay ray = geometry::sample_ray(camera, i, j);
      const auto hit = geometry::first_hit(index, ray);
      if (!hit) continue;
      for (std::uint32_t l = 0; l < scene.lights.size(); ++l) {
        const geometry::ShadowAnswer a = geometry::classify_sample(index, ray, *hit, l);
        t.cls[l][p] = a.cls == geometry::ShadowClass::lit        ? TruthMasks::kLit
                      : a.cls == geometry::ShadowClass::shadowed ? TruthMasks::kShadowed
                                                                 : TruthMasks::kOutOfRange;
        t.boundary[l][p] = a.boundary ? 1 : 0;
      }
    }
  }
  return t;
}

namespace {

json vec(const geometry::Vec3& v) { return json::array({v.x, v.y, v.z}); }

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw util::InputError(path.string(), "cannot write");
}

bool same_bits(const geometry::Vec3& a, const geometry::Vec3& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

/// The first field of `back` whose bits differ from `scene`'s, or "" when
/// every coordinate the checks use is the same double.
std::string first_difference(const geometry::Scene& scene, const geometry::Scene& back) {
  if (back.models.size() != scene.models.size()) return "number of models";
  if (back.lights.size() != scene.lights.size()) return "number of lights";
  if (!same_bits(back.camera.eye, scene.camera.eye)) return "camera.eye";
  if (!same_bits(back.camera.look_at, scene.camera.look_at)) return "camera.look_at";
  for (std::size_t k = 0; k < scene.models.size(); ++k) {
    const auto& a = scene.models[k];
    const auto& b = back.models[k];
    if (b.vertices.size() != a.vertices.size() || b.polygons != a.polygons)
      return fmt::format("models[{}] polygons", k);
    for (std::size_t v = 0; v < a.vertices.size(); ++v)
      if (!same_bits(b.vertices[v], a.vertices[v]))
        return fmt::format("models[{}].vertices[{}]", k, v);
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const auto& a = scene.lights[l];
    const auto& b = back.lights[l];
    if (!same_bits(b.position, a.position)) return fmt::format("lights[{}].position", l);
    if (!same_bits(b.direction, a.direction)) return fmt::format("lights[{}].direction", l);
    if (b.light_end != a.light_end) return fmt::format("lights[{}].light_end", l);
  }
  return "";
}

}  // namespace

namespace {
/// Camera, ambient and lights of the scene format.
json scene_header(const geometry::Scene& scene) {
  json doc;
  const auto& cam = scene.camera;
  doc["camera"] = {{"eye", vec(cam.eye)}, {"look_at", vec(cam.look_at)},
                   {"up", vec(cam.up)},   {"fov_y_deg", cam.fov_y_deg},
                   {"width", cam.width},  {"height", cam.height}};
  doc["ambient"] = json::array({scene.ambient.r, scene.ambient.g, scene.ambient.b});
  doc["lights"] = json::array();
  for (const auto& l : scene.lights) {
    json j;
    j["intensity"] = json::array({l.intensity.r, l.intensity.g, l.intensity.b});
    if (l.type == geometry::LightType::point) {
      j["type"] = "point";
      j["position"] = vec(l.position);
      if (l.light_end) {
        j["dec_begin"] = l.dec_begin;
        j["light_end"] = *l.light_end;
      }
    } else {
      j["type"] = "directional";
      j["direction"] = vec(l.direction);
    }
    doc["lights"].push_back(j);
  }
  return doc;
}
}  // namespace

std::string scene_to_json(const geometry::Scene& scene) {
  json doc = scene_header(scene);
  doc["models"] = json::array();
  for (const geometry::Model& m : scene.models) {
    json vertices = json::array();
    for (const auto& v : m.vertices) vertices.push_back(vec(v));
    doc["models"].push_back({{"name", m.name},
                             {"polygons", {{"vertices", vertices}, {"faces", m.polygons}}},
                             {"casts_shadows", m.casts_shadows}});
  }
  return doc.dump();
}

void export_scene(const GeneratedScene& generated, const TruthMasks& truth, const fs::path& dir) {
  const geometry::Scene& scene = generated.scene;
  const fs::path root = dir / generated.name;
  std::error_code ec;
  fs::create_directories(root / "meshes", ec);
  if (ec) throw util::InputError((root / "meshes").string(), ec.message());

  json doc = scene_header(scene);
  doc["models"] = json::array();
  for (std::size_t k = 0; k < scene.models.size(); ++k) {
    const geometry::Model& m = scene.models[k];
    const std::string mesh = fmt::format("meshes/{}_{}.off", k, m.name);
    // OFF with the shortest decimal that reads back as the same double.
    std::string off = fmt::format("OFF\n{} {} 0\n", m.vertices.size(), m.polygons.size());
    for (const auto& v : m.vertices) off += fmt::format("{} {} {}\n", v.x, v.y, v.z);
    for (const auto& p : m.polygons) {
      off += std::to_string(p.size());
      for (auto i : p) off += fmt::format(" {}", i);
      off += "\n";
    }
    write_file(root / mesh, off);
    doc["models"].push_back({{"name", m.name},
                             {"mesh", mesh},
                             {"color", json::array({m.color.r, m.color.g, m.color.b})},
                             {"casts_shadows", m.casts_shadows}});
  }
  write_file(root / "scene.json", doc.dump(2) + "\n");

  // Truth images: per light the class, and the boundary mask.
  const std::size_t total = static_cast<std::size_t>(truth.width) * truth.height;
  json counts = json::array();
  for (std::size_t l = 0; l < truth.cls.size(); ++l) {
    std::vector<float> rgb(total * 3), mask(total * 3);
    std::uint64_t n[4] = {0, 0, 0, 0}, boundary = 0;
    for (std::size_t p = 0; p < total; ++p) {
      const std::uint8_t c = truth.cls[l][p];
      float r = 0, g = 0, b = 0;
      if (c == TruthMasks::kLit)
        r = g = b = 1, ++n[0];
      else if (c == TruthMasks::kShadowed)
        ++n[1];
      else if (c == TruthMasks::kOutOfRange)
        r = g = b = 0.5f, ++n[2];
      else
        b = 1, ++n[3];
      rgb[3 * p] = r, rgb[3 * p + 1] = g, rgb[3 * p + 2] = b;
      const float m = truth.boundary[l][p] ? 1.0f : 0.0f;
      boundary += truth.boundary[l][p];
      mask[3 * p] = mask[3 * p + 1] = mask[3 * p + 2] = m;
    }
    raster::write_rgb_png(root / fmt::format("truth.{}.png", l), truth.width, truth.height, rgb);
    raster::write_rgb_png(root / fmt::format("boundary.{}.png", l), truth.width, truth.height,
                          mask);
    counts.push_back({{"light", l},
                      {"lit", n[0]},
                      {"shadowed", n[1]},
                      {"out_of_range", n[2]},
                      {"background", n[3]},
                      {"boundary", boundary}});
  }
  json info;
  info["name"] = generated.name;
  info["features"] = generated.features;
  info["placements"] = json::array();  // per light: where the generator put it
  for (const auto& p : generated.placements) info["placements"].push_back(describe(p));
  info["width"] = truth.width;
  info["height"] = truth.height;
  info["lights"] = counts;
  info["legend"] =
      "truth.<i>.png: white lit, black shadowed, grey out of range, blue background; "
      "boundary.<i>.png: white where either answer is right (DESIGN.md)";
  write_file(root / "truth.json", info.dump(2) + "\n");

  // The files must say exactly what was checked.
  const geometry::Scene back = geometry::load_scene(root / "scene.json");
  const std::string differs = first_difference(scene, back);
  if (!differs.empty())
    throw std::runtime_error(
        root.string() + ": the exported scene does not read back bit for bit (" + differs + ")");
}

}  // namespace umbra::fuzz
