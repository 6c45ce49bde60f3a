#pragma once
// Sample rays exactly as DESIGN.md defines them; shared by every render
// method and by the validator, so that all of them look at the same points.
#include <umbra/geometry/scene.h>

#include <span>

namespace umbra::geometry {

/// The ray eye + t·direction through the centre of pixel (i, j), i from the
/// left, j from the top. `direction` is not unit length. Both are computed in
/// IEEE doubles in DESIGN.md's order and are then taken as exact values.
struct SampleRay {
  Vec3 origin;
  Vec3 direction;
};

/// The camera frame of DESIGN.md: forward f, right r, up u, and the scale
/// factors h = tan(fov/2) and a = width / height.
struct CameraFrame {
  Vec3 eye, f, r, u;
  double h = 0, a = 0;
  int width = 0, height = 0;
};

CameraFrame camera_frame(const Camera& camera);
SampleRay sample_ray(const CameraFrame& frame, int i, int j);

/// The directions of row j's sample rays: out[i] is sample_ray(frame, i,
/// j).direction bit for bit, for i < out.size() (at most the width). The
/// row's own terms are computed once, where a renderer asking pixel by
/// pixel computes them every time (the scanline makes every pixel's ray).
void sample_row_directions(const CameraFrame& frame, int j, std::span<Vec3> out);

}  // namespace umbra::geometry
