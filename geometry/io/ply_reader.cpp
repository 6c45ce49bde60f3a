// PLY (Stanford polygon format): ascii, binary_little_endian, binary_big_endian.
//
// The `vertex` element must have scalar properties x, y, z of any PLY type
// (char/int8, uchar/uint8, short/int16, ushort/uint16, int/int32, uint/uint32,
// float/float32, double/float64). Their value is the one the file denotes: a
// `float` property is a float (in ASCII, the text rounded to float) widened
// exactly to double; a `double` property keeps its double. The `face` element
// needs a list property `vertex_indices` or `vertex_index` with integer count
// and index types. Every other property and element is read past, in all three
// encodings. Element counts are checked against the bytes left before anything
// is reserved. Locations: "file:line" in ASCII, "file: byte N" in binary.
// Over 500 lines: the header, the three encodings and the face-table variant
// (footprint files' face properties) share one parser, which splitting would
// have to expose.
#include <umbra/geometry/io/mesh_lexer.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

namespace umbra::geometry::detail {
namespace {

enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64 };

std::optional<Scalar> scalar_named(std::string_view name) {
  if (name == "char" || name == "int8") return Scalar::i8;
  if (name == "uchar" || name == "uint8") return Scalar::u8;
  if (name == "short" || name == "int16") return Scalar::i16;
  if (name == "ushort" || name == "uint16") return Scalar::u16;
  if (name == "int" || name == "int32") return Scalar::i32;
  if (name == "uint" || name == "uint32") return Scalar::u32;
  if (name == "float" || name == "float32") return Scalar::f32;
  if (name == "double" || name == "float64") return Scalar::f64;
  return std::nullopt;
}

std::size_t size_of(Scalar type) {
  switch (type) {
    case Scalar::i8:
    case Scalar::u8:
      return 1;
    case Scalar::i16:
    case Scalar::u16:
      return 2;
    case Scalar::i32:
    case Scalar::u32:
    case Scalar::f32:
      return 4;
    case Scalar::f64:
      return 8;
  }
  return 0;
}

bool is_integer(Scalar type) { return type != Scalar::f32 && type != Scalar::f64; }

std::int64_t min_of(Scalar type) {
  switch (type) {
    case Scalar::i8:
      return std::numeric_limits<std::int8_t>::min();
    case Scalar::i16:
      return std::numeric_limits<std::int16_t>::min();
    case Scalar::i32:
      return std::numeric_limits<std::int32_t>::min();
    default:
      return 0;
  }
}

std::int64_t max_of(Scalar type) {
  switch (type) {
    case Scalar::i8:
      return std::numeric_limits<std::int8_t>::max();
    case Scalar::u8:
      return std::numeric_limits<std::uint8_t>::max();
    case Scalar::i16:
      return std::numeric_limits<std::int16_t>::max();
    case Scalar::u16:
      return std::numeric_limits<std::uint16_t>::max();
    case Scalar::i32:
      return std::numeric_limits<std::int32_t>::max();
    default:
      return std::numeric_limits<std::uint32_t>::max();
  }
}

struct Property {
  std::string name;
  bool is_list = false;
  Scalar count_type = Scalar::u8;  // lists only
  Scalar type = Scalar::f32;       // the value's type, or the list items' type
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  // header line that declared it
};

enum class Encoding { ascii, little_endian, big_endian };

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  std::size_t data_offset = 0;  // first byte after end_header's line
  std::size_t data_line = 0;    // line number of that byte (ASCII)
};

