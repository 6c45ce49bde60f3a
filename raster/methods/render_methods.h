#pragma once
// The render methods behind raster::render (render.h), one file each.
#include <umbra/geometry/oracle/scene_index.h>
#include <umbra/geometry/volumes/model_tables.h>
#include <umbra/raster/frame.h>
#include <umbra/raster/render.h>
#include <umbra/util/parallel_for.h>

#include <cstddef>
#include <span>

namespace umbra::raster {

/// The rows `options` asks for (a tile), or every row of the image.
inline RowRange rows_to_render(const RenderOptions& options, int height) {
  return options.rows ? *options.rows : RowRange{0, height};
}

/// Calls row(j) for every row j of `rows`, one row at a time from up to
/// `threads` threads (util::parallel_for).
template <class Row>
void for_each_row(RowRange rows, unsigned threads, Row&& row) {
  util::parallel_for(static_cast<std::size_t>(rows.size()), threads,
                     [&](std::size_t k) { row(rows.begin + static_cast<int>(k)); });
}

/// The oracle's own answer at every pixel: exact first hit, exact class.
/// count.<i> is 1 where shadowed, 0 elsewhere.
Frame render_exact(const geometry::SceneIndex& index, const RenderOptions& options,
                   RenderStats& stats);

/// Shadow volumes from contour edges through the scanline depth count, with
/// every pixel the scanline cannot decide in floating point decided again
/// exactly (visible_surface.h, geometry/volumes/crossings.h, and the oracle where even
/// the exact volume count meets a degenerate configuration). `tables` are
/// the scene's models' (geometry::model_tables), which render() has made
/// for its statistics.
Frame render_volume(const geometry::SceneIndex& index,
                    std::span<const geometry::ModelTables> tables, const RenderOptions& options,
                    RenderStats& stats);

/// Williams' shadow maps: the visible surface as Method::volume finds it
/// (scanline, exact where float cannot decide), then each visible sample
/// compared with each light's depth views in floating point.
Frame render_map(const geometry::SceneIndex& index, const RenderOptions& options,
                 RenderStats& stats);

/// Ray-cast shadows with Embree: a primary ray per pixel and one occlusion
/// ray per visible sample and light (RayOptions::area_samples stratified
/// ones for an area light: V = unoccluded / N), all in single precision.
Frame render_ray(const geometry::SceneIndex& index, const RenderOptions& options,
                 RenderStats& stats);

}  // namespace umbra::raster
