#pragma once
// CSV fields as RFC 4180 writes them: what the footprint and sun-series
// tables share.
#include <string>

namespace umbra::geometry {

/// `s` as one CSV field: quoted when it holds a comma, a quote or a line
/// break, its quotes doubled.
inline std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace umbra::geometry
