#pragma once
// A bounding-volume hierarchy over axis-aligned boxes that only picks
// candidates: its float tests are conservative (boxes are widened by more
// than the rounding error of the tests), and exact predicates decide.
#include <umbra/geometry/box.h>

#include <cstdint>
#include <vector>

namespace umbra::geometry {

class Bvh {
 public:
  Bvh() = default;
  /// `boxes[i]` bounds item i.
  explicit Bvh(std::vector<Box> boxes);

  /// Items whose box may meet the segment from `from` to `to` (or the ray
  /// from `from` along `to` when `to_is_direction`), widened by `slack` in
  /// every direction. Appends to `out`.
  void query_segment(const Vec3& from, const Vec3& to, bool to_is_direction, double slack,
                     std::vector<std::uint32_t>& out) const;

  /// Items whose box may meet `box`, widened by `slack` (and by 1e-9 of the
  /// coordinates' size). Appends to `out`.
  void query_box(const Box& box, double slack, std::vector<std::uint32_t>& out) const;

  /// Items whose box, and every enclosing node's, `keep` accepts: `keep`
  /// must accept every box that meets what is sought (false only for a box
  /// certainly apart from it). Appends to `out`.
  template <class Keep>
  void query_if(const Keep& keep, std::vector<std::uint32_t>& out) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!keep(node.box)) continue;
      if (node.count > 0) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
          if (keep(boxes_[i])) out.push_back(order_[i]);
      } else {
        const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
        stack[top++] = self + 1;
        stack[top++] = node.first;
      }
    }
  }

  std::size_t size() const { return boxes_.size(); }

  /// The same queries over `boxes` without a tree, item by item in index
  /// order: the candidates are those the tree finds (up to the rounding of
  /// the tests, which the widening covers either way). The scene index scans
  /// by groups (below); these are the reference its tests compare with.
  static void scan_segment(const std::vector<Box>& boxes, const Vec3& from, const Vec3& to,
                           bool to_is_direction, double slack, std::vector<std::uint32_t>& out);
  static void scan_box(const std::vector<Box>& boxes, const Box& box, double slack,
                       std::vector<std::uint32_t>& out);

  /// Boxes kScanGroup at a time in index order, each group's box bounding
  /// its members'. The scans below test a group's box first and its members
  /// only where that passes, with a group test that passes wherever a
  /// member's would: the same items in the same order as the plain scans,
  /// and on a mesh, whose consecutive triangles lie side by side, a segment
  /// through a corner of the scene tests few members (a scan was ~7.6 M
  /// instructions on bunny00's 70k triangles, and a frame asks up to 32).
  static constexpr std::uint32_t kScanGroup = 16;
  static std::vector<Box> group_boxes(const std::vector<Box>& boxes);
  static void scan_segment(const std::vector<Box>& boxes, const std::vector<Box>& groups,
                           const Vec3& from, const Vec3& to, bool to_is_direction, double slack,
                           std::vector<std::uint32_t>& out);
  static void scan_box(const std::vector<Box>& boxes, const std::vector<Box>& groups,
                       const Box& box, double slack, std::vector<std::uint32_t>& out);

 private:
  struct Node {
    Box box;
    std::uint32_t first = 0;  ///< leaf: first index into order_; inner: left child
    std::uint32_t count = 0;  ///< leaf: number of items; inner: 0
  };
  /// `centres[i]` is boxes_[i].centre(), computed once for the whole build.
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, const std::vector<Vec3>& centres);

  std::vector<Box> boxes_;  ///< after the build, item order_[i]'s box is boxes_[i]
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace umbra::geometry
