#include <fuzz/mesh_catalog.h>
#include <umbra/util/input_error.h>

#include <algorithm>
#include <cctype>

namespace umbra::fuzz {

namespace fs = std::filesystem;

namespace {
bool is_mesh(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}
}  // namespace

std::vector<MeshFile> find_mesh_files(const std::vector<fs::path>& roots) {
  std::vector<fs::path> paths;
  for (const fs::path& root : roots) {
    if (fs::is_regular_file(root)) {
      paths.push_back(root);
    } else if (fs::is_directory(root)) {
      for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file() && is_mesh(entry.path())) paths.push_back(entry.path());
    } else {
      throw util::InputError(root.string(), "no such file or folder (--meshes)");
    }
  }
  std::sort(paths.begin(), paths.end());
  paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
  std::vector<MeshFile> files;
  for (const fs::path& p : paths) files.push_back({p, p.filename().string()});
  return files;
}

std::vector<fs::path> default_mesh_roots() {
  std::vector<fs::path> roots;
  for (const char* sub : {"OBJ", "PLY", "OFF", "STL"}) {
    const fs::path dir = fs::path("/usr/share/assimp/models") / sub;
    if (fs::is_directory(dir)) roots.push_back(dir);
  }
  const fs::path cgal = "build/cgal-data/data/meshes";
  if (fs::is_directory(cgal)) roots.push_back(cgal);
  return roots;
}

}  // namespace umbra::fuzz
