#pragma once
// Test scenes built by hand: a model that is one polygon.
#include <umbra/geometry/scene.h>

#include <string>
#include <utility>
#include <vector>

namespace umbra::test {

/// A model named `name` whose only polygon runs through `v` in order.
inline geometry::Model polygon_model(std::string name, std::vector<geometry::Vec3> v) {
  geometry::Model m;
  m.name = std::move(name);
  m.vertices = std::move(v);
  geometry::Polygon p;
  for (std::uint32_t i = 0; i < m.vertices.size(); ++i) p.push_back(i);
  m.polygons = {p};
  return m;
}

}  // namespace umbra::test
