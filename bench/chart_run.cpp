#include "chart_run.h"

#include <umbra/raster/image_io.h>
#include <umbra/raster/methods/ikedo_functions.h>
#include <umbra/raster/methods/map_variants.h>
#include <umbra/util/huge_pages.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace umbra::bench {

namespace {

Setting map_setting(const std::string& curve, int resolution, double bias_factor,
                    raster::MapLookup lookup, int pcf,
                    raster::MapVariant variant = raster::MapVariant::depth,
                    raster::IdGranularity ids = raster::IdGranularity::object) {
  Setting s{"map", curve, {}};
  s.options.method = raster::Method::map;
  raster::ShadowMapOptions& m = s.options.map;
  m.variant = variant;
  m.id_granularity = ids;
  m.resolution = resolution;
  m.constant_bias *= bias_factor;
  m.slope_bias *= bias_factor;
  m.lookup = lookup;
  m.pcf = pcf;
  return s;
}

Setting ray_setting(const std::string& curve, double epsilon_factor) {
  Setting s{"ray", curve, {}};
  s.options.method = raster::Method::ray;
  s.options.ray.epsilon *= epsilon_factor;
  return s;
}

Setting volume_setting() {
  Setting s{"volume", "volume", {}};
  s.options.method = raster::Method::volume;
  return s;
}

Setting plain_setting() {
  Setting s{"plain", "no shadows", {}};
  s.options.method = raster::Method::volume;
  s.options.shadows = false;
  return s;
}

}  // namespace

std::vector<Setting> chart_settings(bool quick, int max_map_resolution, bool area) {
  using raster::IdGranularity;
  using raster::MapLookup;
  using raster::MapVariant;
  std::vector<Setting> out = {plain_setting(), volume_setting()};
  if (area) {
    for (const int n : quick ? std::vector<int>{16} : std::vector<int>{16, 64, 256, 1024}) {
      Setting r = ray_setting("ray, N light samples (16, 64, 256, 1024)", 1);
      r.options.ray.area_samples = n;
      out.push_back(r);
    }
    const std::vector<int> resolutions =
        quick ? std::vector<int>{512} : std::vector<int>{512, 1024, 2048};
    for (const int res : resolutions)
      if (res <= max_map_resolution)
        out.push_back(map_setting("map PCSS", res, 1, MapLookup::nearest, 1));
    // Ikedo's penumbra with each of his coefficient sets (quick: set a).
    using raster::IkedoCoefficients;
    const std::vector<IkedoCoefficients> sets =
        quick ? std::vector<IkedoCoefficients>{IkedoCoefficients::a}
              : std::vector<IkedoCoefficients>{IkedoCoefficients::a, IkedoCoefficients::b,
                                               IkedoCoefficients::c, IkedoCoefficients::d};
    for (const IkedoCoefficients set : sets)
      for (const int res : resolutions)
        if (res <= max_map_resolution) {
          Setting m =
              map_setting(fmt::format("map Ikedo, set {}", raster::ikedo_coefficients_name(set)),
                          res, 1, MapLookup::nearest, 1, MapVariant::ikedo);
          m.options.map.ikedo_coefficients = set;
          out.push_back(m);
        }
    return out;
  }
  for (const double f : quick ? std::vector<double>{1} : std::vector<double>{0, 1, 100})
    out.push_back(ray_setting("ray (epsilon x0, x1, x100 of default)", f));
  const std::vector<int> resolutions =
      quick ? std::vector<int>{256, 1024} : std::vector<int>{256, 512, 1024, 2048, 4096};
  struct Curve {
    const char* name;
    double bias;
    MapLookup lookup;
    int pcf;
    MapVariant variant = MapVariant::depth;
    IdGranularity ids = IdGranularity::object;
  };
  // The source papers' variants (issue 22): Williams' post-process and
  // Ikedo's ID buffer, an ID per object (his) and per polygon.
  const Curve post{"map post-process (Williams)", 1, MapLookup::nearest, 1,
                   MapVariant::post_process};
  const Curve object_ids{"map ID buffer per object (Ikedo)", 1, MapLookup::nearest, 1,
                         MapVariant::polygon_id};
  const Curve polygon_ids{"map ID buffer per polygon", 1,
                          MapLookup::nearest,          1,
                          MapVariant::polygon_id,      IdGranularity::polygon};
  const std::vector<Curve> curves =
      quick ? std::vector<Curve>{{"map nearest, default bias", 1, MapLookup::nearest, 1},
                                 post,
                                 object_ids}
            : std::vector<Curve>{{"map nearest, no bias", 0, MapLookup::nearest, 1},
                                 {"map nearest, default bias", 1, MapLookup::nearest, 1},
                                 {"map nearest, 4x bias", 4, MapLookup::nearest, 1},
                                 {"map bilinear, default bias", 1, MapLookup::bilinear, 1},
                                 {"map PCF 3x3, default bias", 1, MapLookup::nearest, 3},
                                 post,
                                 object_ids,
                                 polygon_ids};
  for (const Curve& c : curves)
    for (const int r : resolutions)
      if (r <= max_map_resolution)
        out.push_back(map_setting(c.name, r, c.bias, c.lookup, c.pcf, c.variant, c.ids));
  return out;
}

