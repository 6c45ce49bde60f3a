// CityJSON as umbra's surfaces (cityjson_reader.h; docs/scene-format.md,
// "CityJSON models"). The file is untrusted: it is parsed by simdjson
// (json_document.h: nesting and malformed text refused with a location),
// and every value read is checked once, here, through json_fields.h so that
// a refusal names the file and the value's JSON path. Only what umbra uses
// is read: unknown members (metadata, appearance, extensions "+...") are
// ignored, as CityJSON asks of readers.
#include <umbra/geometry/export/polygon_triangulation.h>
#include <umbra/geometry/io/cityjson_reader.h>
#include <umbra/geometry/io/json_fields.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace umbra::geometry {
namespace {

using json::Array;
using json::child;
using json::Element;
using json::Fields;
using json::item;

/// The largest integer coordinate read: every integer up to 2^53 in
/// magnitude is a double exactly, so v·scale + translate rounds only twice.
constexpr std::int64_t kMaxIntegerCoordinate = std::int64_t{1} << 53;

/// The file's vertices: as written (the integers, or the numbers of a file
/// without a transform), and in world coordinates.
struct Vertices {
  std::vector<Vec3> file;
  std::vector<Vec3> world;
};

/// "CityObjects.b12", or CityObjects["NL.IMBAG.Pand.1"] for an id that a
/// dotted path would misread.
std::string object_path(std::string_view id) {
  if (!id.empty() && id.find_first_of(".[]\"\\") == std::string_view::npos)
    return child("CityObjects", id);
  std::string quoted;
  for (const char c : id) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return "CityObjects[\"" + quoted + "\"]";
}

/// The world point of integer vertex `k`: each coordinate k·scale +
/// translate, a product and a sum each rounded once in doubles (no fused
/// multiply-add: -ffp-contract=off).
Vec3 to_world(const std::array<std::int64_t, 3>& k, const Vec3& scale, const Vec3& translate) {
  return {static_cast<double>(k[0]) * scale.x + translate.x,
          static_cast<double>(k[1]) * scale.y + translate.y,
          static_cast<double>(k[2]) * scale.z + translate.z};
}

Vertices read_vertices(const Fields& in, Element root) {
  std::optional<Vec3> scale, translate;
  if (const std::optional<Element> transform = Fields::find(root, "transform")) {
    in.expect_object(*transform, "transform");
    scale = in.vec3(in.required(*transform, "scale", "transform"), "transform.scale");
    for (std::size_t c = 0; c < 3; ++c)
      if (!((*scale)[static_cast<int>(c)] > 0)) in.fail(item("transform.scale", c), "must be > 0");
    translate = in.vec3(in.required(*transform, "translate", "transform"), "transform.translate");
  }
  const Array list = in.array(in.required(root, "vertices", ""), "vertices");
  Vertices v;
  v.file.reserve(list.size());
  v.world.reserve(list.size());
  for (const Element vertex : list) {
    const std::size_t index = v.file.size();
    const auto at = [&] { return item("vertices", index); };
    if (!scale) {
      const std::optional<Vec3> p = Fields::try_vec3(vertex);
      v.file.push_back(p ? *p : in.vec3(vertex, at()));
      v.world.push_back(v.file.back());
    } else {
      std::array<std::int64_t, 3> k{};
      Array a;
      std::size_t c = 0;
      if (vertex.get_array().get(a) || a.size() != 3)
        in.fail(at(), "expected an array of 3 integers (the file has a transform)");
      for (const Element e : a) {
        if (e.get_int64().get(k[c]) || k[c] < -kMaxIntegerCoordinate ||
            k[c] > kMaxIntegerCoordinate) {
          if (!e.is_int64() && !e.is_uint64())
            in.fail(item(at(), c), "expected an integer (the file has a transform)");
          in.fail(item(at(), c), "is beyond ±2^53, where integers stop being exact doubles");
        }
        ++c;
      }
      v.file.push_back(
          Vec3{static_cast<double>(k[0]), static_cast<double>(k[1]), static_cast<double>(k[2])});
      v.world.push_back(to_world(k, *scale, *translate));
      const Vec3& w = v.world.back();
      if (!is_finite(w))
        in.fail(at(), fmt::format("({}, {}, {}) · transform.scale + transform.translate "
                                  "overflows a double",
                                  k[0], k[1], k[2]));
    }
    if (!within_coordinate_range(v.world.back()))
      in.fail(at(), Fields::out_of_range(v.world.back()));
  }
  return v;
}

/// A geometry's `semantics.surfaces` types (the names of its surfaces).
std::vector<std::string> read_semantic_types(const Fields& in, Element semantics,
                                             const std::string& path) {
  in.expect_object(semantics, path);
  const std::string list_path = child(path, "surfaces");
  std::vector<std::string> types;
  for (const Element surface : in.array(in.required(semantics, "surfaces", path), list_path)) {
    const std::string at = item(list_path, types.size());
    in.expect_object(surface, at);
    types.push_back(in.string(in.required(surface, "type", at), child(at, "type")));
  }
  return types;
}

/// Levels of arrays above the surfaces in a geometry's `boundaries` (and in
/// its semantics `values`): 1 for a MultiSurface or CompositeSurface
/// ([surface]), 2 for a Solid ([shell][surface]), 3 for a MultiSolid or
/// CompositeSolid ([solid][shell][surface]); 0 for the types umbra skips;
/// -1 for an unknown type.
int surface_levels(std::string_view type) {
  if (type == "MultiSurface" || type == "CompositeSurface") return 1;
  if (type == "Solid") return 2;
  if (type == "MultiSolid" || type == "CompositeSolid") return 3;
  if (type == "GeometryInstance" || type == "MultiPoint" || type == "MultiLineString") return 0;
  return -1;
}

/// One CityObject's chosen geometry turned into polygons.
class SurfaceReader {
 public:
  SurfaceReader(const Fields& in, const Vertices& vertices, CityObjectSurfaces& out)
      : in_(in), vertices_(vertices), out_(out) {}

