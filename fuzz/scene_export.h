#pragma once
// Writes a generated scene as files other renderers can read (scene JSON plus
// one OFF mesh per model, coordinates in shortest round-trip decimal, so the
// scene reads back bit for bit) together with its exact truth: per light the
// oracle's class of every pixel and a mask of the boundary samples.
#include <fuzz/degenerate_scenes.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace umbra::fuzz {

/// Per pixel (row-major from the top-left) and light, the oracle's answer.
struct TruthMasks {
  static constexpr std::uint8_t kLit = 0, kShadowed = 1, kOutOfRange = 2, kBackground = 255;
  int width = 0, height = 0;
  std::vector<std::vector<std::uint8_t>> cls;       ///< per light
  std::vector<std::vector<std::uint8_t>> boundary;  ///< per light: 1 on a boundary sample
};

TruthMasks oracle_truth(const geometry::Scene& scene);

/// The scene as scene-format JSON with inline polygons (coordinates in
/// shortest round-trip form): what a harness prints when a check fails, so
/// the failing case can be loaded with `umbra render`/`validate`/`volume`.
std::string scene_to_json(const geometry::Scene& scene);

/// Writes DIR/<name>/: scene.json, meshes/<k>_<model>.off, truth.<i>.png
/// (white lit, black shadowed, grey out of range, blue background),
/// boundary.<i>.png (white on boundary samples) and truth.json (features and
/// counts). Reads scene.json back and throws std::runtime_error unless every
/// coordinate is bit-identical. Throws util::InputError if files cannot
/// be written.
void export_scene(const GeneratedScene& generated, const TruthMasks& truth,
                  const std::filesystem::path& dir);

}  // namespace umbra::fuzz
