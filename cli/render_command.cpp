#include <cli/exit_codes.h>
#include <cli/memory_limit.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <cli/progress_bar.h>
#include <cli/render_command.h>
#include <cli/scene_loading.h>
#include <cli/stats_json.h>
#include <umbra/raster/image_io.h>
#include <umbra/raster/memory_estimate.h>
#include <umbra/raster/methods/ikedo_functions.h>
#include <umbra/raster/methods/map_variants.h>
#include <umbra/raster/render.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace umbra::cli {

namespace fs = std::filesystem;

namespace {

/// The parser has already restricted `name` to these (case-insensitively,
/// and CLI11 hands back the canonical spelling).
raster::Method parse_method(const std::string& name) {
  if (name == "exact") return raster::Method::exact;
  if (name == "map") return raster::Method::map;
  if (name == "ray") return raster::Method::ray;
  return raster::Method::volume;
}

/// A method's parameters given with another method are a mistake, not
/// something to ignore silently.
void check_method_options(const RenderArgs& args) {
  const bool map_given = args.map_resolution || args.map_bias || args.map_slope_bias ||
                         args.map_lookup || args.map_dither || args.map_pcf || args.map_variant;
  if (map_given && args.method != "map")
    throw util::InputError("--map-*", "applies to --method map only");
  // Ikedo's buffer compares IDs, and depths only without bias: a bias given
  // with it would be silently ignored.
  if (args.map_variant && args.map_variant->starts_with("id") &&
      (args.map_bias || args.map_slope_bias))
    throw util::InputError("--map-bias", "does not apply to --map-variant id (no depth bias)");
  const bool ikedo = args.map_variant == "ikedo";
  if (ikedo && (args.map_bias || args.map_slope_bias))
    throw util::InputError("--map-bias", "does not apply to --map-variant ikedo (no depth bias)");
  if ((args.ikedo_coeffs || args.ikedo_filter) && !ikedo)
    throw util::InputError("--ikedo-*", "applies to --method map --map-variant ikedo only");
  if (args.ray_epsilon && args.method != "ray")
    throw util::InputError("--ray-epsilon", "applies to --method ray only");
  if (args.area_samples && args.method != "ray")
    throw util::InputError("--area-samples", "applies to --method ray only");
}

/// A label of what a tile was rendered from: the bytes of every file the
/// scene reads and every option that changes a pixel (FNV-1a, 64 bits).
/// umbra merge refuses tiles whose labels differ.
std::string job_label(const geometry::Scene& scene, const RenderArgs& args) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto add = [&](std::string_view bytes) {
    for (const unsigned char c : bytes) hash = (hash ^ c) * 0x100000001b3ull;
    hash = (hash ^ 0xff) * 0x100000001b3ull;  // a separator
  };
  for (const fs::path& input : scene.inputs) add(util::read_input_file(input, "scene input"));
  // Exposure and area samples only when given, so that labels of earlier
  // tiles still match.
  add(fmt::format("method={} spp={} shadows={} map={},{},{},{},{},{} ray={}{}{}{}{}{}", args.method,
                  args.spp, !args.no_shadows, args.map_resolution.value_or(-1),
                  args.map_bias.value_or(-1), args.map_slope_bias.value_or(-1),
                  args.map_lookup.value_or(""), args.map_dither, args.map_pcf.value_or(-1),
                  args.ray_epsilon.value_or(-1),
                  args.exposure != 0 ? fmt::format(" exposure={}", args.exposure) : "",
                  args.area_samples ? fmt::format(" area_samples={}", *args.area_samples) : "",
                  args.map_variant ? fmt::format(" map_variant={}", *args.map_variant) : "",
                  args.ikedo_coeffs ? fmt::format(" ikedo_coeffs={}", *args.ikedo_coeffs) : "",
                  args.ikedo_filter ? fmt::format(" ikedo_filter={}", *args.ikedo_filter) : ""));
  return fmt::format("{:016x}", hash);
}

/// -v: a line per light, then the counts and times per phase, on stderr.
void print_render_details(const geometry::Scene& scene, const raster::RenderStats& stats,
                          const RenderTimings& timings) {
  for (std::size_t i = 0; i < scene.lights.size(); ++i)
    fmt::print(stderr, "light {}: {}\n", i, describe_light(scene.lights[i]));
  fmt::print(stderr,
             "counts: {} pixels, {} contour edges, {} shadow polygons, {} twisted polygons\n",
             stats.pixels, stats.contour_edges, stats.shadow_polygons, stats.twisted_polygons);
  fmt::print(stderr,
             "seconds: load {:.3f}, volumes {:.3f}, raster {:.3f}, decide {:.3f}, render {:.3f}, "
             "write {:.3f}, total {:.3f}\n",
             timings.load, stats.seconds_volumes, stats.seconds_raster, stats.seconds_decide,
             timings.render, timings.write, timings.total);
}

