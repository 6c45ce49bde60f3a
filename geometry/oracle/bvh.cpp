#include <umbra/geometry/oracle/bvh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace umbra::geometry {

Bvh::Bvh(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
  order_.resize(boxes_.size());
  for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  if (!boxes_.empty()) {
    // The centres once, not in every comparison of every level's split
    // (the same values: the same expression).
    std::vector<Vec3> centres;
    centres.reserve(boxes_.size());
    for (const Box& b : boxes_) centres.push_back(b.centre());
    nodes_.reserve(2 * boxes_.size());
    build(0, static_cast<std::uint32_t>(boxes_.size()), centres);
    // Leaves' boxes in leaf order: a query reads each leaf's items side by
    // side, not scattered over the input's order.
    std::vector<Box> ordered;
    ordered.reserve(boxes_.size());
    for (const std::uint32_t i : order_) ordered.push_back(boxes_[i]);
    boxes_ = std::move(ordered);
  }
}

std::uint32_t Bvh::build(std::uint32_t begin, std::uint32_t end,
                         const std::vector<Vec3>& centres_of) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Box box, centres;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.extend(boxes_[order_[i]]);
    centres.extend(centres_of[order_[i]]);
  }
  nodes_[index].box = box;
  constexpr std::uint32_t kLeafSize = 4;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Items as large as half the node (a floor under a model, the ground
  // under a city) go to a child of their own beside the rest. Split by
  // their centres they would sit deep in the tree with every node above
  // them as large as they are, and every query would walk down to them:
  // on refined_elephant's floor, ~40 box tests a lit sample's pyramid.
  const Vec3 size = box.hi - box.lo;
  const double node_size = std::max({size.x, size.y, size.z});
  std::uint32_t large_end = begin;
  for (std::uint32_t i = begin; i < end; ++i) {
    const Vec3 s = boxes_[order_[i]].hi - boxes_[order_[i]].lo;
    if (2 * std::max({s.x, s.y, s.z}) >= node_size) std::swap(order_[i], order_[large_end++]);
  }
  if (large_end > begin && large_end < end) {
    build(begin, large_end, centres_of);  // the left child is always index + 1
    const std::uint32_t right = build(large_end, end, centres_of);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
  }
  const Vec3 extent = centres.hi - centres.lo;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(
      order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
      [&](std::uint32_t a, std::uint32_t b) { return centres_of[a][axis] < centres_of[b][axis]; });
  build(begin, mid, centres_of);  // the left child is always index + 1
  const std::uint32_t right = build(mid, end, centres_of);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

namespace {

/// Slab test of the segment from + s·(to - from), s in [0, 1] (or s >= 0 for a
/// ray) against the box widened by `slack`. The widening must exceed the
/// rounding error of this test, which is relative to the magnitudes involved:
/// the caller's slack plus 1e-9 of the coordinates' size covers it with room.
///
/// With `group`, the test of a box that holds others (Bvh::group_boxes)
/// passes whenever the plain test passes for any box it holds: its pad is
/// at least theirs (a larger scale), its slab interval [ta, tb] holds
/// theirs (every step rounds monotonically), and the parameter interval
/// is widened by 2e-9·max(|ta|, |tb|), at least any held box's 1e-9·(|ta'|
/// + |tb'|) since both lie within its own interval. (The plain widening is
/// not monotone: [-1, 6] is widened less than [5, 6].) So s0 and s1 stay
/// at or below, and at or above, any held box's on every axis.
template <bool group>
bool meets(const Box& box, const Vec3& from, const Vec3& dir, double s_max, double slack) {
  double s0 = 0, s1 = s_max;
  for (int a = 0; a < 3; ++a) {
    const double scale = std::max({std::abs(box.lo[a]), std::abs(box.hi[a]), std::abs(from[a])});
    const double pad = slack + 1e-9 * scale;
    const double lo = box.lo[a] - pad, hi = box.hi[a] + pad;
    const double o = from[a], d = dir[a];
    if (d == 0) {
      if (o < lo || o > hi) return false;
      continue;
    }
    double ta = (lo - o) / d, tb = (hi - o) / d;
    if (ta > tb) std::swap(ta, tb);
    // Widen the parameter interval too: the divisions round.
    const double widen =
        1e-9 * (group ? 2 * std::max(std::abs(ta), std::abs(tb)) : std::abs(ta) + std::abs(tb)) +
        1e-300;
    s0 = std::max(s0, ta - widen);
    s1 = std::min(s1, tb + widen);
    if (s0 > s1) return false;
  }
  return true;
}

bool overlaps(const Box& a, const Box& b, double slack) {
  for (int k = 0; k < 3; ++k) {
    const double scale =
        std::max({std::abs(a.lo[k]), std::abs(a.hi[k]), std::abs(b.lo[k]), std::abs(b.hi[k])});
    const double pad = slack + 1e-9 * scale;
    if (a.lo[k] > b.hi[k] + pad || b.lo[k] > a.hi[k] + pad) return false;
  }
  return true;
}

}  // namespace

void Bvh::scan_segment(const std::vector<Box>& boxes, const Vec3& from, const Vec3& to,
                       bool to_is_direction, double slack, std::vector<std::uint32_t>& out) {
  const Vec3 dir = to_is_direction ? to : to - from;
  const double s_max = to_is_direction ? std::numeric_limits<double>::infinity() : 1.0;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    if (meets<false>(boxes[i], from, dir, s_max, slack)) out.push_back(i);
}

void Bvh::scan_box(const std::vector<Box>& boxes, const Box& box, double slack,
                   std::vector<std::uint32_t>& out) {
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    if (overlaps(boxes[i], box, slack)) out.push_back(i);
}

std::vector<Box> Bvh::group_boxes(const std::vector<Box>& boxes) {
  std::vector<Box> groups;
  groups.reserve((boxes.size() + kScanGroup - 1) / kScanGroup);
  for (std::size_t first = 0; first < boxes.size(); first += kScanGroup) {
    Box group;  // in registers, not stored back at every member
    const std::size_t end = std::min<std::size_t>(first + kScanGroup, boxes.size());
    for (std::size_t i = first; i < end; ++i) group.extend(boxes[i]);
    groups.push_back(group);
  }
  return groups;
}

namespace {

/// The members of the groups `keep_group` passes that `keep` passes, in
/// index order.
template <class KeepGroup, class Keep>
void scan_groups(const std::vector<Box>& boxes, const std::vector<Box>& groups,
                 const KeepGroup& keep_group, const Keep& keep, std::vector<std::uint32_t>& out) {
  for (std::uint32_t g = 0; g < groups.size(); ++g) {
    if (!keep_group(groups[g])) continue;
    const std::uint32_t end = std::min<std::uint32_t>((g + 1) * Bvh::kScanGroup, boxes.size());
    for (std::uint32_t i = g * Bvh::kScanGroup; i < end; ++i)
      if (keep(boxes[i])) out.push_back(i);
  }
}

}  // namespace

void Bvh::scan_segment(const std::vector<Box>& boxes, const std::vector<Box>& groups,
                       const Vec3& from, const Vec3& to, bool to_is_direction, double slack,
                       std::vector<std::uint32_t>& out) {
  const Vec3 dir = to_is_direction ? to : to - from;
  const double s_max = to_is_direction ? std::numeric_limits<double>::infinity() : 1.0;
  scan_groups(
      boxes, groups, [&](const Box& b) { return meets<true>(b, from, dir, s_max, slack); },
      [&](const Box& b) { return meets<false>(b, from, dir, s_max, slack); }, out);
}

void Bvh::scan_box(const std::vector<Box>& boxes, const std::vector<Box>& groups, const Box& box,
                   double slack, std::vector<std::uint32_t>& out) {
  // overlaps is monotone as it stands: a larger box has a larger pad.
  const auto keep = [&](const Box& b) { return overlaps(b, box, slack); };
  scan_groups(boxes, groups, keep, keep, out);
}

void Bvh::query_box(const Box& box, double slack, std::vector<std::uint32_t>& out) const {
  query_if([&](const Box& b) { return overlaps(b, box, slack); }, out);
}

void Bvh::query_segment(const Vec3& from, const Vec3& to, bool to_is_direction, double slack,
                        std::vector<std::uint32_t>& out) const {
  const Vec3 dir = to_is_direction ? to : to - from;
  const double s_max = to_is_direction ? std::numeric_limits<double>::infinity() : 1.0;
  query_if([&](const Box& b) { return meets<false>(b, from, dir, s_max, slack); }, out);
}

}  // namespace umbra::geometry
