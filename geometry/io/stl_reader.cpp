// STL, ASCII and binary.
//
// Binary or ASCII is decided by size first: a file of exactly 84 + 50·n bytes,
// n being the little-endian count at byte 80, is binary, whatever its header
// says (binary headers often start with "solid"). Otherwise a file whose first
// word is `solid` is ASCII (separated by any whitespace: `solid<TAB>name` is
// ASCII, which CGAL 5.5 misreads). Anything else is an error naming the sizes.
//
// ASCII grammar, keywords case-insensitive, several solids allowed in a file:
//   solid [name] / facet normal nx ny nz / outer loop / vertex x y z (3 or more)
//   / endloop / endfacet / ... / endsolid [name]
// Normals are read past (they must be numbers; they are not coordinates, so
// NaN is tolerated there). Each facet is one polygon. Vertices are shared
// between facets only when their three coordinates are bit-identical (so +0
// and -0 stay apart), which is what lets adjacency be found downstream.
#include <umbra/geometry/io/mesh_lexer.h>
#include <umbra/geometry/io/position_welder.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace umbra::geometry::detail {
namespace {

std::uint32_t read_u32_le(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
         static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

float read_f32_le(const char* p) { return std::bit_cast<float>(read_u32_le(p)); }

PolygonSoup parse_binary(std::string_view bytes, std::uint32_t count, const std::string& name) {
  PolygonSoup soup;
  soup.polygons.reserve(count);  // the size rule has proven the file holds them
  PositionWelder merger(soup.vertices);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t facet = 84 + 50 * static_cast<std::size_t>(t);
    Polygon polygon;
    polygon.reserve(3);
    for (std::size_t corner = 0; corner < 3; ++corner) {
      Vec3 p;
      double* const axes[3] = {&p.x, &p.y, &p.z};
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::size_t offset = facet + 12 + 12 * corner + 4 * axis;
        *axes[axis] = static_cast<double>(read_f32_le(bytes.data() + offset));
        if (!std::isfinite(*axes[axis])) {
          throw util::InputError(at_byte(name, offset),
                                 "coordinate is not finite (triangle " + std::to_string(t) + ")");
        }
      }
      polygon.push_back(merger.add(p));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

bool keyword_is(std::string_view token, std::string_view keyword) {
  return to_lower(token) == keyword;
}

PolygonSoup parse_ascii(std::string_view bytes, const std::string& name) {
  PolygonSoup soup;
  PositionWelder merger(soup.vertices);
  TextCursor cursor(bytes);
  std::string_view token;
  auto expect = [&](std::string_view keyword) {
    if (!cursor.next(token)) {
      throw util::InputError(at_line(name, cursor.line()),
                             "file ends where '" + std::string(keyword) + "' was expected");
    }
    if (!keyword_is(token, keyword)) {
      throw util::InputError(at_line(name, cursor.line()),
                             "expected '" + std::string(keyword) + "', found '" +
                                 std::string(token.substr(0, 40)) + "'");
    }
  };
  auto number = [&](bool coordinate) {
    if (!cursor.next(token))
      throw util::InputError(at_line(name, cursor.line()), "file ends inside a facet");
    const std::string where = at_line(name, cursor.line());
    return coordinate ? parse_coordinate(token, where)
                      : parse_double(token, where, "normal component");
  };

  while (cursor.next(token)) {  // one solid per turn
    if (!keyword_is(token, "solid")) {
      throw util::InputError(at_line(name, cursor.line()),
                             "expected 'solid', found '" + std::string(token.substr(0, 40)) + "'");
    }
    cursor.skip_line();  // the solid's name
    while (true) {
      if (!cursor.next(token))
        throw util::InputError(at_line(name, cursor.line()), "file ends before 'endsolid'");
      if (keyword_is(token, "endsolid")) {
        cursor.skip_line();
        break;
      }
      if (!keyword_is(token, "facet")) {
        throw util::InputError(
            at_line(name, cursor.line()),
            "expected 'facet' or 'endsolid', found '" + std::string(token.substr(0, 40)) + "'");
      }
      const std::size_t facet_line = cursor.line();
      expect("normal");
      for (int k = 0; k < 3; ++k) number(false);
      expect("outer");
      expect("loop");
      Polygon polygon;
      while (true) {
        if (!cursor.next(token))
          throw util::InputError(at_line(name, cursor.line()), "file ends inside a facet");
        if (keyword_is(token, "endloop")) break;
        if (!keyword_is(token, "vertex")) {
          throw util::InputError(
              at_line(name, cursor.line()),
              "expected 'vertex' or 'endloop', found '" + std::string(token.substr(0, 40)) + "'");
        }
        Vec3 p;
        p.x = number(true);
        p.y = number(true);
        p.z = number(true);
        polygon.push_back(merger.add(p));
        if (polygon.size() > kMaxPolygonVertices)
          throw util::InputError(at_line(name, facet_line), polygon_too_large(polygon.size()));
      }
      if (polygon.size() < 3) {
        throw util::InputError(
            at_line(name, facet_line),
            "facet has " + std::to_string(polygon.size()) + " vertices; at least 3 are needed");
      }
      expect("endfacet");
      soup.polygons.push_back(std::move(polygon));
    }
  }
  return soup;
}

bool starts_with_solid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && (is_space(bytes[i]) || bytes[i] == '\n')) ++i;
  if (bytes.size() - i < 5 || to_lower(bytes.substr(i, 5)) != "solid") return false;
  return bytes.size() - i == 5 || is_space(bytes[i + 5]) || bytes[i + 5] == '\n';
}

}  // namespace

PolygonSoup parse_stl(std::string_view bytes, const std::string& name) {
  if (bytes.size() >= 84) {
    const std::uint32_t count = read_u32_le(bytes.data() + 80);
    if (84 + 50 * static_cast<std::uint64_t>(count) == bytes.size())
      return parse_binary(bytes, count, name);
    if (!starts_with_solid(bytes)) {
      throw util::InputError(at_byte(name, 80),
                             "truncated or oversized binary STL: the header declares " +
                                 std::to_string(count) + " triangles (84 + 50·" +
                                 std::to_string(count) + " = " +
                                 std::to_string(84 + 50 * static_cast<std::uint64_t>(count)) +
                                 " bytes) but the file has " + std::to_string(bytes.size()) +
                                 " bytes, and it is not ASCII STL (no 'solid' first)");
    }
  } else if (!starts_with_solid(bytes)) {
    throw util::InputError(
        name, "not an STL file: " + std::to_string(bytes.size()) +
                  " bytes is too short for binary STL and it does not start with 'solid'");
  }
  return parse_ascii(bytes, name);
}

}  // namespace umbra::geometry::detail
