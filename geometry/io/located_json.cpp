#include <umbra/geometry/io/located_json.h>
#include <umbra/util/input_error.h>

#include <algorithm>
#include <set>
#include <vector>

namespace umbra::geometry::json {

std::string child(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

namespace {

// Builds the document like nlohmann's own DOM parser, and on the side keeps
// the path of the value being parsed, refuses duplicated keys, and turns parse
// errors into InputErrors with a line and column.
class LocatingSax {
 public:
  LocatingSax(Json& root, std::string_view text, const std::string& file)
      : dom_(root, true), text_(text), file_(file) {}

  bool null() { return value(dom_.null()); }
  bool boolean(bool v) { return value(dom_.boolean(v)); }
  bool number_integer(Json::number_integer_t v) { return value(dom_.number_integer(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return value(dom_.number_unsigned(v)); }
  bool number_float(Json::number_float_t v, const Json::string_t& s) {
    // An integer nlohmann could only keep as a double; simdjson refuses it,
    // and so does umbra, rather than read a different number than written.
    if (s.find_first_of(".eE") == std::string::npos) {
      const std::string field = path();
      throw util::InputError(field.empty() ? file_ : file_ + ": " + field,
                             "integer " + s +
                                 " does not fit in 64 bits; write it with a decimal point or an "
                                 "exponent if a rounded double is meant");
    }
    return value(dom_.number_float(v, s));
  }
  bool string(Json::string_t& v) { return value(dom_.string(v)); }
  bool binary(Json::binary_t& v) { return value(dom_.binary(v)); }
  bool start_object(std::size_t n) {
    frames_.push_back({true, {}, 0, {}});
    return dom_.start_object(n);
  }
  bool key(Json::string_t& k) {
    Frame& frame = frames_.back();
    frame.key = k;
    if (!frame.keys.insert(k).second) {
      throw util::InputError(file_ + ": " + path(), "duplicate field '" + k + "'");
    }
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return value(dom_.end_object());
  }
  bool start_array(std::size_t n) {
    frames_.push_back({false, {}, 0, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return value(dom_.end_array());
  }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& error) {
    // nlohmann's position counts the characters read, the offending one
    // included: the error is at 0-based offset position - 1.
    const std::size_t offset = std::min(position == 0 ? 0 : position - 1, text_.size());
    const std::size_t line =
        1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + offset, '\n'));
    const std::size_t line_start =
        text_.rfind('\n', offset == 0 ? std::string_view::npos : offset - 1);
    const std::size_t column =
        offset - (line_start == std::string_view::npos ? 0 : line_start + 1) + 1;
    const std::string at = "line " + std::to_string(line) + ", column " + std::to_string(column);
    if (error.id == 406) {  // number overflow: the value would be infinite
      const std::string field = path();
      throw util::InputError(field.empty() ? file_ : file_ + ": " + field,
                             "number " + last_token + " is not a finite double (" + at + ")");
    }
    // Keep nlohmann's explanation, without its "[json.exception...] parse error at ...:" prefix.
    std::string what = error.what();
    if (const auto syntax = what.find("syntax error"); syntax != std::string::npos) {
      what = what.substr(syntax);
    } else if (const auto bracket = what.find("] "); bracket != std::string::npos) {
      what = what.substr(bracket + 2);
    }
    throw util::InputError(file_ + ":" + std::to_string(line) + ":" + std::to_string(column),
                           "malformed JSON: " + what);
  }

 private:
  struct Frame {
    bool object;
    std::string key;
    std::size_t index;
    std::set<std::string> keys;
  };
  bool value(bool ok) {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return ok;
  }
  std::string path() const {
    std::string out;
    for (const Frame& frame : frames_)
      out = frame.object ? child(out, frame.key) : item(out, frame.index);
    return out;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::string_view text_;
  const std::string& file_;
  std::vector<Frame> frames_;
};

}  // namespace

Json parse_located(std::string_view text, const std::string& file) {
  Json root;
  LocatingSax sax(root, text, file);
  Json::sax_parse(text, &sax);
  return root;
}

}  // namespace umbra::geometry::json
