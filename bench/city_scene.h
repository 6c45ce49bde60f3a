#pragma once
// A night city in the spirit of Bergeron's downtown Montreal: a grid of
// blocks of box buildings on streets, lit by many street lights of small
// reach. Each building is its own model, so a light's sphere of influence
// decides which buildings cast volumes for it at all.
#include <umbra/geometry/scene.h>

#include <cstdint>

namespace umbra::bench {

struct CityOptions {
  int blocks = 7;  ///< blocks per side; (blocks + 1)^2 street lights at the crossings
  int width = 640, height = 360;
  std::uint32_t seed = 1986;  ///< building heights
};

geometry::Scene night_city(const CityOptions& options = {});

/// Keeps `lamps` of the city's (blocks + 1)^2 street lights, spread over
/// it: for a square number m² of them the m × m crossings at
/// ⌊(a + ½)·(blocks + 1)/m⌋ along each street (one lamp: the middle
/// crossing), else lamp ⌊(k + ½)·N/K⌋ of the N in grid order. All of them
/// when `lamps` is not below N.
void keep_lamps(geometry::Scene& city, int blocks, int lamps);

}  // namespace umbra::bench
