#pragma once
// Benchmark scenes: a mesh set on a floor under N point lights, at a fixed
// camera, built in code so that only the mesh file has to exist.
#include <umbra/geometry/scene.h>

#include <filesystem>

namespace umbra::bench {

/// The mesh scaled to unit height, standing on a floor of 6 x 6 units, lit by
/// `lights` point lights on a ring above it (total intensity 1), seen by a
/// width x height camera from the front and above.
geometry::Scene mesh_on_floor(const std::filesystem::path& mesh, int lights, int width, int height);

/// Goal 1's last case (issue 20): mesh_on_floor with 4 lights, the floor
/// 60 x 60 units (to the horizon in the picture) and the fourth light a
/// low directional one, (-1, -0.22, -0.35), whose shadow volume's sides
/// run long across the floor.
geometry::Scene mesh_on_large_floor(const std::filesystem::path& mesh, int width, int height);

}  // namespace umbra::bench
