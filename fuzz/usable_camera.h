#pragma once
// The generators' cameras must be ones the scene loader accepts: a scene
// whose frame underflows in doubles gives NaN rays in memory and is refused
// when read back from its exported file, so a "finding" on it is neither
// real nor replayable.
#include <umbra/geometry/scene.h>

namespace umbra::fuzz {

/// Sets camera.up to the first of (0,1,0), (1,0,0), (0,0,1) whose camera
/// frame is finite and not degenerate (the loader's test, geometry/io/scene_json.cpp)
/// and returns true; false when none is, e.g. an eye within a few subnormals
/// of look_at (a light nudged off the origin, the eye put behind it): the
/// caller must move the eye.
bool choose_usable_up(geometry::Camera& camera);

}  // namespace umbra::fuzz
