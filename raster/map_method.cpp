// Method::map: placeholder until the method lands (issue 5); refuses to run.
#include <raster/render_methods.h>

#include <stdexcept>

namespace umbra::raster {

Frame render_map(const geometry::SceneIndex&, const RenderOptions&, RenderStats&) {
  throw std::logic_error("render: method 'map' is not built yet");
}

}  // namespace umbra::raster
