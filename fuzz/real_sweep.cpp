#include <fuzz/mesh_catalog.h>
#include <fuzz/real_scenes.h>
#include <fuzz/real_sweep.h>
#include <fuzz/scene_export.h>
#include <fuzz/unit_box.h>
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/util/input_error.h>
#include <umbra/util/phase_clock.h>

#include <fmt/format.h>

#include <chrono>
#include <fstream>

namespace umbra::fuzz {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) {
  const std::string s = path.string();
  return s.find_first_of(" '\"") == std::string::npos ? s : "'" + s + "'";
}

/// The mesh in its unit box, or the loader's reason for refusing it.
std::optional<geometry::Model> load_mesh(const MeshFile& file, std::string& reason) {
  geometry::PolygonSoup soup;
  try {
    soup = geometry::read_polygon_soup(file.path);
  } catch (const util::InputError& e) {
    reason = e.what();
    return std::nullopt;
  } catch (const std::exception& e) {
    reason = std::string("not an InputError (a loader bug): ") + e.what();
    return std::nullopt;
  }
  geometry::Model model;
  model.name = file.path.stem().string();
  model.vertices = std::move(soup.vertices);
  model.polygons = std::move(soup.polygons);
  apply_unit_box(unit_box(model.vertices), model.vertices);
  return model;
}

std::uint64_t scenes_for(const RealSweepOptions& o, std::uint64_t file, std::uint64_t files) {
  if (o.index) return 1;
  if (!o.count) return o.per_mesh;
  return *o.count / files + (file < *o.count % files ? 1 : 0);
}

void tally(const RealSceneResult& r, RealSweepSummary& s) {
  const SceneCheck& c = r.check;
  ++s.scenes;
  s.counts += c.counts;
  s.refused += c.refused;
  for (std::size_t l = 0; l < r.placements.size(); ++l) {
    const std::uint64_t wrong = l < c.light_mismatches.size() ? c.light_mismatches[l] : 0;
    // A refusal that names no light is held against every light.
    const bool refused =
        c.refused && (c.refused_light < 0 || c.refused_light == static_cast<int>(l));
    for (const std::string& key : {r.placements[l].kind, std::string("ulp_nudge")}) {
      if (key == "ulp_nudge" && !r.placements[l].nudged()) continue;
      KindTally& k = s.kinds[key];
      ++k.lights;
      k.failing += (wrong > 0 || refused) ? 1 : 0;
      k.mismatches += wrong;
      k.refusals += refused ? 1 : 0;
    }
  }
  if (!c.ok()) {
    ++s.failed;
    for (const auto& f : r.features) ++s.failing_features[f];
    s.failures.push_back(r);
  }
}

/// DIR/<name>/: the scene files of scene_export.h and recipe.txt, the
/// commands that found it and that replay it.
fs::path export_failure(const GeneratedScene& g, const RealSceneResult& r, const fs::path& dir) {
  export_scene(g, oracle_truth(g.scene), dir);
  const fs::path root = dir / g.name;
  std::ofstream recipe(root / "recipe.txt");
  recipe << "# found by\n"
         << r.recipe << "\n# "
         << (r.check.refused ? "refused: " + r.check.refusal
                             : fmt::format("{} mismatches ({} false lit, {} false shadowed)",
                                           r.check.counts.mismatches, r.check.counts.false_lit,
                                           r.check.counts.false_shadowed))
         << "\n# replay (from this folder)\numbra render scene.json -o render.exr\n"
         << "umbra validate scene.json --image render.exr\n";
  for (std::size_t l = 0; l < r.placements.size(); ++l)
    recipe << "# light " << l << ": " << describe(r.placements[l]) << "\n";
  recipe.close();
  if (!recipe) throw util::InputError((root / "recipe.txt").string(), "cannot write");
  return root;
}

/// Scenes of one loaded mesh, file k of the `files` of the whole walk.
void sweep_mesh(const RealSweepOptions& o, const geometry::Model& mesh, const MeshFile& file,
                std::uint64_t k, std::uint64_t files, RealSweepSummary& s) {
  const std::uint64_t n = scenes_for(o, k, files);
  const std::uint64_t first = o.index.value_or(0);
  s.mesh_scenes.push_back({k, file.path.string(), file.name, first, n});
  for (std::uint64_t i = first; i - first < n; ++i) {
    const GeneratedScene g = real_mesh_scene(mesh, file.name, o.seed, i, o.width, o.height);
    RealSceneResult r;
    r.name = g.name;
    r.mesh_path = file.path;
    r.file = k;
    r.index = i;
    r.features = g.features;
    r.placements = g.placements;
    r.recipe =
        fmt::format("umbra fuzz real --meshes {} --seed {} --index {} --width {} --height {}",
                    quoted(file.path), o.seed, i, o.width, o.height);
    SceneCheckOptions check;
    check.threads = o.threads;
    check.closure = o.closure;
    check.render = o.render;
    r.check = check_scene(g.scene, check);
    if (!r.check.ok() && o.export_dir && s.exported < o.export_limit) {
      // A scene that cannot be written is still a finding: say so, go on.
      try {
        r.exported = export_failure(g, r, *o.export_dir);
        ++s.exported;
      } catch (const std::exception& e) {
        r.export_error = e.what();
      }
    }
    tally(r, s);
    if (o.on_scene) o.on_scene(r);
  }
}

}  // namespace

RealSweepSummary run_real_sweep(const RealSweepOptions& o) {
  const auto start = util::Clock::now();
  RealSweepSummary s;
  const std::vector<MeshFile> all = find_mesh_files(o.roots);
  for (std::size_t k = o.shard; k < all.size(); k += o.shards) {
    const MeshFile& file = all[k];
    ++s.files;
    const auto load_start = util::Clock::now();
    std::string reason;
    const std::optional<geometry::Model> mesh = load_mesh(file, reason);
    s.seconds_load += util::seconds_since(load_start);
    if (!mesh) {
      s.refused_meshes.push_back({k, file.path.string(), reason});
    } else {
      ++s.meshes;
      sweep_mesh(o, *mesh, file, k, all.size(), s);
    }
    if (o.shards > all.size() - k) break;  // k + shards would wrap around
  }
  s.seconds = util::seconds_since(start);
  return s;
}

}  // namespace umbra::fuzz
