#pragma once
// Seeded scenes on a real mesh for `umbra fuzz real`: the mesh (already in
// its unit box, fuzz/unit_box.h) on a floor, 1-3 lights of which most sit
// where exact decisions degenerate, and an eye far away, near the floor, or
// inside a volume. Scene `index` of seed `seed` on a mesh depends only on the
// mesh's vertices and its file name, never on which other meshes a run
// includes, so a failure's recipe names one file.
#include <fuzz/degenerate_scenes.h>
#include <umbra/geometry/scene.h>

#include <cstdint>
#include <string>

namespace umbra::fuzz {

/// The light placements, by feature name (docs/fuzzing.md): "light_above",
/// "light_on_vertex", "light_inside_edge", "light_edge_midpoint_sum",
/// "light_edge_midpoint_lerp", "light_sees_edges_cross", "light_on_edge_line",
/// "light_in_face_plane", "light_inside_face", "light_in_floor_plane", "light_at_box_centre",
/// "light_grazing_floor", "directional", "directional_along_edge",
/// "directional_in_face_plane", "directional_grazing"; a point light gets
/// "+light_end" when its reach ends at a vertex's distance (cutting the
/// model). Eyes: "eye_far", "eye_near_floor", "eye_in_shadow",
/// "eye_at_box_centre". Also "floor_touching" / "floor_below", "ulp_nudge",
/// "placement_rounded".
///
/// `mesh` is model 0 (its name, vertices and polygons are kept); the floor
/// is model 1. Name: "<mesh_name>-s<seed>-<index>".
GeneratedScene real_mesh_scene(const geometry::Model& mesh, const std::string& mesh_name,
                               std::uint64_t seed, std::uint64_t index, int width, int height);

}  // namespace umbra::fuzz
