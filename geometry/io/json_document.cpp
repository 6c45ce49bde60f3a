#include <umbra/geometry/io/json_depth.h>
#include <umbra/geometry/io/json_document.h>
#include <umbra/geometry/io/located_json.h>
#include <umbra/util/input_error.h>

namespace umbra::geometry::json {

Document::Document(std::string_view text, const std::string& file) {
  // simdjson reads past the end in 64-byte blocks: `true` lets it copy the
  // text into a padded buffer of its own (a memcpy, ~1 % of the parse).
  const simdjson::error_code error = parser_.parse(text.data(), text.size(), true).get(root_);
  if (!error) return;
  if (error == simdjson::DEPTH_ERROR) {
    throw util::InputError(file,
                           "JSON nesting too deep: " + std::to_string(json_nesting_depth(text)) +
                               " levels; umbra reads scene files of at most " +
                               std::to_string(kMaxSceneNesting));
  }
  // Say where: the located pass throws for every error simdjson finds in
  // valid-looking text (syntax, UTF-8, 1e999, integers beyond 64 bits).
  parse_located(text, file);
  throw util::InputError(file, std::string("malformed JSON: ") + simdjson::error_message(error));
}

}  // namespace umbra::geometry::json
