#include <umbra/geometry/footprint/receiver_partition.h>

#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_observer.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace umbra::geometry::detail {

namespace {

using Traits = CGAL::Arr_segment_traits_2<Epeck>;
using Dcel = CGAL::Arr_face_extended_dcel<Traits, int>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
using Curve = Traits::Curve_2;
using Face = Arrangement::Face_handle;
using Halfedge = Arrangement::Halfedge_handle;

// Face labels: outside the surface, or the Classifier's key plus one (so
// kLit is key 0's; every label above it is a shadow).
constexpr int kUnknown = -1, kOutside = 0, kLit = 1;

/// Faces split by a cut inherit the label of the face they came from.
/// It observes the base Arrangement_on_surface_2, the type the arrangement
/// calls its observers through: CGAL 5.5's Arr_observer<Arrangement_2> is a
/// different class that Arrangement_2 casts to the base's observer type, a
/// cast UBSan's vptr check rightly reports.
class LabelKeeper : public CGAL::Arr_observer<Arrangement::Base> {
 public:
  explicit LabelKeeper(Arrangement& arr) : CGAL::Arr_observer<Arrangement::Base>(arr) {}
  void after_split_face(Face f, Face new_f, bool /*is_hole*/) override {
    new_f->set_data(f->data());
  }
};

/// Every halfedge bounding f: its outer boundary and its holes' (the face
/// lies to the left of each).
std::vector<Halfedge> boundary_of(Face f) {
  std::vector<Halfedge> out;
  if (!f->is_unbounded()) {
    auto c = f->outer_ccb();
    const auto first = c;
    do out.push_back(c);
    while (++c != first);
  }
  for (auto h = f->holes_begin(); h != f->holes_end(); ++h) {
    auto c = *h;
    const auto first = c;
    do out.push_back(c);
    while (++c != first);
  }
  return out;
}

/// A point strictly inside the bounded face f, different for each attempt:
/// from a point M inside one of its outer halfedges, a step along the
/// inward normal half-way to the nearest boundary that normal meets.
Point2 interior_point(const std::vector<Halfedge>& boundary, std::size_t outer_size,
                      unsigned attempt) {
  static constexpr int kFractions[][2] = {{1, 2}, {1, 3}, {2, 3}, {2, 5}, {3, 7}, {5, 8}, {3, 11}};
  constexpr unsigned kCount = sizeof kFractions / sizeof kFractions[0];
  const Halfedge h = boundary[(attempt * 7) % outer_size];
  const auto* frac = kFractions[attempt % kCount];
  const InwardRay ray(h->source()->point(), h->target()->point(), FT(frac[0]) / FT(frac[1]));
  std::optional<FT> nearest;
  for (const Halfedge& e : boundary) {
    if (e == h) continue;
    const std::optional<FT> r = first_hit(ray, e->source()->point(), e->target()->point());
    if (r && (!nearest || *r < *nearest)) nearest = r;
  }
  if (!nearest) throw std::logic_error("partition_receiver: a bounded face with no boundary ahead");
  const FT step = *nearest / FT(1 + attempt % 3);  // 1/2, 1/3, 1/4 of the way
  return ray.at(step / 2);
}

/// Odd number of fan triangles strictly containing p (p is on none of
/// their edges: they are all in the arrangement).
bool in_surface(const ReceiverOutline& outline, const Point2& p) {
  bool odd = false;
  for (const auto& t : outline.fan) {
    const Point2& a = outline.vertices[t[0]];
    const Point2& b = outline.vertices[t[1]];
    const Point2& c = outline.vertices[t[2]];
    const CGAL::Orientation o = CGAL::orientation(a, b, c);
    if (o == CGAL::COLLINEAR) continue;
    if (CGAL::orientation(a, b, p) == o && CGAL::orientation(b, c, p) == o &&
        CGAL::orientation(c, a, p) == o)
      odd = !odd;
  }
  return odd;
}

void label_faces(Arrangement& arr, const ReceiverOutline& outline, const Classifier& classify,
                 PartitionCounts& counts) {
  constexpr unsigned kAttempts = 64;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) {
      f->set_data(kOutside);
      continue;
    }
    const std::vector<Halfedge> boundary = boundary_of(f);
    // boundary_of lists the outer boundary first.
    std::size_t outer_size = 0;
    auto c = f->outer_ccb();
    const auto first = c;
    do ++outer_size;
    while (++c != first);
    int label = kUnknown;
    for (unsigned attempt = 0; attempt < kAttempts && label == kUnknown; ++attempt) {
      const Point2 p = interior_point(boundary, outer_size, attempt);
      if (!in_surface(outline, p)) {
        label = kOutside;
        break;
      }
      const std::optional<int> key = classify(p);
      if (key) label = *key + 1;
    }
    if (label == kUnknown)
      throw std::logic_error("partition_receiver: no point of a face could be classified");
    if (label != kOutside) ++counts.classified_faces;
    f->set_data(label);
  }
}