  void read_geometry(Element geometry, int levels, const std::string& path) {
    const std::optional<Element> semantics = Fields::find(geometry, "semantics");
    std::optional<Element> values;
    if (semantics) {
      const std::string semantics_path = child(path, "semantics");
      types_ = read_semantic_types(in_, *semantics, semantics_path);
      values = in_.required(*semantics, "values", semantics_path);
    }
    read_level(in_.required(geometry, "boundaries", path), values, levels,
               child(path, "boundaries"), child(child(path, "semantics"), "values"));
  }

 private:
  /// `boundaries` `levels` levels above the surfaces; `values` the
  /// semantics values of the same level (absent or null: no semantics for
  /// any surface below).
  void read_level(Element boundaries, std::optional<Element> values, int levels,
                  const std::string& path, const std::string& values_path) {
    const Array list = in_.array(boundaries, path);
    Array value_list;
    const bool has_values = values && !values->is_null();
    if (has_values) {
      value_list = in_.array(*values, values_path);
      if (value_list.size() != list.size())
        in_.fail(values_path,
                 fmt::format("has {} entries for the {} of {} ({} {})", value_list.size(),
                             levels == 1   ? "surfaces"
                             : levels == 2 ? "shells"
                                           : "solids",
                             path, list.size(), levels == 1 ? "surfaces" : "elements"));
    }
    auto value = value_list.begin();
    std::size_t i = 0;
    for (const Element element : list) {
      std::optional<Element> element_value;
      if (has_values) {
        element_value = *value;
        ++value;
      }
      if (levels > 1) {
        read_level(element, element_value, levels - 1, item(path, i), item(values_path, i));
      } else {
        read_surface(element, item(path, i), name_of(element_value, values_path, i));
      }
      ++i;
    }
  }

  /// The semantic type a surface's value names ("" for none or null).
  std::string name_of(std::optional<Element> value, const std::string& values_path,
                      std::size_t i) const {
    if (!value || value->is_null()) return "";
    std::int64_t k = -1;
    if (value->get_int64().get(k) || k < 0 || static_cast<std::uint64_t>(k) >= types_.size())
      in_.fail(item(values_path, i),
               fmt::format("expected null or an index into semantics.surfaces ({} entries)",
                           types_.size()));
    return types_[static_cast<std::size_t>(k)];
  }

