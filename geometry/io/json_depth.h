#pragma once
// The nesting depth of JSON text, measured without parsing it: for parsers
// that recurse once per level (tinygltf overflows the stack at ~20,000
// levels, PLATFORM-NOTES.md), the depth must be known before they see it.
#include <cstddef>
#include <string_view>

namespace umbra::geometry {

/// The deepest nesting of `[`/`{` in `text`, counting brackets outside JSON
/// strings only (a `"` escaped by `\` inside a string does not end it).
/// Unbalanced or malformed text is measured as far as it goes; the parser
/// reports what is wrong with it. Linear time, constant memory.
std::size_t json_nesting_depth(std::string_view text);

}  // namespace umbra::geometry