Header parse_header(std::string_view bytes, const std::string& name) {
  Header header;
  LineReader lines(bytes);
  std::string_view line;
  std::string_view token;
  if (!lines.next(line) || [&] {
        Tokens t(line);
        return !t.next(token) || token != "ply" || t.next(token);
      }()) {
    throw util::InputError(at_line(name, 1), "malformed PLY header: the first line must be 'ply'");
  }
  bool have_format = false;
  while (true) {
    if (!lines.next(line)) {
      throw util::InputError(at_line(name, lines.line_number()),
                             "malformed PLY header: no 'end_header'");
    }
    const std::string where = at_line(name, lines.line_number());
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string_view format;
      std::string_view version;
      if (!tokens.next(format) || !tokens.next(version) || tokens.next(token) || version != "1.0") {
        throw util::InputError(where,
                               "malformed PLY format line: expected 'format <encoding> 1.0'");
      }
      if (format == "ascii")
        header.encoding = Encoding::ascii;
      else if (format == "binary_little_endian")
        header.encoding = Encoding::little_endian;
      else if (format == "binary_big_endian")
        header.encoding = Encoding::big_endian;
      else
        throw util::InputError(where, "unknown PLY format '" + std::string(format) + "'");
      have_format = true;
    } else if (keyword == "element") {
      std::string_view element_name;
      if (!tokens.next(element_name) || !tokens.next(token) || tokens.count_remaining() != 0) {
        throw util::InputError(where,
                               "malformed PLY element line: expected 'element <name> <count>'");
      }
      Element element;
      element.name = element_name;
      element.count = static_cast<std::uint64_t>(parse_integer(
          token, where, "element count", 0, std::numeric_limits<std::int64_t>::max()));
      element.line = lines.line_number();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) throw util::InputError(where, "PLY property before any element");
      Property property;
      std::string_view type_name;
      tokens.next(type_name);
      if (type_name == "list") {
        std::string_view count_name;
        std::string_view item_name;
        std::string_view property_name;
        if (!tokens.next(count_name) || !tokens.next(item_name) || !tokens.next(property_name) ||
            tokens.next(token)) {
          throw util::InputError(
              where,
              "malformed PLY list property: expected 'property list <count type> "
              "<item type> <name>'");
        }
        const auto count_type = scalar_named(count_name);
        const auto item_type = scalar_named(item_name);
        if (!count_type || !item_type) throw util::InputError(where, "unknown PLY scalar type");
        if (!is_integer(*count_type))
          throw util::InputError(where, "PLY list count type must be an integer type");
        property = {std::string(property_name), true, *count_type, *item_type};
      } else {
        std::string_view property_name;
        const auto type = scalar_named(type_name);
        if (!type)
          throw util::InputError(where, "unknown PLY scalar type '" + std::string(type_name) + "'");
        if (!tokens.next(property_name) || tokens.next(token)) {
          throw util::InputError(where,
                                 "malformed PLY property: expected 'property <type> <name>'");
        }
        property = {std::string(property_name), false, Scalar::u8, *type};
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      throw util::InputError(where, "unknown PLY header keyword '" + std::string(keyword) + "'");
    }
  }
  if (!have_format)
    throw util::InputError(at_line(name, lines.line_number()), "PLY header has no format line");
  header.data_offset = lines.position();
  header.data_line = lines.line_number() + 1;
  return header;
}

// Values of the ASCII body, token by token.
class AsciiSource {
 public:
  AsciiSource(std::string_view body, std::size_t first_line, const std::string& name)
      : cursor_(body, first_line), name_(name) {}

  std::string where() const { return at_line(name_, cursor_.line()); }
  /// Where the value read last is.
  std::string last_where() const { return where(); }

  double real(Scalar type, std::string_view what, const std::string& context) {
    const std::string_view token = take(context);
    const std::string at = where();
    if (type == Scalar::f32) return parse_float_as_double(token, at, what);
    if (type == Scalar::f64) return parse_double(token, at, what);
    return static_cast<double>(parse_integer(token, at, what, min_of(type), max_of(type)));
  }
  std::int64_t integer(Scalar type, std::string_view what, const std::string& context) {
    const std::string_view token = take(context);
    return parse_integer(token, where(), what, min_of(type), max_of(type));
  }
  /// Whether `n` values of `type` can still follow.
  bool has_room(std::uint64_t n, Scalar /*type*/) const { return n <= cursor_.remaining() / 2 + 1; }