/// Removes every edge with the same label on both sides, then every vertex
/// where the boundary runs straight on.
void merge_alike(Arrangement& arr) {
  std::vector<Halfedge> alike;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e)
    if (e->face()->data() == e->twin()->face()->data()) alike.push_back(e);
  for (const Halfedge& e : alike) arr.remove_edge(e);
  std::vector<Arrangement::Vertex_handle> straight;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (v->degree() != 2) continue;
    auto c = v->incident_halfedges();
    const Point2& p = c->source()->point();
    const Point2& q = (++c)->source()->point();
    if (CGAL::collinear(p, v->point(), q)) straight.push_back(v);
  }
  for (const auto& v : straight) {
    auto c = v->incident_halfedges();
    const Halfedge e1 = c;
    const Halfedge e2 = ++c;
    arr.merge_edge(e1, e2->twin(), Curve(e1->source()->point(), e2->source()->point()));
  }
}

/// The first boundary point of f straight above (up) or below p.
Point2 vertical_hit(const std::vector<Halfedge>& boundary, const Point2& p, bool up) {
  std::optional<FT> best;
  const auto better = [&](const FT& y) {
    if (up ? !(y > p.y()) : !(y < p.y())) return;
    if (!best || (up ? y < *best : y > *best)) best = y;
  };
  for (const Halfedge& e : boundary) {
    const Point2& a = e->source()->point();
    const Point2& b = e->target()->point();
    if (a.x() == b.x()) {
      if (a.x() == p.x()) {
        better(a.y());
        better(b.y());
      }
      continue;
    }
    if ((a.x() <= p.x() && p.x() <= b.x()) || (b.x() <= p.x() && p.x() <= a.x()))
      better(a.y() + (p.x() - a.x()) * (b.y() - a.y()) / (b.x() - a.x()));
  }
  if (!best) throw std::logic_error("partition_receiver: a hole with no boundary around it");
  return {p.x(), *best};
}

bool less_xy(const Point2& a, const Point2& b) { return CGAL::compare_xy(a, b) == CGAL::SMALLER; }

FT twice_area(const std::vector<Point2>& ring) {
  FT twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return twice;
}

/// A boundary that passes through a vertex twice, cut there into loops
/// that do not: each loop runs from a repeated vertex back to it. A face's
/// outer boundary does so where a hole touches it at a vertex (that loop
/// runs clockwise: the hole is on its right) or where two lobes of the
/// face touch (both run counter-clockwise).
std::vector<std::vector<Point2>> loops_of(const std::vector<Point2>& ring) {
  std::vector<std::vector<Point2>> loops;
  std::vector<Point2> stack;
  std::map<Point2, std::size_t, decltype(&less_xy)> at(&less_xy);
  for (const Point2& p : ring) {
    const auto it = at.find(p);
    if (it == at.end()) {
      at.emplace(p, stack.size());
      stack.push_back(p);
      continue;
    }
    // p closes the loop stack[it->second ..]; p stays as its start.
    std::vector<Point2> loop(stack.begin() + static_cast<std::ptrdiff_t>(it->second), stack.end());
    for (std::size_t k = it->second + 1; k < stack.size(); ++k) at.erase(stack[k]);
    stack.resize(it->second + 1);
    loops.push_back(std::move(loop));
  }
  loops.push_back(std::move(stack));
  return loops;
}

/// The outer boundary of f as its vertices, in order.
std::vector<Point2> outer_ring(Face f) {
  std::vector<Point2> ring;
  auto c = f->outer_ccb();
  const auto first = c;
  do ring.push_back(c->source()->point());
  while (++c != first);
  return ring;
}

