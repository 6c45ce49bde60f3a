#include <cli/exit_codes.h>
#include <cli/memory_limit.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <cli/scene_loading.h>
#include <cli/stats_json.h>
#include <cli/volume_command.h>
#include <umbra/geometry/export/volume_export.h>
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/geometry/volumes/builder.h>
#include <umbra/raster/memory_estimate.h>
#include <umbra/util/input_error.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

namespace umbra::cli {

namespace fs = std::filesystem;

namespace {

/// "light 0: 120, light 1: 96"
std::string faces_per_light(const VolumeCounts& counts) {
  std::string text;
  for (std::size_t i = 0; i < counts.lights.size(); ++i)
    text += fmt::format("{}light {}: {}", i == 0 ? "" : ", ", i, counts.lights[i].total);
  return text.empty() ? "no lights" : text;
}

}  // namespace

CLI::App* add_volume_command(CLI::App& app, VolumeArgs& args) {
  CLI::App* cmd = app.add_subcommand("volume", "Export every light's shadow volume");
  cmd->add_option("SCENE", args.scene, "Scene file (.json, .gltf or .glb)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args.output,
                  "Output mesh: .ply (attributes as face properties), .obj/.off (attributes "
                  "in the sidecar OUT.json; .obj grouped by light and type with materials in "
                  "<stem>.mtl) or .gltf/.glb (float32 positions; a node and material per light "
                  "and type; attributes as per-vertex _FACE, _LIGHT, ...); default "
                  "<scene stem>.ply in the current directory")
      ->check(non_empty_path())
      ->type_name("OUT");
  cmd->add_option("--ply-format", args.ply_format,
                  "binary (default) or ascii: how a .ply output stores its elements; both "
                  "exact (ascii: shortest round-trip decimals), ascii for readers such as "
                  "meshio that cannot read the binary one")
      ->transform(CLI::IsMember({"binary", "ascii"}, CLI::ignore_case))
      ->type_name("FORMAT");
  cmd->add_option("--stats-json", args.stats_json,
                  "Write counts per light and timings as JSON to FILE ('-' = stdout)")
      ->check(non_empty_path())
      ->type_name("FILE");
  cmd->add_option(
         "--threads", args.threads,
         "Worker threads, one light at a time each (0 = the CPUs the process may use); the "
         "output does not depend on it")
      ->check(thread_count())
      ->type_name("N");
  add_memory_limit_option(cmd, args.memory_limit);
  add_verbosity_flags(cmd, args.verbose, args.quiet, "Print nothing on success");
  cmd->footer(
      "Example:\n"
      "  umbra volume data/scenes/default.json -o out/default.volume.ply\n"
      "Per face: light, model, polygon, edge, type (1/2/3), nb_c, twisted "
      "(docs/volume-export.md).\n"
      "Files are written only when everything succeeded.");
  return cmd;
}

int run_volume(const VolumeArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path scene_path = args.scene;
  const fs::path output = args.output.empty()
                              ? fs::path(fs::path(args.scene).stem().string() + ".ply")
                              : fs::path(args.output);
  const bool stats_to_stdout = args.stats_json == "-";

  // Cheap checks first: nothing is built for an output that cannot be written.
  check_output_path(output, {".ply", ".obj", ".off", ".gltf", ".glb"});
  geometry::VolumeFileOptions options;
  if (!args.ply_format.empty()) {
    if (geometry::detail::to_lower(output.extension().string()) != ".ply")
      throw util::InputError("--ply-format", "applies to a .ply output only");
    if (args.ply_format == "ascii") options.ply = geometry::PlyEncoding::ascii;
  }
  std::vector<NamedFile> outputs = {{output, args.output.empty() ? "the default output" : "-o"}};
  const auto sidecar = geometry::volume_sidecar_path(output);
  if (sidecar) {
    check_output_path(*sidecar, {});
    outputs.push_back({*sidecar, "the sidecar of -o"});
  }
  const auto materials = geometry::volume_material_path(output);
  if (materials) {
    check_output_path(*materials, {});
    outputs.push_back({*materials, "the materials of -o"});
  }
  if (!args.stats_json.empty() && !stats_to_stdout) {
    check_output_path(args.stats_json, {});
    outputs.push_back({args.stats_json, "--stats-json"});
  }
  check_outputs_distinct({{scene_path, "the input scene"}}, outputs);

  VolumeTimings timings;
  auto phase = std::chrono::steady_clock::now();
  // Volumes need no eye: a scene without a camera loads.
  const geometry::Scene scene = load_verb_scene(scene_path, {.require_camera = false});
  check_outputs_distinct(scene_inputs(scene), outputs);  // its meshes and buffers too
  check_memory(raster::estimate_volume_bytes(scene), memory_limit(args.memory_limit),
               scene_path.string(), "building the volumes of " + lights_text(scene.lights.size()));
  timings.load = util::seconds_since(phase);

  phase = std::chrono::steady_clock::now();
  const geometry::ShadowVolumes volumes =
      geometry::build_shadow_volumes(scene, {.caps = true, .threads = args.threads});
  timings.volumes = util::seconds_since(phase);

  phase = std::chrono::steady_clock::now();
  geometry::write_volumes(volumes, output, options);
  timings.write = util::seconds_since(phase);
  timings.total = util::seconds_since(start);

  const VolumeCounts counts = count_volume_faces(volumes, scene.lights.size());
  if (!args.stats_json.empty()) {
    VolumeRun run;
    run.scene = scene_path.string();
    run.output = output.string();
    run.sidecar = sidecar ? sidecar->string() : std::string();
    run.lights = scene.lights.size();
    run.models = scene.models.size();
    emit_json(volume_stats_json(run, volumes, counts, timings), args.stats_json);
  }

  if (args.verbose) {
    for (std::size_t i = 0; i < counts.lights.size(); ++i) {
      const FaceCounts& c = counts.lights[i];
      fmt::print(
          stderr, "light {}: {}: {} faces (type 1: {}, type 2: {}, type 3: {}; {} twisted)\n", i,
          describe_light(scene.lights[i]), c.total, c.type[0], c.type[1], c.type[2], c.twisted);
    }
    fmt::print(stderr, "seconds: load {:.3f}, volumes {:.3f}, write {:.3f}, total {:.3f}\n",
               timings.load, timings.volumes, timings.write, timings.total);
  }
  if (!args.quiet) {
    // With the statistics on stdout, keep stdout pure JSON.
    std::FILE* stream = stats_to_stdout ? stderr : stdout;
    fmt::print(stream,
               "wrote {}{}{}: {} faces (type 1: {}, type 2: {}, type 3: {}; {}), {:.2f} s\n",
               output.string(), sidecar ? " + " + sidecar->filename().string() : std::string(),
               materials ? " + " + materials->filename().string() : std::string(), counts.all.total,
               counts.all.type[0], counts.all.type[1], counts.all.type[2], faces_per_light(counts),
               timings.total);
  }
  return kExitSuccess;
}

}  // namespace umbra::cli
