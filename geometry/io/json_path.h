#pragma once
// A JSON field's path as messages name it: "lights[1].position". Internal to
// geometry/io (located_json.cpp defines these).
#include <cstddef>
#include <string>
#include <string_view>

namespace umbra::geometry::json {

/// "path.key", or "key" at the root: a field's JSON path.
std::string child(const std::string& path, std::string_view key);

/// "path[index]": an array element's JSON path.
std::string item(const std::string& path, std::size_t index);

}  // namespace umbra::geometry::json