/// Where to cut so that f's hole, or the loop of its outer boundary that a
/// hole touching it at a vertex makes, joins the rest of f's boundary.
/// Vertical rays from a loop's extreme vertices meet nothing of the loop:
/// up from the topmost of its leftmost (or rightmost) vertices, down from
/// the bottommost. A hole is cut up and down from its leftmost vertices,
/// which splits f so that no piece keeps the hole. A touching loop needs
/// one cut, from an extreme vertex other than those it touches the rest of
/// the boundary at (`touches`): that cut alone puts the two visits of the
/// vertex it touches at in different pieces.
void add_cuts(const std::vector<Halfedge>& boundary, const std::vector<Point2>& loop,
              const std::vector<Point2>* touches, std::vector<Curve>& cuts) {
  const auto extreme = [&](bool leftmost, bool top) {
    const Point2* best = &loop.front();
    for (const Point2& q : loop) {
      const CGAL::Comparison_result cx = CGAL::compare_x(q, *best);
      const bool further = leftmost ? cx == CGAL::SMALLER : cx == CGAL::LARGER;
      if (further || (cx == CGAL::EQUAL && (top ? q.y() > best->y() : q.y() < best->y())))
        best = &q;
    }
    return *best;
  };
  if (!touches) {
    const Point2 top = extreme(true, true), bottom = extreme(true, false);
    cuts.emplace_back(top, vertical_hit(boundary, top, true));
    cuts.emplace_back(bottom, vertical_hit(boundary, bottom, false));
    return;
  }
  for (const bool leftmost : {true, false}) {
    for (const bool top : {true, false}) {
      const Point2 u = extreme(leftmost, top);
      if (std::find(touches->begin(), touches->end(), u) != touches->end()) continue;
      cuts.emplace_back(u, vertical_hit(boundary, u, top));
      return;
    }
  }
  throw std::logic_error("partition_receiver: a touching loop with no vertex but its touch");
}

/// Cuts every labelled face until none has a hole or a hole touching its
/// outer boundary, so that every face's outer boundary is one simple
/// polygon or lobes meeting at vertices (which partition_receiver writes
/// as separate regions).
void cut_holes(Arrangement& arr) {
  for (int round = 0;; ++round) {
    if (round > 100000) throw std::logic_error("partition_receiver: holes do not close");
    // Every face's cuts at once: they lie in faces whose interiors are
    // disjoint, so one face's cuts do not move another's.
    std::vector<Curve> cuts;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
      if (f->data() < kLit) continue;
      const std::vector<Halfedge> boundary = boundary_of(f);
      if (f->number_of_holes() > 0) {
        for (auto h = f->holes_begin(); h != f->holes_end(); ++h) {
          std::vector<Point2> hole;
          auto c = *h;
          const auto start = c;
          do hole.push_back(c->target()->point());
          while (++c != start);
          add_cuts(boundary, hole, nullptr, cuts);
        }
        continue;  // touching loops, if any, in a later round
      }
      const std::vector<Point2> ring = outer_ring(f);
      for (const std::vector<Point2>& loop : loops_of(ring)) {
        if (!CGAL::is_negative(twice_area(loop))) continue;
        // The loop's vertices that the ring visits more than once.
        std::vector<Point2> touches;
        for (const Point2& q : loop)
          if (std::count(ring.begin(), ring.end(), q) > 1) touches.push_back(q);
        add_cuts(boundary, loop, &touches, cuts);
        break;
      }
    }
    if (cuts.empty()) return;
    for (const Curve& cut : cuts) CGAL::insert(arr, cut);
  }
}

}  // namespace

std::vector<PartitionRegion> partition_receiver(const ReceiverOutline& outline,
                                                const std::vector<Segment2>& boundary,
                                                const Classifier& classify,
                                                PartitionCounts& counts) {
  std::vector<Curve> curves;
  const auto add = [&](const Point2& a, const Point2& b) {
    if (a != b) curves.emplace_back(a, b);
  };
  const std::size_t n = outline.vertices.size();
  for (std::size_t i = 0; i < n; ++i) add(outline.vertices[i], outline.vertices[(i + 1) % n]);
  for (const auto& t : outline.fan) {  // the diagonals: the surface's parity is known off them
    add(outline.vertices[t[0]], outline.vertices[t[1]]);
    add(outline.vertices[t[2]], outline.vertices[t[0]]);
  }
  for (const Segment2& s : boundary) add(s.source(), s.target());

  Arrangement arr;
  LabelKeeper keeper(arr);
  CGAL::insert(arr, curves.begin(), curves.end());
  label_faces(arr, outline, classify, counts);
  merge_alike(arr);
  cut_holes(arr);

  std::vector<PartitionRegion> regions;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->data() < kLit) continue;
    auto c = f->outer_ccb();
    const auto first = c;
    do {
      if (c->twin()->face() == f)
        throw std::logic_error("partition_receiver: a region's boundary runs along itself");
    } while (++c != first);
    // Lobes of one face that touch at a vertex are separate regions.
    for (std::vector<Point2>& loop : loops_of(outer_ring(f))) {
      PartitionRegion region;
      region.cls = f->data() == kLit ? FootprintClass::lit : FootprintClass::shadowed;
      region.key = f->data() - 1;
      region.area = twice_area(loop) / 2;
      if (!CGAL::is_positive(region.area))
        throw std::logic_error(
            "partition_receiver: a region's loop does not run counter-clockwise");
      region.ring = std::move(loop);
      regions.push_back(std::move(region));
    }
  }
  return regions;
}

}  // namespace umbra::geometry::detail
