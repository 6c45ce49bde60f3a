#pragma once
// Internal to the mesh readers (geometry/*_reader.cpp, geometry/io/mesh_io.cpp):
// the per-format parsers and the lexing and number parsing they share. Not part
// of umbra's public API; include <geometry/io/mesh_io.h> instead.
#include <umbra/geometry/io/mesh_io.h>
#include <umbra/util/input_error.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::geometry::detail {

// One parser per format. `name` is the file as messages spell it. Each reports
// bad input with InputError at "name:line" (text) or "name: byte N" (binary),
// checks its own face indices, and may return a soup without polygons (the
// caller reports the empty mesh).
PolygonSoup parse_off(std::string_view bytes, const std::string& name);
PolygonSoup parse_obj(std::string_view bytes, const std::string& name);
PolygonSoup parse_ply(std::string_view bytes, const std::string& name);
PolygonSoup parse_stl(std::string_view bytes, const std::string& name);

/// A PLY file's polygons with its face element's integer scalar properties
/// (footprint files carry light, model, class... on each face).
struct PlyFaceTable {
  PolygonSoup soup;
  std::vector<std::string> names;                  ///< the face properties, in header order
  std::vector<std::vector<std::int64_t>> columns;  ///< one value per face for each name
  /// The face's floating-point scalar properties, likewise.
  std::vector<std::string> real_names;
  std::vector<std::vector<double>> real_columns;
  bool float_coordinates = false;  ///< some of x, y, z is a float
};
/// parse_ply, keeping the face element's scalar properties, and reading
/// faces of up to `max_polygon_vertices` vertices.
PlyFaceTable parse_ply_face_table(std::string_view bytes, const std::string& name,
                                  std::size_t max_polygon_vertices);

/// "name:line", the location of a text line (1-based).
std::string at_line(const std::string& name, std::size_t line);

/// Where a value was read, made into text ("name:line", at_line) only when
/// an error names it: the readers pass the place of every line they parse,
/// and building that text for each line cost more than the parsing (a 17 MB
/// OFF file: 320 M of its 1.2 G instructions). Holds pointers: the name, or
/// a given text, must outlive it.
class Where {
 public:
  /// A place already written out.
  Where(const std::string& text) : text_(&text) {}  // NOLINT: implicit on purpose
  /// Line `line` of file `name`.
  Where(const std::string& name, std::size_t line) : name_(&name), line_(line) {}
  operator std::string() const { return text_ ? *text_ : at_line(*name_, line_); }

 private:
  const std::string* text_ = nullptr;
  const std::string* name_ = nullptr;
  std::size_t line_ = 0;
};
/// "name: byte N", the location of binary data (0-based offset from the file's start).
std::string at_byte(const std::string& name, std::size_t offset);

/// Whitespace as every text format here sees it: space, \t, \r, \v, \f (a lone
/// \r inside a line, as in assimp's OFF/invalid.off, separates tokens).
constexpr bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Splits text into lines at '\n'; line numbers are 1-based.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  /// The next line without its '\n'; false at the end of the text.
  bool next(std::string_view& line);
  /// Number of the line `next` returned last.
  std::size_t line_number() const { return line_; }
  /// Bytes not yet returned.
  std::size_t remaining() const { return text_.size() - pos_; }
  /// Offset of the first byte not yet returned.
  std::size_t position() const { return pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

/// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : line_(line) {}
  /// The next token; false when none is left.
  bool next(std::string_view& token);
  /// The count of tokens not yet taken (scans, does not consume).
  std::size_t count_remaining() const;

 private:
  std::string_view line_;
  std::size_t pos_ = 0;
};

/// Whitespace-separated tokens across lines, tracking the line of each token.
class TextCursor {
 public:
  explicit TextCursor(std::string_view text, std::size_t first_line = 1)
      : text_(text), line_(first_line) {}
  /// The next token and its line; false at the end of the text.
  bool next(std::string_view& token);
  /// Line of the token `next` returned last (0 before the first).
  std::size_t line() const { return token_line_; }
  /// Skips to just after the next '\n'.
  void skip_line();
  std::size_t remaining() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
  std::size_t token_line_ = 0;
};

/// Parses the whole token as the double the text denotes (round to nearest,
/// std::from_chars, never through float); one leading '+' is allowed. Throws
/// InputError at `where` when the token is not wholly a number or is out of a
/// double's range: a magnitude that overflows (1e999) or underflows to zero
/// (1e-400) is refused rather than silently changed; subnormals are kept.
/// NaN and infinity spelled out ("nan", "inf") are returned as such.
double parse_double(std::string_view token, const Where& where, std::string_view what);
/// Same, for a coordinate: NaN and infinity are refused too.
double parse_coordinate(std::string_view token, const Where& where);
/// Same as parse_double in float (PLY ASCII `float` properties): the float the
/// text denotes, then widened exactly to double.
double parse_float_as_double(std::string_view token, const Where& where, std::string_view what);
/// Parses the whole token as a decimal integer (optional sign). Throws
/// InputError at `where` when malformed or outside [min, max].
std::int64_t parse_integer(std::string_view token, const Where& where, std::string_view what,
                           std::int64_t min, std::int64_t max);

/// ASCII lower-case copy, for case-insensitive keywords and extensions.
std::string to_lower(std::string_view text);

}  // namespace umbra::geometry::detail
