#include <umbra/geometry/export/gltf_buffer.h>
#include <umbra/util/input_error.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace umbra::geometry::detail {

namespace {

using Json = nlohmann::json;

template <class T>
void append_le(std::string& out, T value) {
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  out.append(bytes.data(), bytes.size());
}

std::string base64(const std::string& in) {
  static constexpr char kTable[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, in.size() - i);
    std::uint32_t bits = 0;
    for (std::size_t k = 0; k < 3; ++k)
      bits = (bits << 8) | (k < n ? static_cast<std::uint8_t>(in[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kTable[(bits >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

}  // namespace

std::size_t GltfBuffer::view(const std::string& data, int target) {
  while (bin_.size() % 4 != 0) bin_ += '\0';
  views_.push_back({{"buffer", 0},
                    {"byteOffset", bin_.size()},
                    {"byteLength", data.size()},
                    {"target", target}});
  bin_ += data;
  return views_.size() - 1;
}

std::size_t GltfBuffer::floats_view(const std::vector<float>& values) {
  std::string data;
  data.reserve(values.size() * 4);
  for (const float v : values) append_le(data, v);
  return view(data, kGltfArrayBuffer);
}

std::size_t GltfBuffer::indices_view(const std::vector<std::uint32_t>& values) {
  std::string data;
  data.reserve(values.size() * 4);
  for (const std::uint32_t v : values) append_le(data, v);
  return view(data, kGltfElementArrayBuffer);
}

std::size_t GltfBuffer::accessor(std::size_t view_index, int component, std::size_t count,
                                 const char* type, const Json& min, const Json& max) {
  Json a = {
      {"bufferView", view_index}, {"componentType", component}, {"count", count}, {"type", type}};
  if (!min.is_null()) a["min"] = min;
  if (!max.is_null()) a["max"] = max;
  accessors_.push_back(std::move(a));
  return accessors_.size() - 1;
}

std::string GltfBuffer::finish(Json doc, bool binary, const std::string& name,
                               std::string_view what) const {
  if (!accessors_.empty()) {
    doc["accessors"] = accessors_;
    doc["bufferViews"] = views_;
    Json buffer = {{"byteLength", bin_.size()}};
    if (!binary) buffer["uri"] = "data:application/octet-stream;base64," + base64(bin_);
    doc["buffers"] = Json::array({buffer});
  }
  std::string json = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (!binary) return json + "\n";

  // GLB: 12-byte header, JSON chunk padded with spaces, BIN chunk with zeros.
  while (json.size() % 4 != 0) json += ' ';
  std::string body = bin_;
  while (body.size() % 4 != 0) body += '\0';
  const std::uint64_t total = 12 + 8 + json.size() + (body.empty() ? 0 : 8 + body.size());
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw util::InputError(name,
                           std::string(what) + " needs more than 4 GiB, more than a GLB can hold");
  std::string out = "glTF";
  append_le(out, std::uint32_t{2});
  append_le(out, static_cast<std::uint32_t>(total));
  append_le(out, static_cast<std::uint32_t>(json.size()));
  append_le(out, std::uint32_t{0x4E4F534A});  // "JSON"
  out += json;
  if (!body.empty()) {
    append_le(out, static_cast<std::uint32_t>(body.size()));
    append_le(out, std::uint32_t{0x004E4942});  // "BIN\0"
    out += body;
  }
  return out;
}

GltfFaceVertices::GltfFaceVertices(std::vector<const char*> attributes, std::string file,
                                   std::string what)
    : names_(std::move(attributes)),
      file_(std::move(file)),
      what_(std::move(what)),
      values_(names_.size()) {
  for (int k = 0; k < 3; ++k) {
    lo_[k] = std::numeric_limits<float>::max();
    hi_[k] = -std::numeric_limits<float>::max();
  }
}

std::uint32_t GltfFaceVertices::add_face(std::size_t index, const std::vector<Vec3>& vertices,
                                         const std::vector<double>& values) {
  for (std::size_t a = 0; a < values.size(); ++a)
    if (std::abs(values[a]) > 16777216.0)
      throw util::InputError(file_, std::string("attribute ") + names_[a] + " of " + what_ + " " +
                                        std::to_string(index) +
                                        " exceeds 2^24 and is not exact in a glTF float; use .ply");
  const auto first = static_cast<std::uint32_t>(count());
  for (const Vec3& v : vertices) {
    const double c[3] = {v.x, v.y, v.z};
    for (int k = 0; k < 3; ++k) {
      const auto x = static_cast<float>(c[k]);  // round to nearest float
      if (!std::isfinite(x))
        throw util::InputError(file_, "a vertex of " + what_ + " " + std::to_string(index) +
                                          " does not fit a float32 glTF position; use .ply");
      positions_.push_back(x);
      lo_[k] = std::min(lo_[k], x);
      hi_[k] = std::max(hi_[k], x);
    }
    for (std::size_t a = 0; a < values.size(); ++a)
      values_[a].push_back(static_cast<float>(values[a]));
  }
  return first;
}

void GltfFaceVertices::write(GltfBuffer& buffer, Json& attributes_json) const {
  attributes_json["POSITION"] =
      buffer.accessor(buffer.floats_view(positions_), kGltfFloat, count(), "VEC3",
                      {lo_[0], lo_[1], lo_[2]}, {hi_[0], hi_[1], hi_[2]});
  for (std::size_t a = 0; a < names_.size(); ++a) {
    const auto [mn, mx] = std::minmax_element(values_[a].begin(), values_[a].end());
    attributes_json[names_[a]] = buffer.accessor(buffer.floats_view(values_[a]), kGltfFloat,
                                                 count(), "SCALAR", {*mn}, {*mx});
  }
}

}  // namespace umbra::geometry::detail
