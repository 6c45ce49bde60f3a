#pragma once
// JSON text parsed with every error located (docs/scene-format.md): syntax
// errors by line and column, numbers that overflow a double (1e999) or that
// are integers beyond 64 bits, and duplicated keys by their field path
// ("lights[1].position"). nlohmann-json's SAX interface builds the document
// as its own parser would, with the path kept on the side. Scenes are read
// by simdjson (json_document.h), which says only that something is wrong;
// this slower pass then says where. Internal to geometry/io.
#include <umbra/geometry/io/json_path.h>

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace umbra::geometry::json {

using Json = nlohmann::json;

/// The document in `text`; throws InputError naming `file` and the line and
/// column (syntax) or the field path (overflow, a too large integer,
/// duplicate key).
Json parse_located(std::string_view text, const std::string& file);

}  // namespace umbra::geometry::json
