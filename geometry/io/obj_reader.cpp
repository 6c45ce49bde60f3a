// Wavefront OBJ, geometry only.
//
//   v x y z [w]        a vertex; w must be exactly 1 (umbra does not divide by
//                      it); 6 or 7 values are x y z [w] r g b (vertex colors,
//                      a common extension), the colors ignored
//   f r1 r2 r3 ...     a polygon of 3 or more references i, i/t, i//n or i/t/n;
//                      i counts from 1, or from the end when negative (-1 is
//                      the last vertex read so far); t and n are ignored
//   fo ...             the old spelling of f
// vt, vn, g, o, s, usemtl, mtllib, l, p and any other statement are ignored.
// '#' starts a comment. A reference must name a vertex defined above it: index
// 0 or one past the last vertex read so far is an error at that line. Line
// continuation with '\' is not supported (the '\' is reported as malformed).
#include <umbra/geometry/io/mesh_lexer.h>

#include <cstdint>
#include <limits>

namespace umbra::geometry::detail {
namespace {

// The vertex index of one face reference ("7", "7/2", "7//3", "-1/2/3"), 0-based.
std::uint32_t vertex_index(std::string_view reference, std::size_t vertex_count,
                           const Where& where) {
  const std::string_view index_text = reference.substr(0, reference.find('/'));
  constexpr std::int64_t kLimit = std::numeric_limits<std::int64_t>::max();
  const std::int64_t index = parse_integer(index_text, where, "face index", -kLimit, kLimit);
  const auto count = static_cast<std::int64_t>(vertex_count);
  if (index == 0) throw util::InputError(where, "face index 0: OBJ indices start at 1");
  if (index > count || index < -count) {
    throw util::InputError(where, "face index " + std::to_string(index) + " out of range: " +
                                      std::to_string(count) + " vertices defined so far");
  }
  return static_cast<std::uint32_t>(index > 0 ? index - 1 : count + index);
}

}  // namespace

PolygonSoup parse_obj(std::string_view bytes, const std::string& name) {
  if (bytes.size() >= 2 &&
      ((bytes[0] == '\xFE' && bytes[1] == '\xFF') || (bytes[0] == '\xFF' && bytes[1] == '\xFE'))) {
    throw util::InputError(at_line(name, 1), "UTF-16 text is not supported; save the OBJ as UTF-8");
  }
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // UTF-8 byte-order mark

  PolygonSoup soup;
  LineReader lines(bytes);
  std::string_view line;
  std::string_view token;
  while (lines.next(line)) {
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    if (keyword == "v") {
      const Where where(name, lines.line_number());
      const std::size_t n = tokens.count_remaining();
      if (n != 3 && n != 4 && n != 6 && n != 7) {
        throw util::InputError(where,
                               "vertex needs 'x y z [w]' (optionally followed by 'r g b'); got " +
                                   std::to_string(n) + " values");
      }
      Vec3 p;
      tokens.next(token);
      p.x = parse_coordinate(token, where);
      tokens.next(token);
      p.y = parse_coordinate(token, where);
      tokens.next(token);
      p.z = parse_coordinate(token, where);
      if (n == 4 || n == 7) {
        tokens.next(token);
        const double w = parse_double(token, where, "w coordinate");
        if (w != 1.0) {
          throw util::InputError(where, "homogeneous coordinate w = " + std::string(token) +
                                            " is not supported (only w = 1)");
        }
      }
      if (soup.vertices.size() == std::numeric_limits<std::uint32_t>::max()) {
        throw util::InputError(where, "too many vertices for 32-bit indices");
      }
      soup.vertices.push_back(p);
    } else if (keyword == "f" || keyword == "fo") {
      const Where where(name, lines.line_number());
      const std::size_t n = tokens.count_remaining();
      if (n < 3) {
        throw util::InputError(
            where, "face has " + std::to_string(n) + " vertices; at least 3 are needed");
      }
      if (n > kMaxPolygonVertices) throw util::InputError(where, polygon_too_large(n));
      Polygon polygon;
      polygon.reserve(n);
      while (tokens.next(token))
        polygon.push_back(vertex_index(token, soup.vertices.size(), where));
      soup.polygons.push_back(std::move(polygon));
    }
    // Everything else (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) carries no polygon.
  }
  return soup;
}

}  // namespace umbra::geometry::detail
