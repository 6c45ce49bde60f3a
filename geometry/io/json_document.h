#pragma once
// A scene file's JSON, parsed by simdjson (Debian's libsimdjson): a few
// instructions a byte where nlohmann-json's DOM took ~170 (issue 20, goal 6).
// simdjson's errors carry no position, so on any error the text is parsed a
// second time by located_json.h, which names the line and column or the
// field path. Internal to geometry/io.
#include <umbra/geometry/io/json_path.h>

#include <simdjson.h>

#include <string>
#include <string_view>

namespace umbra::geometry::json {

/// Scene JSON nested deeper than this is refused (simdjson's own limit).
inline constexpr std::size_t kMaxSceneNesting = simdjson::DEFAULT_MAX_DEPTH;

/// A parsed document and the parser that owns its memory; elements are
/// valid while it lives.
class Document {
 public:
  /// Parses `text`; throws InputError naming `file` and where it is wrong.
  Document(std::string_view text, const std::string& file);
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  simdjson::dom::element root() const { return root_; }

 private:
  simdjson::dom::parser parser_;
  simdjson::dom::element root_;
};

}  // namespace umbra::geometry::json