/// A finite number of stops with |EV| <= raster::kMaxExposure.
CLI::Validator exposure_stops() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        const char* last = text.data() + text.size();
        const auto [end, ec] = std::from_chars(text.data(), last, value);
        if (text.empty() || ec != std::errc() || end != last ||
            !(std::abs(value) <= raster::kMaxExposure))
          return fmt::format("'{}' is not a finite number of stops from -{} to {}", text,
                             raster::kMaxExposure, raster::kMaxExposure);
        return {};
      },
      fmt::format("-{}..{}", raster::kMaxExposure, raster::kMaxExposure));
}

raster::ShadowMapOptions map_options(const RenderArgs& args) {
  raster::ShadowMapOptions map;
  if (args.map_resolution) map.resolution = *args.map_resolution;
  if (args.map_bias) map.constant_bias = *args.map_bias;
  if (args.map_slope_bias) map.slope_bias = *args.map_slope_bias;
  if (args.map_lookup)
    map.lookup =
        *args.map_lookup == "bilinear" ? raster::MapLookup::bilinear : raster::MapLookup::nearest;
  map.dither = args.map_dither;
  if (args.map_pcf) map.pcf = *args.map_pcf;
  if (args.map_variant) {
    const std::string& v = *args.map_variant;
    map.variant = v == "post"           ? raster::MapVariant::post_process
                  : v == "ikedo"        ? raster::MapVariant::ikedo
                  : v.starts_with("id") ? raster::MapVariant::polygon_id
                                        : raster::MapVariant::depth;
    if (v == "id-polygon") map.id_granularity = raster::IdGranularity::polygon;
  }
  if (args.ikedo_coeffs)  // one of the sets' names (the option's IsMember)
    for (const auto set : {raster::IkedoCoefficients::a, raster::IkedoCoefficients::b,
                           raster::IkedoCoefficients::c, raster::IkedoCoefficients::d})
      if (*args.ikedo_coeffs == raster::ikedo_coefficients_name(set)) map.ikedo_coefficients = set;
  if (args.ikedo_filter == "bi") map.ikedo_corners = raster::IkedoCorners::two;
  return map;
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
  // The --map-* and --ray-* options are unset unless given (a method's
  // options with another method are refused); --help shows the library's
  // defaults they stand for.
  const raster::ShadowMapOptions kMapDefaults{};
  CLI::App* cmd = app.add_subcommand("render", "Render a scene with its shadows");
  cmd->add_option("SCENE", args.scene, "Scene file (.json, .gltf or .glb)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args.output,
                  "Output image: .png (beauty) or .exr (beauty + shadow.<i>, count.<i>, depth); "
                  "default <scene stem>.png in the current directory")
      ->check(non_empty_path())
      ->type_name("OUT");
  cmd->add_option("--method", args.method,
                  "Shadow method: volume (exact at every sample), map (Williams' shadow "
                  "maps), ray (Embree occlusion rays) or exact (the oracle; slow)")
      ->transform(CLI::IsMember({"volume", "map", "ray", "exact"}, CLI::ignore_case))
      ->type_name("METHOD");
  cmd->add_option("--map-resolution", args.map_resolution,
                  "Texels across each shadow-map view: a 90° cube face of a point light, the "
                  "scene's extent for a directional light (map only)")
      ->check(CLI::Range(1, 16384))
      ->default_str(std::to_string(kMapDefaults.resolution))
      ->type_name("N");
  cmd->add_option("--map-bias", args.map_bias,
                  "Constant depth bias in float depth spacings at the sample's depth, as "
                  "glPolygonOffset's units (map only; docs/shadow-maps.md)")
      ->check(finite_non_negative())
      ->default_str(fmt::format("{}", kMapDefaults.constant_bias))
      ->type_name("B");
  cmd->add_option("--map-slope-bias", args.map_slope_bias,
                  "Slope-scaled depth bias: times the receiver's depth change per texel, as "
                  "glPolygonOffset's factor (map only; docs/shadow-maps.md)")
      ->check(finite_non_negative())
      ->default_str(fmt::format("{}", kMapDefaults.slope_bias))
      ->type_name("S");
  cmd->add_option("--map-lookup", args.map_lookup, "Depth lookup: nearest or bilinear (map only)")
      ->transform(CLI::IsMember({"nearest", "bilinear"}, CLI::ignore_case))
      ->default_str(kMapDefaults.lookup == raster::MapLookup::bilinear ? "bilinear" : "nearest")
      ->type_name("KIND");
  cmd->add_flag("--map-dither", args.map_dither, "Dither the lookup position (Williams; map only)");
  cmd->add_option("--map-pcf", args.map_pcf,
                  "Percentage-closer filter width in texels: 1 (off), 3 or 5 (map only; "
                  "shadow.<i> is shadowed where less than half the filter sees the light)")
      ->check(CLI::IsMember({1, 3, 5}))
      ->default_str(std::to_string(kMapDefaults.pcf))
      ->type_name("K");
  cmd->add_option("--map-variant", args.map_variant,
                  "depth (Williams), post (Williams' post-process: shadows darken the shaded "
                  "image), id (Ikedo's ID buffer, an ID per object), id-polygon (an ID per "
                  "polygon) or ikedo (Ikedo's penumbra for area lights: filtered ID buffers, "
                  "erosion and penumbra functions) (map only; docs/shadow-maps.md)")
      ->transform(CLI::IsMember({"depth", "post", "id", "id-polygon", "ikedo"}, CLI::ignore_case))
      ->default_str("depth")
      ->type_name("VARIANT");
  cmd->add_option("--ikedo-coeffs", args.ikedo_coeffs,
                  "Ikedo's light-erosion coefficients (k0, k1, k2): a (3/2, 1, 1), b (7/6, 3, 3), "
                  "c (21/20, 20, 20) or d (101/100, 50, 50) (--map-variant ikedo only; "
                  "docs/soft-shadows.md)")
      ->transform(CLI::IsMember({"a", "b", "c", "d"}, CLI::ignore_case))
      ->default_str("a")
      ->type_name("SET");
  cmd->add_option("--ikedo-filter", args.ikedo_filter,
                  "Ikedo's IIR filter from two corners (bi) or four (crossed) "
                  "(--map-variant ikedo only)")
      ->transform(CLI::IsMember({"bi", "crossed"}, CLI::ignore_case))
      ->default_str("crossed")
      ->type_name("KIND");
  cmd->add_option("--ray-epsilon", args.ray_epsilon,
                  "Shadow-ray start offset as a fraction of the scene's bounding-box diagonal "
                  "(ray only)")
      ->check(finite_non_negative())
      ->default_str(fmt::format("{}", raster::RayOptions{}.epsilon))
      ->type_name("E");
  cmd->add_option("--area-samples", args.area_samples,
                  "Stratified sample points per area light and visible sample, one occlusion ray "
                  "each; visibility.<i> is the fraction unoccluded (ray only)")
      ->check(CLI::Range(1, raster::kMaxAreaSamples))
      ->default_str(std::to_string(raster::RayOptions{}.area_samples))
      ->type_name("N");
  cmd->add_option("--threads", args.threads, "Worker threads (0 = the CPUs the process may use)")
      ->check(thread_count())
      ->type_name("N");
  cmd->add_option("--stats-json", args.stats_json,
                  "Write timings per phase and counts as JSON to FILE ('-' = stdout)")
      ->check(non_empty_path())
      ->type_name("FILE");
  add_memory_limit_option(cmd, args.memory_limit);
  add_verbosity_flags(cmd, args.verbose, args.quiet, "Print nothing on success");
  cmd->add_option("--spp", args.spp,
                  "Beauty samples per pixel: 1, 9 or 25 (an odd grid; shadow.<i>, count.<i> and "
                  "depth stay the pixel centre's, which validate checks)")
      ->check(CLI::IsMember({1, 9, 25}))
      ->type_name("N");
  cmd->add_option("--tile", args.tile,
                  "Render only tile I of N (0 <= I < N: bands of rows split evenly) into a "
                  "partial OpenEXR; `umbra merge` assembles the N tiles into the frame, "
                  "byte-identical to one render (docs/scale.md)")
      ->type_name("I/N");
  cmd->add_option("--exposure", args.exposure,
                  "Exposure in stops: the beauty pass is scaled by 2^EV after supersampling (AOVs "
                  "unchanged); e.g. -14 for glTF lights in photometric units (Blender's 1000 W "
                  "lamp arrives as 54,351 cd)")
      ->check(exposure_stops())
      ->type_name("EV");
  cmd->add_flag("--no-shadows", args.no_shadows,
                "Plain render without any shadow: every light reaches every sample in its "
                "range (volume method only; the baseline shadow costs are measured against)");
  cmd->footer(
      "Example:\n"
      "  umbra render data/scenes/default.json -o out/default.exr --stats-json out/stats.json\n"
      "Files are written only when everything succeeded.");
  return cmd;
}

