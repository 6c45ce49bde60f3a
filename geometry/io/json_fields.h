#pragma once
// Validating accessors over a parsed JSON document: each reads one field as
// the type umbra needs (a finite number, an integer in a range, a position
// within ±2^500, a direction that normalizes, a colour) and, on failure,
// names the file and the field's JSON path. Unknown keys are errors, so that
// typos never pass. Internal to geometry/io.
#include <geometry/exact/coordinate_range.h>
#include <geometry/io/located_json.h>
#include <geometry/scene.h>
#include <util/input_error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>

namespace umbra::geometry::json {

class Fields {
 public:
  explicit Fields(const std::filesystem::path& file) : file_(file), name_(file.string()) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw util::InputError(path.empty() ? name_ : name_ + ": " + path, what);
  }

  void expect_object(const Json& v, const std::string& path) const {
    if (!v.is_object()) fail(path, std::string("expected an object, found ") + kind(v));
  }

  void check_keys(const Json& object, const std::string& path,
                  std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string list;
      for (std::string_view name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      fail(child(path, key), "unknown field '" + key + "'; expected one of " + list);
    }
  }

  const Json& required(const Json& object, std::string_view key, const std::string& path) const {
    const auto it = object.find(key);
    if (it == object.end())
      fail(child(path, key), "missing required field '" + std::string(key) + "'");
    return *it;
  }

  double number(const Json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, std::string("expected a number, found ") + kind(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "number is not finite");
    return d;
  }

  int integer(const Json& v, const std::string& path, int min, int max) const {
    if (!v.is_number_integer()) fail(path, std::string("expected an integer, found ") + kind(v));
    const bool in_range =
        v.is_number_unsigned()
            ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(max) &&
                  (min <= 0 || v.get<std::uint64_t>() >= static_cast<std::uint64_t>(min))
            : v.get<std::int64_t>() >= min && v.get<std::int64_t>() <= max;
    if (!in_range)
      fail(path,
           "must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return static_cast<int>(v.get<std::int64_t>());
  }

  bool boolean(const Json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, std::string("expected true or false, found ") + kind(v));
    return v.get<bool>();
  }

  std::string string(const Json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, std::string("expected a string, found ") + kind(v));
    return v.get<std::string>();
  }

  const Json& array(const Json& v, const std::string& path) const {
    if (!v.is_array()) fail(path, std::string("expected an array, found ") + kind(v));
    return v;
  }

  Vec3 vec3(const Json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3)
      fail(path, "expected an array of 3 numbers, found " + shape(v));
    return {number(v[0], item(path, 0)), number(v[1], item(path, 1)), number(v[2], item(path, 2))};
  }

  /// A position: a vector within ±kMaxCoordinate (coordinate_range.h).
  Vec3 point(const Json& v, const std::string& path) const {
    const Vec3 p = vec3(v, path);
    if (!within_coordinate_range(p)) fail(path, out_of_range(p));
    return p;
  }

  /// A direction: a nonzero vector that normalizes in doubles.
  Vec3 direction(const Json& v, const std::string& path) const {
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

  Rgb rgb(const Json& v, const std::string& path) const {
    const Vec3 c = vec3(v, path);
    for (int i = 0; i < 3; ++i) {
      if (c[i] < 0) fail(item(path, static_cast<std::size_t>(i)), "must be >= 0");
    }
    return {c.x, c.y, c.z};
  }

  const std::filesystem::path& file() const { return file_; }

 private:
  static const char* kind(const Json& v) {
    if (v.is_number_integer()) return "an integer";
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
  }
  static std::string shape(const Json& v) {
    if (v.is_array()) return "an array of " + std::to_string(v.size());
    return kind(v);
  }

  std::filesystem::path file_;
  std::string name_;
};

}  // namespace umbra::geometry::json
