#pragma once
// The stability sweeps of the speed/accuracy chart: scene families in which
// one parameter walks toward the place where some method breaks.
#include <umbra/geometry/scene.h>

#include <string>
#include <vector>

namespace umbra::bench {

struct SweepPoint {
  double value = 0;
  geometry::Scene scene;
};

struct Sweep {
  std::string name;       ///< e.g. "grazing"
  std::string parameter;  ///< axis label, e.g. "light elevation above the floor (degrees)"
  bool log_axis = false;  ///< values span decades (0 drawn on a linear stretch)
  std::vector<SweepPoint> points;
};

/// All sweeps at width x height; `quick` keeps three points of each.
std::vector<Sweep> stability_sweeps(int width, int height, bool quick);

}  // namespace umbra::bench