  void read_surface(Element surface, const std::string& path, const std::string& name) {
    const Array rings = in_.array(surface, path);
    if (rings.size() == 0) in_.fail(path, "a surface needs at least its outer ring");
    std::vector<std::vector<std::uint32_t>> indices;
    for (const Element ring : rings) {
      const std::string ring_path = item(path, indices.size());
      const Array list = in_.array(ring, ring_path);
      if (list.size() < 3)
        in_.fail(ring_path,
                 fmt::format("ring has {} vertices; at least 3 are needed", list.size()));
      if (list.size() > kMaxPolygonVertices) in_.fail(ring_path, polygon_too_large(list.size()));
      indices.emplace_back();
      for (const Element index : list) {
        std::int64_t k = -1;
        if (index.get_int64().get(k) || k < 0 ||
            static_cast<std::uint64_t>(k) >= vertices_.world.size()) {
          const std::string at = item(ring_path, indices.back().size());
          in_.fail(at, "vertex index " + in_.index_text(index, at) + " out of range (file has " +
                           std::to_string(vertices_.world.size()) + " vertices)");
        }
        indices.back().push_back(static_cast<std::uint32_t>(k));
      }
    }
    if (indices.size() == 1) {
      add_polygon(indices[0], name);
      return;
    }
    // Inner rings: umbra's polygons have none, so the surface becomes
    // triangles, decided on the file's own coordinates (exact integers when
    // the file has a transform, whose positive scale keeps every orientation).
    std::vector<std::vector<Vec3>> points;
    std::vector<std::uint32_t> flat;
    for (const std::vector<std::uint32_t>& ring : indices) {
      points.emplace_back();
      for (const std::uint32_t k : ring) {
        points.back().push_back(vertices_.file[k]);
        flat.push_back(k);
      }
    }
    const auto triangles = detail::triangulate_rings(points);
    if (!triangles)
      in_.fail(path,
               "its rings cross each other (seen along the outer ring's normal): not a valid "
               "surface with holes");
    if (triangles->empty()) {  // no area: kept as degenerate geometry is
      add_polygon(indices[0], name);
      return;
    }
    for (const std::array<std::uint32_t, 3>& t : *triangles)
      add_polygon({flat[t[0]], flat[t[1]], flat[t[2]]}, name);
  }

  void add_polygon(const std::vector<std::uint32_t>& file_indices, const std::string& name) {
    Polygon polygon;
    polygon.reserve(file_indices.size());
    for (const std::uint32_t k : file_indices) {
      const auto [it, added] =
          local_.emplace(k, static_cast<std::uint32_t>(out_.soup.vertices.size()));
      if (added) out_.soup.vertices.push_back(vertices_.world[k]);
      polygon.push_back(it->second);
    }
    out_.soup.polygons.push_back(std::move(polygon));
    out_.polygon_names.push_back(name);
  }

  const Fields& in_;
  const Vertices& vertices_;
  CityObjectSurfaces& out_;
  std::vector<std::string> types_;
  std::unordered_map<std::uint32_t, std::uint32_t> local_;  ///< file index -> the object's
};

/// A surface geometry of a CityObject: where it is and what it holds.
struct Candidate {
  Element geometry;
  std::string path;
  std::string lod;
  int levels = 0;
};

/// A geometry's `lod`: a string (1.1, 2.0) or a number (1.0) written as a
/// LoD ("2", "2.2").
std::string read_lod(const Fields& in, Element geometry, const std::string& path) {
  const std::string at = child(path, "lod");
  const Element v = in.required(geometry, "lod", path);
  std::string text;
  if (v.is_string()) {
    text = std::string(json::as_string(v));
  } else if (v.is_int64() || v.is_uint64() || v.is_double()) {
    text = fmt::format("{}", in.number(v, at));
  }
  if (!is_lod_text(text))
    in.fail(at, "expected a level of detail such as \"2.2\" (digits, a point, digits)");
  return text;
}

std::vector<Candidate> surface_geometries(const Fields& in, Element object,
                                          const std::string& path) {
  std::vector<Candidate> out;
  const std::optional<Element> geometries = Fields::find(object, "geometry");
  if (!geometries) return out;
  const std::string list_path = child(path, "geometry");
  std::size_t g = 0;
  for (const Element geometry : in.array(*geometries, list_path)) {
    const std::string at = item(list_path, g++);
    in.expect_object(geometry, at);
    const std::string type = in.string(in.required(geometry, "type", at), child(at, "type"));
    const int levels = surface_levels(type);
    if (levels < 0)
      in.fail(child(at, "type"),
              "unknown geometry type '" + type +
                  "'; expected MultiSurface, CompositeSurface, Solid, MultiSolid or "
                  "CompositeSolid (MultiPoint, MultiLineString and GeometryInstance are skipped)");
    if (levels == 0) continue;
    out.push_back({geometry, at, read_lod(in, geometry, at), levels});
  }
  return out;
}

/// The geometry umbra reads of an object: see parse_cityjson.
const Candidate* choose(const std::vector<Candidate>& candidates,
                        const std::optional<std::string>& lod) {
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates) {
    if (lod) {
      if (compare_lods(c.lod, *lod) == 0) return &c;
    } else if (!best || compare_lods(c.lod, best->lod) > 0) {
      best = &c;
    }
  }
  return best;
}

