#include <umbra/geometry/export/mesh_text.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <type_traits>

namespace umbra::geometry {

namespace {

template <class T>
void append_le(std::string& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  out.append(bytes.data(), bytes.size());
}

std::int32_t index_as_int32(std::uint32_t value) {
  if (value > static_cast<std::uint32_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("PLY: vertex index " + std::to_string(value) +
                                " does not fit a 32-bit int");
  return static_cast<std::int32_t>(value);
}

void append_position(std::string& out, const Vec3& v) {
  append_double(out, v.x);
  out += ' ';
  append_double(out, v.y);
  out += ' ';
  append_double(out, v.z);
}

}  // namespace

void append_double(std::string& out, double value) {
  std::array<char, 32> buffer;
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (ec != std::errc()) throw std::logic_error("to_chars failed");
  out.append(buffer.data(), end);
}

std::string ply_bytes(const IndexedFaces& indexed, std::span<const std::string> comments,
                      std::span<const FaceAttribute> attributes, std::span<const FaceReal> reals,
                      PlyEncoding encoding) {
  std::size_t largest = 0;
  for (const auto& face : indexed.faces) largest = std::max(largest, face.size());
  // uchar counts are what most PLY readers expect; a face with more vertices
  // than that needs a wider count, which the PLY format allows.
  const bool wide_count = largest > std::numeric_limits<std::uint8_t>::max();
  const bool ascii = encoding == PlyEncoding::ascii;

  std::string out = ascii ? "ply\nformat ascii 1.0\n" : "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& comment : comments) out += "comment " + comment + "\n";
  out += "element vertex " + std::to_string(indexed.vertices.size()) +
         "\n"
         "property double x\n"
         "property double y\n"
         "property double z\n"
         "element face " +
         std::to_string(indexed.faces.size()) + "\n";
  out += wide_count ? "property list uint int vertex_indices\n"
                    : "property list uchar int vertex_indices\n";
  for (const FaceAttribute& a : attributes) out += "property int " + a.name + "\n";
  for (const FaceReal& r : reals) out += "property double " + r.name + "\n";
  out += "end_header\n";

  if (ascii) {
    // One element a line, values separated by one space.
    for (const Vec3& v : indexed.vertices) {
      append_position(out, v);
      out += '\n';
    }
    for (std::size_t i = 0; i < indexed.faces.size(); ++i) {
      out += std::to_string(indexed.faces[i].size());
      for (const std::uint32_t v : indexed.faces[i]) out += ' ' + std::to_string(index_as_int32(v));
      for (const FaceAttribute& a : attributes) out += ' ' + std::to_string(a.values[i]);
      for (const FaceReal& r : reals) {
        out += ' ';
        append_double(out, r.values[i]);
      }
      out += '\n';
    }
    return out;
  }
  for (const Vec3& v : indexed.vertices) {
    append_le(out, v.x);
    append_le(out, v.y);
    append_le(out, v.z);
  }
  for (std::size_t i = 0; i < indexed.faces.size(); ++i) {
    const auto& face = indexed.faces[i];
    if (wide_count)
      append_le(out, static_cast<std::uint32_t>(face.size()));
    else
      append_le(out, static_cast<std::uint8_t>(face.size()));
    for (const std::uint32_t v : face) append_le(out, index_as_int32(v));
    for (const FaceAttribute& a : attributes) append_le(out, a.values[i]);
    for (const FaceReal& r : reals) append_le(out, r.values[i]);
  }
  return out;
}

std::string obj_text(const IndexedFaces& indexed, const std::string& comment,
                     const ObjGroups* groups) {
  std::string out = "# " + comment + "\n";
  if (groups) out += "mtllib " + groups->mtllib + "\n";
  for (const Vec3& v : indexed.vertices) {
    out += "v ";
    append_position(out, v);
    out += '\n';
  }
  for (std::size_t i = 0; i < indexed.faces.size(); ++i) {
    if (groups && (i == 0 || groups->names[i] != groups->names[i - 1]))
      out += "g " + groups->names[i] + "\nusemtl " + groups->names[i] + "\n";
    out += 'f';
    for (const std::uint32_t v : indexed.faces[i])
      out += ' ' + std::to_string(std::uint64_t{v} + 1);
    out += '\n';
  }
  return out;
}

std::string off_text(const IndexedFaces& indexed) {
  std::string out = "OFF\n" + std::to_string(indexed.vertices.size()) + " " +
                    std::to_string(indexed.faces.size()) + " 0\n";
  for (const Vec3& v : indexed.vertices) {
    append_position(out, v);
    out += '\n';
  }
  for (const auto& face : indexed.faces) {
    out += std::to_string(face.size());
    for (const std::uint32_t v : face) out += ' ' + std::to_string(v);
    out += '\n';
  }
  return out;
}

}  // namespace umbra::geometry