 private:
  std::string_view take(const std::string& context) {
    std::string_view token;
    if (!cursor_.next(token)) throw util::InputError(where(), "file ends inside " + context);
    return token;
  }
  TextCursor cursor_;
  const std::string& name_;
};

// Values of a binary body, in either byte order.
class BinarySource {
 public:
  BinarySource(std::string_view bytes, std::size_t offset, bool big_endian, const std::string& name)
      : bytes_(bytes),
        pos_(offset),
        swap_(big_endian != (std::endian::native == std::endian::big)),
        name_(name) {}

  std::string where() const { return at_byte(name_, pos_); }
  /// Where the value read last starts.
  std::string last_where() const { return at_byte(name_, last_pos_); }

  double real(Scalar type, std::string_view what, const std::string& context) {
    if (type == Scalar::f32) {
      float value;
      load(&value, sizeof value, context);
      return static_cast<double>(value);
    }
    if (type == Scalar::f64) {
      double value;
      load(&value, sizeof value, context);
      return value;
    }
    return static_cast<double>(integer(type, what, context));
  }
  std::int64_t integer(Scalar type, std::string_view /*what*/, const std::string& context) {
    switch (type) {
      case Scalar::i8: {
        std::int8_t v;
        load(&v, 1, context);
        return v;
      }
      case Scalar::u8: {
        std::uint8_t v;
        load(&v, 1, context);
        return v;
      }
      case Scalar::i16: {
        std::int16_t v;
        load(&v, 2, context);
        return v;
      }
      case Scalar::u16: {
        std::uint16_t v;
        load(&v, 2, context);
        return v;
      }
      case Scalar::i32: {
        std::int32_t v;
        load(&v, 4, context);
        return v;
      }
      case Scalar::u32: {
        std::uint32_t v;
        load(&v, 4, context);
        return v;
      }
      default:
        break;  // the header admits only integer types here
    }
    throw util::InputError(where(), "internal: integer read of a floating-point PLY type");
  }
  bool has_room(std::uint64_t n, Scalar type) const {
    return n <= (bytes_.size() - pos_) / size_of(type);
  }

 private:
  void load(void* out, std::size_t size, const std::string& context) {
    if (bytes_.size() - pos_ < size) {
      throw util::InputError(where(), "truncated binary data: file ends inside " + context);
    }
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, size);
    if (swap_) {
      for (std::size_t i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    }
    std::memcpy(out, raw, size);
    last_pos_ = pos_;
    pos_ += size;
  }
  std::string_view bytes_;
  std::size_t pos_;
  std::size_t last_pos_ = 0;
  bool swap_;
  const std::string& name_;
};

// Checks what the header promises against the bytes that follow it, before
// anything is reserved: every value takes at least its size in binary, and at
// least one character and a separator in ASCII.
void check_counts(const Header& header, std::size_t body_size, const std::string& name) {
  std::uint64_t needed = 0;
  for (const Element& element : header.elements) {
    std::uint64_t per_item = 0;
    for (const Property& property : element.properties) {
      if (header.encoding == Encoding::ascii)
        per_item += 2;
      else
        per_item += size_of(property.is_list ? property.count_type : property.type);
    }
    const std::string where = at_line(name, element.line);
    if (per_item == 0 && element.count > 0) {
      throw util::InputError(where, "PLY element '" + element.name + "' has no properties");
    }
    if (per_item == 0) continue;
    const std::uint64_t room = body_size + 1;  // an ASCII body may lack its last separator
    if (element.count > room / per_item || needed + element.count * per_item > room) {
      throw util::InputError(where, "PLY element '" + element.name + "' declares " +
                                        std::to_string(element.count) +
                                        " items, more than the remaining " +
                                        std::to_string(body_size) + " bytes can hold");
    }
    needed += element.count * per_item;
  }
}