void check_header(const Fields& in, Element root) {
  if (!root.is_object()) in.fail("", "a CityJSON file must be a JSON object");
  const std::string type = in.string(in.required(root, "type", ""), "type");
  if (type != "CityJSON")
    in.fail("type", "is '" + type +
                        "'; expected 'CityJSON' (CityJSONFeature streams, .jsonl, are not read)");
  const std::string version = in.string(in.required(root, "version", ""), "version");
  if (version != "1.0" && version != "1.1" && version != "2.0")
    in.fail("version", "CityJSON version '" + version + "' is not read; expected 1.0, 1.1 or 2.0");
}

}  // namespace

bool is_lod_text(std::string_view lod) {
  const std::size_t point = lod.find('.');
  const std::string_view whole = lod.substr(0, point);
  const std::string_view fraction =
      point == std::string_view::npos ? std::string_view("0") : lod.substr(point + 1);
  const auto digits = [](std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
  };
  return digits(whole) && digits(fraction);
}

int compare_lods(std::string_view a, std::string_view b) {
  const auto split = [](std::string_view s) {
    const std::size_t point = s.find('.');
    std::string_view whole = s.substr(0, point);
    std::string_view fraction = point == std::string_view::npos ? "" : s.substr(point + 1);
    while (whole.size() > 1 && whole.front() == '0') whole.remove_prefix(1);
    while (!fraction.empty() && fraction.back() == '0') fraction.remove_suffix(1);
    return std::pair{whole, fraction};
  };
  const auto [aw, af] = split(a);
  const auto [bw, bf] = split(b);
  // Whole parts without leading zeros: the longer is larger, else the
  // digits decide; fractions without trailing zeros: the digits decide.
  if (aw.size() != bw.size()) return aw.size() < bw.size() ? -1 : 1;
  if (const int c = aw.compare(bw)) return c < 0 ? -1 : 1;
  if (const int c = af.compare(bf)) return c < 0 ? -1 : 1;
  return 0;
}

std::vector<CityObjectSurfaces> parse_cityjson(std::string_view text,
                                               const std::filesystem::path& file,
                                               const std::optional<std::string>& lod) {
  const json::Document document(text, file.string());
  const Element root = document.root();
  const Fields in(file);
  check_header(in, root);
  const Vertices vertices = read_vertices(in, root);
  const Element objects = in.required(root, "CityObjects", "");
  in.expect_object(objects, "CityObjects");

  std::vector<CityObjectSurfaces> out;
  std::unordered_set<std::string_view> ids;
  std::vector<std::string> lods_seen;
  for (const simdjson::dom::key_value_pair field : json::as_object(objects)) {
    const std::string path = object_path(field.key);
    if (!ids.insert(field.key).second)
      in.fail(path, "duplicate CityObject id '" + std::string(field.key) + "'");
    in.expect_object(field.value, path);
    const std::vector<Candidate> candidates = surface_geometries(in, field.value, path);
    for (const Candidate& c : candidates)
      if (lods_seen.size() < 8 &&
          std::find(lods_seen.begin(), lods_seen.end(), c.lod) == lods_seen.end())
        lods_seen.push_back(c.lod);
    const Candidate* chosen = choose(candidates, lod);
    if (!chosen) continue;
    CityObjectSurfaces object;
    object.id = std::string(field.key);
    SurfaceReader(in, vertices, object)
        .read_geometry(chosen->geometry, chosen->levels, chosen->path);
    if (!object.soup.polygons.empty()) out.push_back(std::move(object));
  }
  if (out.empty() && lod) {
    std::string seen;
    for (const std::string& l : lods_seen) seen += (seen.empty() ? "" : ", ") + l;
    in.fail("CityObjects", "no CityObject has a surface geometry of LoD " + *lod +
                               (seen.empty() ? " (the file has no surface geometry)"
                                             : " (the file's LoDs include " + seen + ")"));
  }
  if (out.empty())
    in.fail("CityObjects",
            "no CityObject has surface geometry (MultiSurface, CompositeSurface, Solid, "
            "MultiSolid or CompositeSolid): nothing to cast or receive shadows");
  return out;
}

std::vector<CityObjectSurfaces> read_cityjson(const std::filesystem::path& file,
                                              const std::optional<std::string>& lod) {
  return parse_cityjson(util::read_input_file(file, "CityJSON"), file, lod);
}

}  // namespace umbra::geometry
