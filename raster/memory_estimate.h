#pragma once
// How much memory a verb will need at its peak, estimated before it
// starts (issue 17, row 6: 2,000 lights at 1280x720 asked for 23 GB and met
// the kernel's OOM killer; 16384² frames ended in "internal error:
// std::bad_alloc"). The estimate counts what grows with the input: the
// frame and the methods' per-pixel buffers, per light; the encoded image;
// shadow-map views; shadow volumes. Its constants were measured on the
// scenes of data/scenes (docs/cli.md, "Memory"); it is meant to be within a
// factor of about 1.5, enough to refuse a render that cannot fit long
// before it starts, not to budget the last megabyte.
#include <umbra/geometry/scene.h>
#include <umbra/raster/render.h>

#include <cstdint>

namespace umbra::raster {

/// Peak bytes of raster::render(scene, options) plus writing its frame as
/// an EXR (`exr`) or a PNG.
std::uint64_t estimate_render_bytes(const geometry::Scene& scene, const RenderOptions& options,
                                    bool exr);

/// Peak bytes of validating a render of `scene` (its shadow channels read
/// back, the report's mask and the mask PNG).
std::uint64_t estimate_validate_bytes(const geometry::Scene& scene);

/// Peak bytes of building every light's shadow volumes and exporting them.
std::uint64_t estimate_volume_bytes(const geometry::Scene& scene);

}  // namespace umbra::raster
