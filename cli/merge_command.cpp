#include <cli/csv_parts.h>
#include <cli/exit_codes.h>
#include <cli/geojson_parts.h>
#include <cli/memory_limit.h>
#include <cli/merge_command.h>
#include <cli/output_files.h>
#include <cli/parse_checks.h>
#include <umbra/raster/image_io.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>

#include <filesystem>
#include <limits>

namespace umbra::cli {

namespace fs = std::filesystem;

CLI::App* add_merge_command(CLI::App& app, MergeArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Assemble the tiles of `umbra render --tile I/N` into the whole frame");
  cmd->add_option("PART", args.parts,
                  "Every tile of one render (.exr), in any order; or every part of a sharded "
                  "sun series' --schedule or --csv table (.csv) or -o GeoJSON (.geojson), in "
                  "shard order")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args.output,
                  "Output: .exr (beauty and every AOV) or .png (beauty) for tiles; .csv for "
                  "table parts; .geojson for GeoJSON parts")
      ->required()
      ->check(non_empty_path())
      ->type_name("OUT");
  add_memory_limit_option(cmd, args.memory_limit);
  cmd->add_flag("-q,--quiet", args.quiet, "Print nothing on success");
  cmd->footer(
      "Example:\n"
      "  umbra render scene.json --tile 0/2 -o t0.exr && umbra render scene.json --tile 1/2 -o "
      "t1.exr\n"
      "  umbra merge t0.exr t1.exr -o frame.exr\n"
      "The result is byte-identical to `umbra render scene.json -o frame.exr`.\n"
      "  umbra merge s0.csv s1.csv -o schedule.csv   (parts of footprint --sun-times --shard)\n"
      "  umbra merge s0.geojson s1.geojson -o steps.geojson   (the same, -o PART.geojson)");
  return cmd;
}

int run_merge(const MergeArgs& args) {
  const auto start = util::Clock::now();
  const fs::path output = args.output;
  check_output_path(output, {".png", ".exr", ".csv", ".geojson"});
  std::vector<NamedFile> inputs;
  std::vector<fs::path> parts;
  for (const std::string& part : args.parts) {
    inputs.push_back({part, "a tile to merge"});
    parts.emplace_back(part);
  }
  check_outputs_distinct(inputs, {{output, "-o"}});
  const std::string extension = lowercase_extension(output);
  if (extension == ".csv" || extension == ".geojson") {
    write_text_file(output,
                    extension == ".csv" ? join_csv_parts(parts) : join_geojson_parts(parts));
    if (!args.quiet)
      fmt::print("wrote {} (from {} parts, {:.2f} s)\n", output.string(), parts.size(),
                 util::seconds_since(start));
    return kExitSuccess;
  }
  const std::optional<MemoryLimit> limit = memory_limit(args.memory_limit);
  const raster::MergedFrame frame = raster::merge_frame_tiles(
      parts, output, limit ? limit->bytes : std::numeric_limits<std::uint64_t>::max());
  if (!args.quiet)
    fmt::print("wrote {} ({}x{} from {} tiles, {:.2f} s)\n", output.string(), frame.width,
               frame.height, frame.tiles, util::seconds_since(start));
  return kExitSuccess;
}

}  // namespace umbra::cli
