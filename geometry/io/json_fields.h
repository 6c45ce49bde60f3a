#pragma once
// Validating accessors over a parsed JSON document (json_document.h): each
// reads one field as the type umbra needs (a finite number, an integer in a
// range, a position within ±2^500, a direction that normalizes, a colour)
// and, on failure, names the file and the field's JSON path. Unknown and
// duplicated keys are errors, so that typos never pass. Paths are strings
// built by the caller; the per-vertex readers of large arrays build them only
// once something is wrong (scene_json.cpp). Internal to geometry/io.
#include <umbra/geometry/exact/coordinate_range.h>
#include <umbra/geometry/io/json_document.h>
#include <umbra/geometry/scene.h>
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <bitset>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace umbra::geometry::json {

using Element = simdjson::dom::element;
using Array = simdjson::dom::array;
using Type = simdjson::dom::element_type;

// An element's value of a type already checked. (simdjson's value_unsafe()
// returns a reference into the temporary result: copy it out at once.)
inline simdjson::dom::object as_object(Element v) {
  simdjson::dom::object o;
  [[maybe_unused]] const simdjson::error_code error = v.get_object().get(o);
  return o;
}
inline Array as_array(Element v) {
  Array a;
  [[maybe_unused]] const simdjson::error_code error = v.get_array().get(a);
  return a;
}
inline double as_double(Element v) {
  double d = 0;
  [[maybe_unused]] const simdjson::error_code error = v.get_double().get(d);
  return d;
}
inline std::int64_t as_int64(Element v) {
  std::int64_t i = 0;
  [[maybe_unused]] const simdjson::error_code error = v.get_int64().get(i);
  return i;
}
inline std::uint64_t as_uint64(Element v) {
  std::uint64_t u = 0;
  [[maybe_unused]] const simdjson::error_code error = v.get_uint64().get(u);
  return u;
}
inline bool as_bool(Element v) {
  bool b = false;
  [[maybe_unused]] const simdjson::error_code error = v.get_bool().get(b);
  return b;
}
inline std::string_view as_string(Element v) {
  std::string_view s;
  [[maybe_unused]] const simdjson::error_code error = v.get_string().get(s);
  return s;
}

class Fields {
 public:
  explicit Fields(const std::filesystem::path& file) : file_(file), name_(file.string()) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw util::InputError(path.empty() ? name_ : name_ + ": " + path, what);
  }

  void expect_object(Element v, const std::string& path) const {
    if (!v.is_object()) fail(path, std::string("expected an object, found ") + kind(v));
  }

  /// Every key of `object` is one of `allowed`, and none appears twice (the
  /// document keeps duplicates; which one a reader took would be arbitrary).
  void check_keys(Element object, const std::string& path,
                  std::initializer_list<std::string_view> allowed) const {
    std::bitset<64> seen;
    for (const simdjson::dom::key_value_pair field : as_object(object)) {
      std::size_t k = 0;
      for (std::string_view name : allowed) {
        if (name == field.key) break;
        ++k;
      }
      if (k == allowed.size()) {
        std::string list;
        for (std::string_view name : allowed)
          list += (list.empty() ? "" : ", ") + std::string(name);
        fail(child(path, field.key),
             "unknown field '" + std::string(field.key) + "'; expected one of " + list);
      }
      if (seen.test(k))
        fail(child(path, field.key), "duplicate field '" + std::string(field.key) + "'");
      seen.set(k);
    }
  }

  /// The value of `key` in `object` (an object already checked), if present.
  static std::optional<Element> find(Element object, std::string_view key) {
    Element value;
    if (as_object(object).at_key(key).get(value)) return std::nullopt;
    return value;
  }

  Element required(Element object, std::string_view key, const std::string& path) const {
    const std::optional<Element> value = find(object, key);
    if (!value) fail(child(path, key), "missing required field '" + std::string(key) + "'");
    return *value;
  }

  double number(Element v, const std::string& path) const {
    // simdjson refuses numbers that overflow a double, so every one is finite.
    if (!is_number(v)) fail(path, std::string("expected a number, found ") + kind(v));
    return as_double(v);
  }

  int integer(Element v, const std::string& path, int min, int max) const {
    const Type type = v.type();
    if (type != Type::INT64 && type != Type::UINT64)
      fail(path, std::string("expected an integer, found ") + kind(v));
    // An UINT64 is above INT64_MAX, outside every int range.
    const std::int64_t value = type == Type::INT64 ? as_int64(v) : -1;
    if (type == Type::UINT64 || value < min || value > max)
      fail(path,
           "must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return static_cast<int>(value);
  }

  /// The text of a vertex index that failed its range check, for the
  /// message; fails at `path` when `v` is not an integer at all.
  std::string index_text(Element v, const std::string& path) const {
    if (!v.is_int64() && !v.is_uint64()) fail(path, "expected a vertex index (an integer)");
    return v.is_int64() ? std::to_string(as_int64(v)) : std::to_string(as_uint64(v));
  }

  bool boolean(Element v, const std::string& path) const {
    if (!v.is_bool()) fail(path, std::string("expected true or false, found ") + kind(v));
    return as_bool(v);
  }

  std::string string(Element v, const std::string& path) const {
    if (!v.is_string()) fail(path, std::string("expected a string, found ") + kind(v));
    return std::string(as_string(v));
  }

  Array array(Element v, const std::string& path) const {
    if (!v.is_array()) fail(path, std::string("expected an array, found ") + kind(v));
    return as_array(v);
  }

  /// `v` as three numbers, or nothing: the check of the hot loops, which
  /// call vec3 (for its message) only when this fails.
  static std::optional<Vec3> try_vec3(Element v) {
    Array a;
    if (v.get_array().get(a) || a.size() != 3) return std::nullopt;
    double c[3];
    int i = 0;
    for (const Element e : a) {
      if (!is_number(e)) return std::nullopt;
      c[i++] = as_double(e);
    }
    return Vec3{c[0], c[1], c[2]};
  }

  Vec3 vec3(Element v, const std::string& path) const {
    if (const std::optional<Vec3> p = try_vec3(v)) return *p;
    if (!v.is_array() || as_array(v).size() != 3)
      fail(path, "expected an array of 3 numbers, found " + shape(v));
    std::size_t i = 0;
    for (const Element e : as_array(v)) number(e, item(path, i++));
    fail(path, "expected an array of 3 numbers");  // not reached: one of them is not a number
  }
  /// A position: a vector within ±kMaxCoordinate (coordinate_range.h).
  Vec3 point(Element v, const std::string& path) const {
    const Vec3 p = vec3(v, path);
    if (!within_coordinate_range(p)) fail(path, out_of_range(p));
    return p;
  }

  /// A direction: a nonzero vector that normalizes in doubles.
  Vec3 direction(Element v, const std::string& path) const {
    const Vec3 d = vec3(v, path);
    if (d == Vec3{0, 0, 0}) fail(path, "must not be the zero vector");
    if (!normalizable_direction(d))
      fail(path, fmt::format("({}, {}, {}) cannot be normalized in doubles: its largest component "
                             "must be between 2^-500 and 2^500 in magnitude",
                             d.x, d.y, d.z));
    return d;
  }

  static std::string out_of_range(const Vec3& p) {
    return fmt::format(
        "({}, {}, {}) is outside ±2^500 (~3.27e150), the range where umbra's "
        "arithmetic is exact (docs/scene-format.md, \"Numbers\")",
        p.x, p.y, p.z);
  }

  Rgb rgb(Element v, const std::string& path) const {
    const Vec3 c = vec3(v, path);
    for (int i = 0; i < 3; ++i) {
      if (c[i] < 0) fail(item(path, static_cast<std::size_t>(i)), "must be >= 0");
    }
    return {c.x, c.y, c.z};
  }

  const std::filesystem::path& file() const { return file_; }

 private:
  static bool is_number(Element v) {
    const Type type = v.type();
    return type == Type::DOUBLE || type == Type::INT64 || type == Type::UINT64;
  }
  static const char* kind(Element v) {
    switch (v.type()) {
      case Type::INT64:
      case Type::UINT64:
        return "an integer";
      case Type::DOUBLE:
        return "a number";
      case Type::STRING:
        return "a string";
      case Type::BOOL:
        return "a boolean";
      case Type::NULL_VALUE:
        return "null";
      case Type::ARRAY:
        return "an array";
      case Type::OBJECT:
        return "an object";
    }
    return "a value";
  }
  static std::string shape(Element v) {
    if (v.is_array()) return "an array of " + std::to_string(as_array(v).size());
    return kind(v);
  }

  std::filesystem::path file_;
  std::string name_;
};

}  // namespace umbra::geometry::json
