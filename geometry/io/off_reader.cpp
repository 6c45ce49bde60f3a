// OFF (Object File Format, as Geomview and CGAL write it).
//
//   [C][N]OFF [nv nf [ne]]     header; the counts may follow on the same line
//   nv nf [ne]                 counts (the edge count is ignored)
//   x y z [extra...]           nv vertex lines; colors/normals after xyz ignored
//   n i0 ... i(n-1) [extra...] nf face lines; a color after the indices ignored
//
// '#' starts a comment up to the end of the line; blank lines are skipped. One
// vertex or face per line. Counts are checked against the bytes that remain
// before anything is reserved, so a header that claims 353535235358 vertices
// (assimp's invalid/OutOfMemory.off) is an error, not an allocation.
#include <umbra/geometry/io/mesh_lexer.h>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace umbra::geometry::detail {
namespace {

// The next line with a token on it, comments removed; false at the end.
bool next_content_line(LineReader& lines, std::string_view& line) {
  while (lines.next(line)) {
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    Tokens probe(line);
    std::string_view token;
    if (probe.next(token)) return true;
  }
  return false;
}

// Each vertex and face takes a line with a token on it: two bytes at least.
// (A valid line takes more, but a line that is there and wrong deserves its
// own message; this bound only stops counts the file cannot possibly hold.)
constexpr std::uint64_t kMinVertexBytes = 2;
constexpr std::uint64_t kMinFaceBytes = 2;

}  // namespace

PolygonSoup parse_off(std::string_view bytes, const std::string& name) {
  LineReader lines(bytes);
  std::string_view line;
  if (!next_content_line(lines, line)) throw util::InputError(name + ":1", "missing OFF header");

  Tokens header(line);
  std::string_view keyword;
  header.next(keyword);
  if (keyword != "OFF" && keyword != "COFF" && keyword != "NOFF" && keyword != "CNOFF") {
    throw util::InputError(at_line(name, lines.line_number()),
                           "malformed OFF header: expected OFF, COFF, NOFF or CNOFF");
  }
  // The counts follow on the header line or on the next content line.
  Tokens counts = header;
  std::size_t counts_line = lines.line_number();
  if (header.count_remaining() == 0) {
    if (!next_content_line(lines, line)) {
      throw util::InputError(at_line(name, lines.line_number()), "missing OFF counts line");
    }
    counts = Tokens(line);
    counts_line = lines.line_number();
  }
  const std::string counts_where = at_line(name, counts_line);
  const std::size_t count_tokens = counts.count_remaining();
  if (count_tokens < 2 || count_tokens > 3) {
    throw util::InputError(counts_where, "malformed OFF counts: expected 'vertices faces [edges]'");
  }
  constexpr std::int64_t kMaxCount = std::numeric_limits<std::int64_t>::max();
  std::string_view token;
  counts.next(token);
  const auto nv =
      static_cast<std::uint64_t>(parse_integer(token, counts_where, "vertex count", 0, kMaxCount));
  counts.next(token);
  const auto nf =
      static_cast<std::uint64_t>(parse_integer(token, counts_where, "face count", 0, kMaxCount));
  if (counts.next(token)) parse_integer(token, counts_where, "edge count", 0, kMaxCount);

  // Never trust a count before the file has shown it can hold that much.
  const std::uint64_t room = lines.remaining() + 1;  // the last line may lack its '\n'
  if (nv > room / kMinVertexBytes || nf > room / kMinFaceBytes ||
      nv * kMinVertexBytes + nf * kMinFaceBytes > room) {
    throw util::InputError(counts_where, "declares " + std::to_string(nv) + " vertices and " +
                                             std::to_string(nf) +
                                             " faces, more than the remaining " +
                                             std::to_string(lines.remaining()) + " bytes can hold");
  }
  if (nv > std::numeric_limits<std::uint32_t>::max()) {
    throw util::InputError(counts_where, "too many vertices for 32-bit indices");
  }

  PolygonSoup soup;
  soup.vertices.reserve(nv);
  soup.polygons.reserve(nf);
  for (std::uint64_t v = 0; v < nv; ++v) {
    if (!next_content_line(lines, line)) {
      throw util::InputError(
          at_line(name, lines.line_number()),
          "file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    }
    const Where where(name, lines.line_number());
    Tokens values(line);
    if (values.count_remaining() < 3) throw util::InputError(where, "vertex needs 3 coordinates");
    Vec3 p;
    values.next(token);
    p.x = parse_coordinate(token, where);
    values.next(token);
    p.y = parse_coordinate(token, where);
    values.next(token);
    p.z = parse_coordinate(token, where);
    soup.vertices.push_back(p);
  }
  const auto max_index = static_cast<std::int64_t>(nv) - 1;
  for (std::uint64_t f = 0; f < nf; ++f) {
    if (!next_content_line(lines, line)) {
      throw util::InputError(
          at_line(name, lines.line_number()),
          "file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    }
    const Where where(name, lines.line_number());
    Tokens values(line);
    values.next(token);
    const std::size_t available = values.count_remaining();
    const auto n = parse_integer(token, where, "face vertex count", 0, kMaxCount);
    if (static_cast<std::uint64_t>(n) > available) {
      throw util::InputError(where, "face declares " + std::to_string(n) +
                                        " vertices but the line has " + std::to_string(available) +
                                        " more values");
    }
    if (n < 3) {
      throw util::InputError(where,
                             "face has " + std::to_string(n) + " vertices; at least 3 are needed");
    }
    if (static_cast<std::uint64_t>(n) > kMaxPolygonVertices)
      throw util::InputError(where, polygon_too_large(static_cast<std::uint64_t>(n)));
    Polygon polygon;
    polygon.reserve(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k) {
      values.next(token);
      if (max_index < 0)
        throw util::InputError(where,
                               "face index " + std::string(token) + " but the file has no vertex");
      polygon.push_back(
          static_cast<std::uint32_t>(parse_integer(token, where, "face index", 0, max_index)));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

}  // namespace umbra::geometry::detail
