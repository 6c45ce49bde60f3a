#include <cli/output_files.h>
#include <cli/stats_json.h>
#include <umbra/raster/methods/ikedo_functions.h>
#include <umbra/raster/methods/map_variants.h>
#include <umbra/util/cpu_budget.h>

#include <cstdio>

namespace umbra::cli {

nlohmann::ordered_json render_stats_json(const RenderRun& run, const raster::RenderStats& stats,
                                         const RenderTimings& timings) {
  nlohmann::ordered_json j;
  j["scene"] = run.scene;
  j["output"] = run.output;
  j["method"] = run.method;
  j["threads"] = run.threads;  // as asked; 0 means the CPUs the process may use
  j["threads_used"] = util::resolve_threads(run.threads);
  j["width"] = run.width;
  j["height"] = run.height;
  j["lights"] = run.lights;
  j["models"] = run.models;
  if (!run.suns.empty()) {
    j["sun"] = nlohmann::ordered_json::array();
    for (const auto& [light, sun] : run.suns)
      j["sun"].push_back({{"light", light},
                          {"time", sun.time},
                          {"azimuth_deg", sun.azimuth_deg},
                          {"zenith_deg", sun.zenith_deg},
                          {"below_horizon", sun.below_horizon}});
  }
  j["seconds"] = {
      {"load", timings.load},           {"volumes", stats.seconds_volumes},
      {"raster", stats.seconds_raster}, {"raster_prepare", stats.seconds_raster_prepare},
      {"maps", stats.seconds_maps},     {"decide", stats.seconds_decide},
      {"bvh", stats.seconds_bvh},       {"render", timings.render},
      {"write", timings.write},         {"total", timings.total},
  };
  j["counts"] = {
      {"pixels", stats.pixels},
      {"contour_edges", stats.contour_edges},
      {"shadow_polygons", stats.shadow_polygons},
      {"surface_polygons", stats.surface_polygons},
      {"spans", stats.spans},
      {"shadow_bands_skipped", stats.shadow_bands_skipped},
      {"exact_fallback_pixels", stats.exact_fallback_pixels},
      {"exact_light_recounts", stats.exact_light_recounts},
      {"area_exact_samples", stats.area_exact_samples},
      {"light_pixels", stats.light_pixels},
      {"twisted_polygons", stats.twisted_polygons},
      {"eye_degenerate_lights", stats.eye_degenerate_lights},
      {"tint_channels", stats.tint_channels},
      {"boundary_edges", stats.boundary_edges},
      {"non_manifold_edges", stats.non_manifold_edges},
      {"degenerate_polygons", stats.degenerate_polygons},
      {"primary_rays", stats.primary_rays},
      {"shadow_rays", stats.shadow_rays},
      {"map_views", stats.map_views},
      {"map_texels", stats.map_texels},
      {"map_lookups", stats.map_lookups},
  };
  // The ray method's parameter as the renderer took it, and what it meant in
  // scene units (docs/ray-cast.md).
  if (run.ray_epsilon) j["ray"] = {{"epsilon", *run.ray_epsilon}, {"offset", stats.ray_offset}};
  if (run.map) {
    // The settings beside the numbers, so that a benchmark's record says
    // which map it measured.
    const raster::ShadowMapOptions& m = *run.map;
    j["map"] = {
        {"resolution", m.resolution},
        {"constant_bias", m.constant_bias},
        {"slope_bias", m.slope_bias},
        {"lookup", m.lookup == raster::MapLookup::bilinear ? "bilinear" : "nearest"},
        {"dither", m.dither},
        {"pcf", m.pcf},
        {"variant", raster::map_variant_name(m)},
    };
    if (m.variant == raster::MapVariant::ikedo) {
      j["map"]["ikedo_coefficients"] = raster::ikedo_coefficients_name(m.ikedo_coefficients);
      j["map"]["ikedo_filter"] = m.ikedo_corners == raster::IkedoCorners::two ? "bi" : "crossed";
    }
  }
  return j;
}

nlohmann::ordered_json validation_json(const ValidateRun& run,
                                       const raster::ValidationReport& report) {
  nlohmann::ordered_json j;
  j["scene"] = run.scene;
  j["image"] = run.image;
  j["mask"] = run.mask ? nlohmann::ordered_json(*run.mask) : nlohmann::ordered_json();
  j["width"] = report.width;
  j["height"] = report.height;
  j["samples"] = run.samples == 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(run.samples);
  j["seed"] = run.seed;
  j["pixels_checked"] = report.pixels_checked;
  j["background"] = report.background;
  j["lights"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < report.lights.size(); ++i) {
    const raster::LightReport& light = report.lights[i];
    if (light.soft) {
      // An area light is judged by |V_image - V| (DESIGN.md's 1e-6 rule).
      j["lights"].push_back({
          {"light", i},
          {"kind", "area"},
          {"compared", light.compared},
          {"boundary", light.boundary},
          {"mismatches", light.mismatches},
          {"max_error", light.max_error},
          {"mean_error", light.mean_error()},
          {"tolerance", raster::kVisibilityTolerance},
      });
      continue;
    }
    j["lights"].push_back({
        {"light", i},
        {"compared", light.compared},
        {"boundary", light.boundary},
        {"mismatches", light.mismatches},
        {"false_lit", light.false_lit},
        {"false_shadowed", light.false_shadowed},
        {"wrong_range", light.wrong_range},
    });
    if (light.tinted)
      j["lights"].back()["transmittance"] = {
          {"mismatches", light.tau_mismatches},
          {"max_error", light.tau_max_error},
          {"mean_error", light.tau_mean_error()},
          {"tolerance", raster::kVisibilityTolerance},
      };
  }
  j["total_mismatches"] = report.total_mismatches();
  return j;
}

VolumeCounts count_volume_faces(const geometry::ShadowVolumes& volumes, std::size_t lights) {
  VolumeCounts counts;
  counts.lights.resize(lights);
  for (const geometry::ShadowPolygon& p : volumes.polygons) {
    if (p.light >= counts.lights.size()) counts.lights.resize(p.light + std::size_t{1});
    const auto type = static_cast<std::size_t>(p.type);
    for (FaceCounts* c : {&counts.all, &counts.lights[p.light]}) {
      ++c->total;
      if (type >= 1 && type <= 3) ++c->type[type - 1];
      if (p.twisted) ++c->twisted;
    }
  }
  return counts;
}

namespace {

nlohmann::ordered_json faces_json(const FaceCounts& c) {
  return {{"total", c.total},
          {"type_1", c.type[0]},
          {"type_2", c.type[1]},
          {"type_3", c.type[2]},
          {"twisted", c.twisted}};
}

}  // namespace

nlohmann::ordered_json volume_stats_json(const VolumeRun& run,
                                         const geometry::ShadowVolumes& volumes,
                                         const VolumeCounts& counts, const VolumeTimings& timings) {
  nlohmann::ordered_json j;
  j["scene"] = run.scene;
  j["output"] = run.output;
  j["sidecar"] =
      run.sidecar.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(run.sidecar);
  j["lights"] = run.lights;
  j["models"] = run.models;
  j["seconds"] = {{"load", timings.load},
                  {"volumes", timings.volumes},
                  {"write", timings.write},
                  {"total", timings.total}};
  j["faces"] = faces_json(counts.all);
  j["per_light"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < counts.lights.size(); ++i) {
    geometry::VolumeStats stats;
    stats.light = static_cast<std::uint32_t>(i);
    for (const geometry::VolumeStats& s : volumes.stats)
      if (s.light == i) stats = s;
    j["per_light"].push_back({
        {"light", i},
        {"contour_edges", stats.contour_edges},
        {"boundary_contour_edges", stats.boundary_contour_edges},
        {"silhouette_contour_edges", stats.silhouette_contour_edges},
        {"side_polygons", stats.side_polygons},
        {"near_caps", stats.near_caps},
        {"far_caps", stats.far_caps},
        {"twisted_polygons", stats.twisted_polygons},
        {"crow_all_edges_polygons", stats.crow_all_edges_polygons},
        {"culled_models", stats.culled_models},
        {"culled_polygons", stats.culled_polygons},
        {"truncated_models", stats.truncated_models},
        {"bytes", stats.bytes},
        {"crow_bytes", stats.crow_bytes},
        {"seconds", stats.seconds},
        {"faces", faces_json(counts.lights[i])},
    });
  }
  return j;
}

void emit_json(const nlohmann::ordered_json& json, const std::string& destination) {
  // Paths need not be UTF-8; replace bad bytes rather than fail after the work is done.
  const std::string text =
      json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  if (destination == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
  } else {
    write_text_file(destination, text);
  }
}

}  // namespace umbra::cli
