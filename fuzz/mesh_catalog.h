#pragma once
// The mesh files a real-model sweep walks: every OFF, OBJ, PLY and STL file
// (by extension, any case) under the given files and folders, in one sorted
// order so that shards and counts mean the same thing on every machine.
#include <filesystem>
#include <string>
#include <vector>

namespace umbra::fuzz {

struct MeshFile {
  std::filesystem::path path;
  std::string name;  ///< the file name: what seeds the mesh's scenes
};

/// Files under `roots` (a file stands for itself, a folder is walked
/// recursively), sorted by path, each once. Throws util::InputError for
/// a root that does not exist.
std::vector<MeshFile> find_mesh_files(const std::vector<std::filesystem::path>& roots);

/// Where Debian puts the shipped meshes: assimp-testmodels'
/// /usr/share/assimp/models/{OBJ,PLY,OFF,STL} and CGAL's data meshes as
/// scripts/cgal-meshes.sh --all extracts them (build/cgal-data/data/meshes),
/// each only when it exists.
std::vector<std::filesystem::path> default_mesh_roots();

}  // namespace umbra::fuzz