/// What read_body keeps besides the soup: the face element's scalar
/// properties, integer and floating-point apart, by column, when a caller
/// asks for them.
struct FaceColumns {
  std::vector<std::string> names;
  std::vector<std::vector<std::int64_t>> values;
  std::vector<std::string> real_names;
  std::vector<std::vector<double>> real_values;
};

template <typename Source>
void read_body(Source& source, const Header& header, PolygonSoup& soup,
               std::size_t max_polygon_vertices, FaceColumns* columns) {
  std::uint64_t vertex_count = 0;
  for (const Element& element : header.elements) {
    if (element.name == "vertex") vertex_count = element.count;
  }
  const auto max_index = static_cast<std::int64_t>(vertex_count) - 1;
  for (const Element& element : header.elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    for (std::uint64_t item = 0; item < element.count; ++item) {
      const std::string context = "element '" + element.name + "' #" + std::to_string(item);
      Vec3 p;
      for (const Property& property : element.properties) {
        if (property.is_list) {
          const bool indices =
              is_face && (property.name == "vertex_indices" || property.name == "vertex_index");
          const std::int64_t n = source.integer(property.count_type, "list length", context);
          const std::string at = source.last_where();
          if (n < 0) throw util::InputError(at, "negative list length in " + context);
          if (!source.has_room(static_cast<std::uint64_t>(n), property.type)) {
            throw util::InputError(at, "truncated data: list length " + std::to_string(n) + " in " +
                                           context + " runs past the end of the file");
          }
          if (!indices) {
            for (std::int64_t k = 0; k < n; ++k) source.real(property.type, "list value", context);
            continue;
          }
          if (n < 3) {
            throw util::InputError(
                at, "face has " + std::to_string(n) + " vertices; at least 3 are needed");
          }
          if (static_cast<std::uint64_t>(n) > max_polygon_vertices)
            throw util::InputError(at,
                                   max_polygon_vertices == kMaxPolygonVertices
                                       ? polygon_too_large(static_cast<std::uint64_t>(n))
                                       : "face has " + std::to_string(n) + " vertices; at most " +
                                             std::to_string(max_polygon_vertices) + " are read");
          Polygon polygon;
          polygon.reserve(static_cast<std::size_t>(n));
          for (std::int64_t k = 0; k < n; ++k) {
            const std::int64_t index = source.integer(property.type, "face index", context);
            const std::string index_at = source.last_where();
            if (index < 0 || index > max_index) {
              throw util::InputError(
                  index_at, "face index " + std::to_string(index) +
                                " out of range: " + std::to_string(vertex_count) + " vertices");
            }
            polygon.push_back(static_cast<std::uint32_t>(index));
          }
          soup.polygons.push_back(std::move(polygon));
        } else if (is_vertex &&
                   (property.name == "x" || property.name == "y" || property.name == "z")) {
          const double value = source.real(property.type, "coordinate", context);
          if (!std::isfinite(value))
            throw util::InputError(source.last_where(),
                                   "coordinate " + property.name + " is not finite");
          (property.name == "x" ? p.x : property.name == "y" ? p.y : p.z) = value;
        } else if (is_face && columns && is_integer(property.type)) {
          const std::int64_t value = source.integer(property.type, "face property", context);
          for (std::size_t c = 0; c < columns->names.size(); ++c)
            if (columns->names[c] == property.name) columns->values[c].push_back(value);
        } else if (is_face && columns) {
          const double value = source.real(property.type, "face property", context);
          for (std::size_t c = 0; c < columns->real_names.size(); ++c)
            if (columns->real_names[c] == property.name) columns->real_values[c].push_back(value);
        } else {
          source.real(property.type, "value", context);
        }
      }
      if (is_vertex) soup.vertices.push_back(p);
    }
  }
}

}  // namespace

