#pragma once
// JSON text parsed with every error located (docs/scene-format.md): syntax
// errors by line and column, numbers that overflow a double (1e999) and
// duplicated keys by their field path ("lights[1].position"). nlohmann-json's
// SAX interface builds the document as its own parser would, with the path
// kept on the side. Internal to geometry/io.
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace umbra::geometry::json {

using Json = nlohmann::json;

/// "path.key", or "key" at the root: a field's JSON path.
std::string child(const std::string& path, std::string_view key);

/// "path[index]": an array element's JSON path.
std::string item(const std::string& path, std::size_t index);

/// The document in `text`; throws InputError naming `file` and the line and
/// column (syntax) or the field path (overflow, duplicate key).
Json parse_located(std::string_view text, const std::string& file);

}  // namespace umbra::geometry::json
