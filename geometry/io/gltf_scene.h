#pragma once
// glTF 2.0 (.gltf, .glb) as umbra's second scene input, read with tinygltf.
// docs/scene-format.md ("glTF scenes") is the user's reference: which parts
// of a glTF file are read, how node transforms are composed, how lights,
// camera and materials map onto umbra's Scene.
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/geometry/scene.h>

#include <filesystem>
#include <string_view>

namespace umbra::geometry {

/// True for the extensions `.gltf` and `.glb`, case-insensitively.
bool is_gltf_path(const std::filesystem::path& file);

/// A whole scene from a glTF file's bytes: one model per triangle primitive of every
/// mesh instance in the default scene (node transforms composed in doubles),
/// the KHR_lights_punctual lights in the order of their `lights` array, the
/// first perspective camera (none: refused unless `options.require_camera`
/// is false, then Scene::has_camera is false). External buffers are resolved relative to the
/// file's folder. Throws InputError naming the file and the glTF JSON path
/// ("meshes[0].primitives[1].indices") or accessor for every malformed input.
///
/// `file` names the file in messages and anchors external buffer URIs; a
/// `.glb` container is recognised by its magic. load_scene (geometry/io/scene_json.h)
/// reads the file and calls this for `.gltf` and `.glb`.
Scene parse_gltf_scene(std::string_view bytes, const std::filesystem::path& file,
                       const SceneLoadOptions& options = {});

/// The triangles of a glTF file as one polygon soup (a JSON scene's
/// `"mesh": "x.glb"`): every triangle primitive of every mesh instance in the
/// default scene, in world coordinates of the glTF file, bit-identical
/// positions welded. Cameras, lights and materials are not read.
PolygonSoup parse_gltf_polygon_soup(std::string_view bytes, const std::filesystem::path& file);

}  // namespace umbra::geometry