std::vector<Setting> sweep_settings() {
  const int map_default = raster::ShadowMapOptions{}.resolution;
  return {volume_setting(),
          ray_setting("ray", 1),
          map_setting("map 512", 512, 1, raster::MapLookup::nearest, 1),
          map_setting("map " + std::to_string(map_default) + " (default)", map_default, 1,
                      raster::MapLookup::nearest, 1),
          map_setting("map " + std::to_string(map_default) + " post-process", map_default, 1,
                      raster::MapLookup::nearest, 1, raster::MapVariant::post_process),
          map_setting("map " + std::to_string(map_default) + " ID per object", map_default, 1,
                      raster::MapLookup::nearest, 1, raster::MapVariant::polygon_id)};
}

Row run_setting(const geometry::Scene& scene, const raster::OracleTruth& truth,
                const Setting& setting, int runs, raster::Frame* last) {
  Row row;
  row.setting = setting;
  raster::Frame frame;
  // The runs reuse each other's buffers (util/huge_pages.h), as a sequence
  // of frames does.
  const util::ReuseHugePages reuse;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    frame = raster::render(scene, setting.options);
    row.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::vector<double> sorted = row.seconds;
  std::sort(sorted.begin(), sorted.end());
  row.median_seconds = sorted[sorted.size() / 2];
  if (last) *last = frame;
  if (setting.method == "plain") {
    row.is_scored = false;
    return row;
  }
  const raster::ShadowChannels channels = raster::shadow_channels(frame);
  const raster::ValidationReport report = raster::score_render(truth, channels);
  for (const raster::LightReport& l : report.lights) {
    if (l.soft) {
      row.soft_mismatches += l.mismatches;
      row.soft_scored += l.scored();
      row.soft_error_sum += l.sum_error;
      row.soft_max_error = std::max(row.soft_max_error, l.max_error);
    }
    if (l.tinted) {
      row.tau_mismatches += l.tau_mismatches;
      row.tau_only += l.mismatches - (l.false_lit + l.false_shadowed + l.wrong_range);
      row.tau_scored += l.scored();
      row.tau_error_sum += l.tau_sum_error;
      row.tau_max_error = std::max(row.tau_max_error, l.tau_max_error);
    }
    row.compared += l.compared;
    row.boundary += l.boundary;
    row.false_lit += l.false_lit;
    row.false_shadowed += l.false_shadowed;
    row.wrong_range += l.wrong_range;
  }
  return row;
}

std::string setting_label(const Setting& setting) {
  const raster::RenderOptions& o = setting.options;
  if (setting.method == "map") {
    // The depth variant's labels as before the variants (docs' pictures
    // name them); the others say which they are.
    std::string variant = o.map.variant == raster::MapVariant::depth
                              ? ""
                              : std::string("-") + raster::map_variant_name(o.map);
    if (o.map.variant == raster::MapVariant::ikedo)
      variant += std::string("-") + raster::ikedo_coefficients_name(o.map.ikedo_coefficients);
    return fmt::format("map-{}-{}-b{:g}-s{:g}-pcf{}{}", o.map.resolution,
                       o.map.lookup == raster::MapLookup::bilinear ? "bilinear" : "nearest",
                       o.map.constant_bias, o.map.slope_bias, o.map.pcf, variant);
  }
  if (setting.method == "ray")
    return fmt::format("ray-eps{:g}-n{}", o.ray.epsilon, o.ray.area_samples);
  return setting.method;
}

}  // namespace umbra::bench