namespace {

PolygonSoup parse_ply_into(std::string_view bytes, const std::string& name,
                           std::size_t max_polygon_vertices, FaceColumns* columns,
                           bool* float_coordinates) {
  const Header header = parse_header(bytes, name);

  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& element : header.elements) {
    const std::string where = at_line(name, element.line);
    if (element.name == "vertex") {
      if (vertex) throw util::InputError(where, "second PLY element 'vertex'");
      vertex = &element;
      for (const char* axis : {"x", "y", "z"}) {
        int found = 0;
        for (const Property& property : element.properties) {
          if (property.name != axis) continue;
          if (property.is_list)
            throw util::InputError(where, std::string("vertex property ") + axis + " is a list");
          ++found;
        }
        if (found != 1) {
          throw util::InputError(
              where, std::string("PLY element 'vertex' needs exactly one property ") + axis);
        }
      }
    } else if (element.name == "face") {
      if (face) throw util::InputError(where, "second PLY element 'face'");
      face = &element;
      int found = 0;
      for (const Property& property : element.properties) {
        if (property.name != "vertex_indices" && property.name != "vertex_index") continue;
        if (!property.is_list || !is_integer(property.type)) {
          throw util::InputError(where,
                                 "face property " + property.name + " must be a list of integers");
        }
        ++found;
      }
      if (found != 1) {
        throw util::InputError(
            where, "PLY element 'face' needs one list property vertex_indices (or vertex_index)");
      }
    }
  }
  if (face && face->count > 0 && !vertex) {
    throw util::InputError(at_line(name, face->line), "PLY file has faces but no element 'vertex'");
  }
  check_counts(header, bytes.size() - header.data_offset, name);
  if (vertex && vertex->count > std::numeric_limits<std::uint32_t>::max()) {
    throw util::InputError(at_line(name, vertex->line), "too many vertices for 32-bit indices");
  }

  PolygonSoup soup;
  if (vertex) soup.vertices.reserve(vertex->count);
  if (face) soup.polygons.reserve(face->count);
  if (columns && face) {
    for (const Property& property : face->properties) {
      if (property.is_list) continue;
      if (std::find(columns->names.begin(), columns->names.end(), property.name) !=
              columns->names.end() ||
          std::find(columns->real_names.begin(), columns->real_names.end(), property.name) !=
              columns->real_names.end())
        throw util::InputError(at_line(name, face->line),
                               "face property " + property.name + " declared twice");
      if (is_integer(property.type)) {
        columns->names.push_back(property.name);
        columns->values.emplace_back().reserve(face->count);
      } else {
        columns->real_names.push_back(property.name);
        columns->real_values.emplace_back().reserve(face->count);
      }
    }
  }
  if (float_coordinates && vertex) {
    *float_coordinates = false;
    for (const Property& property : vertex->properties)
      if ((property.name == "x" || property.name == "y" || property.name == "z") &&
          property.type == Scalar::f32)
        *float_coordinates = true;
  }
  if (header.encoding == Encoding::ascii) {
    AsciiSource source(bytes.substr(header.data_offset), header.data_line, name);
    read_body(source, header, soup, max_polygon_vertices, columns);
  } else {
    BinarySource source(bytes, header.data_offset, header.encoding == Encoding::big_endian, name);
    read_body(source, header, soup, max_polygon_vertices, columns);
  }
  return soup;
}

}  // namespace

PolygonSoup parse_ply(std::string_view bytes, const std::string& name) {
  return parse_ply_into(bytes, name, kMaxPolygonVertices, nullptr, nullptr);
}

PlyFaceTable parse_ply_face_table(std::string_view bytes, const std::string& name,
                                  std::size_t max_polygon_vertices) {
  PlyFaceTable table;
  FaceColumns columns;
  table.soup =
      parse_ply_into(bytes, name, max_polygon_vertices, &columns, &table.float_coordinates);
  table.names = std::move(columns.names);
  table.columns = std::move(columns.values);
  table.real_names = std::move(columns.real_names);
  table.real_columns = std::move(columns.real_values);
  return table;
}

}  // namespace umbra::geometry::detail