int run_render(const RenderArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path scene_path = args.scene;
  const fs::path output =
      args.output.empty() ? fs::path(scene_path.stem().string() + ".png") : fs::path(args.output);
  const bool stats_to_stdout = args.stats_json == "-";

  if (args.no_shadows && args.method != "volume")
    throw util::InputError("--no-shadows", "applies to --method volume only");
  check_method_options(args);
  std::optional<Part> tile;
  if (!args.tile.empty()) {
    tile = parse_part("--tile", args.tile);
    if (lowercase_extension(output) != ".exr")
      throw util::InputError("--tile", "writes a partial OpenEXR; name it -o NAME.exr");
  }
  // Cheap checks first: a long render must not end in "unknown extension".
  check_output_path(output, {".png", ".exr"});
  std::vector<NamedFile> outputs = {{output, args.output.empty() ? "the default output" : "-o"}};
  if (!args.stats_json.empty() && !stats_to_stdout) {
    check_output_path(args.stats_json, {});
    outputs.push_back({args.stats_json, "--stats-json"});
  }
  check_outputs_distinct({{scene_path, "the input scene"}}, outputs);

  RenderTimings timings;
  auto phase = std::chrono::steady_clock::now();
  const geometry::Scene scene = load_verb_scene(scene_path);
  check_outputs_distinct(scene_inputs(scene), outputs);  // its meshes and buffers too
  timings.load = util::seconds_since(phase);

  raster::RenderOptions options;
  options.method = parse_method(args.method);
  options.threads = args.threads;
  options.shadows = !args.no_shadows;
  options.spp = args.spp;
  options.exposure = args.exposure;
  options.map = map_options(args);
  if (options.method == raster::Method::map)
    if (const auto why = raster::map_variant_refusal(options.map, scene))
      throw util::InputError("--map-variant", *why);
  if (args.ray_epsilon) options.ray.epsilon = *args.ray_epsilon;
  if (args.area_samples) options.ray.area_samples = *args.area_samples;
  if (tile) {
    const int bands =
        (scene.camera.height + raster::kTileRowAlignment - 1) / raster::kTileRowAlignment;
    if (tile->count > static_cast<std::uint64_t>(bands))
      throw util::InputError(
          "--tile", fmt::format("{}x{} has {} bands of {} rows; split it into at most {} tiles",
                                scene.camera.width, scene.camera.height, bands,
                                raster::kTileRowAlignment, bands));
    options.rows = raster::tile_rows(scene.camera.height, static_cast<int>(tile->index),
                                     static_cast<int>(tile->count));
  }
  const bool exr = lowercase_extension(output) == ".exr";
  check_memory(raster::estimate_render_bytes(scene, options, exr), memory_limit(args.memory_limit),
               scene_path.string(),
               fmt::format("rendering {}x{} with {} (--method {})", scene.camera.width,
                           scene.camera.height, lights_text(scene.lights.size()), args.method));
  ProgressBar bar(!args.quiet);
  options.progress = bar.callback();
  raster::RenderStats stats;
  phase = std::chrono::steady_clock::now();
  const raster::Frame frame = raster::render(scene, options, &stats);
  bar.finish();
  timings.render = util::seconds_since(phase);

  phase = std::chrono::steady_clock::now();
  if (tile)
    raster::write_frame_tile(frame, *options.rows,
                             {tile->index, tile->count, job_label(scene, args)}, output);
  else
    raster::write_frame(frame, output);
  timings.write = util::seconds_since(phase);
  timings.total = util::seconds_since(start);

  if (!args.stats_json.empty()) {
    RenderRun run;
    run.scene = scene_path.string();
    run.output = output.string();
    run.method = args.method;
    run.threads = args.threads;
    run.width = frame.width;
    run.height = frame.height;
    run.lights = scene.lights.size();
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
      if (scene.lights[l].sun) run.suns.emplace_back(l, *scene.lights[l].sun);
    run.models = scene.models.size();
    if (options.method == raster::Method::ray) run.ray_epsilon = options.ray.epsilon;
    if (options.method == raster::Method::map) run.map = options.map;
    emit_json(render_stats_json(run, stats, timings), args.stats_json);
  }

  if (args.verbose) print_render_details(scene, stats, timings);
  if (!args.quiet) {
    // With the statistics on stdout, keep stdout pure JSON.
    std::FILE* stream = stats_to_stdout ? stderr : stdout;
    if (tile)
      fmt::print(stream, "wrote {} (tile {}/{}: rows {} to {} of {}x{}, {:.2f} s)\n",
                 output.string(), tile->index, tile->count, options.rows->begin, options.rows->end,
                 frame.width, frame.height, timings.total);
    else
      fmt::print(stream, "wrote {} ({}x{}, {:.2f} s)\n", output.string(), frame.width, frame.height,
                 timings.total);
  }
  return kExitSuccess;
}

}  // namespace umbra::cli
