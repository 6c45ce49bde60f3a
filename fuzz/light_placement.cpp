#include <fuzz/light_placement.h>

#include <fmt/format.h>

namespace umbra::fuzz {

std::string describe(const LightPlacement& p) {
  std::string where;
  if (p.model >= 0) where += fmt::format(" model {}", p.model);
  if (p.vertex >= 0) where += fmt::format(" vertex {}", p.vertex);
  if (p.polygon >= 0 && p.vertex < 0) where += fmt::format(" polygon {}", p.polygon);
  if (p.edge >= 0) where += fmt::format(" edge {}", p.edge);
  if (p.other_edge >= 0) where += fmt::format("x{}", p.other_edge);
  std::string text = p.kind + (where.empty() ? "" : " (" + where.substr(1) + ")");
  if (!p.exact) text += " rounded";
  if (p.nudged())
    text += fmt::format(" nudged {:+d},{:+d},{:+d} ulps", p.nudge[0], p.nudge[1], p.nudge[2]);
  return text;
}

}  // namespace umbra::fuzz
