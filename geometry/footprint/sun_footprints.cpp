#include <umbra/geometry/footprint/footprint_tables.h>
#include <umbra/geometry/footprint/light_query.h>
#include <umbra/geometry/footprint/sun_footprints.h>
#include <umbra/geometry/oracle/shadow_oracle.h>
#include <umbra/util/parallel_for.h>

#include <algorithm>
#include <bit>
#include <map>

namespace umbra::geometry {

using namespace detail;

namespace {

/// Lights whose volumes are built together: enough to keep both threads
/// busy, few enough that their volumes' polygons never pile up (a day at
/// ten minutes is ~80 steps; only each light's side edges are kept).
constexpr std::size_t kLightsPerBatch = 32;

/// The lit steps of a point as bits over the series' daylight steps.
using StepBits = std::vector<std::uint64_t>;

struct DaylightSteps {
  std::vector<std::size_t> index;  ///< each daylight step's index in the series
  std::vector<HPoint> light;       ///< its sun as a homogeneous point
  std::vector<LightSides> sides;
};

struct ReceiverHours {
  std::vector<SunHoursRegion> regions;
  std::uint64_t segments = 0, faces = 0;
};

/// Runs of consecutive lit steps in `bits`: a run breaks at an unlit
/// daylight step and at every night between two daylight steps.
std::uint32_t lit_runs(const StepBits& bits, const std::vector<std::size_t>& index) {
  std::uint32_t runs = 0;
  bool previous = false;
  for (std::size_t i = 0; i < index.size(); ++i) {
    const bool lit = (bits[i / 64] >> (i % 64)) & 1u;
    const bool continues = previous && index[i] == index[i - 1] + 1;
    if (lit && !continues) ++runs;
    previous = lit;
  }
  return runs;
}

ReceiverHours hours_of(const FootprintTables& t, const DaylightSteps& day, double step_seconds,
                       std::uint32_t model_index, std::uint32_t polygon_index) {
  const Model& model = t.scene.models[model_index];
  ReceiverHours out;
  std::vector<std::uint32_t> scratch;
  const std::size_t n = day.light.size();
  for (const ReceiverUnit& unit : receiver_units(model, model.polygons[polygon_index],
                                                 t.tables[model_index].surfaces[polygon_index])) {
    const UnitFrame frame = unit_frame(unit);
    // The steps whose sun is on the piece's front: only they can light it.
    std::vector<std::size_t> facing;
    std::vector<Segment2> segments;
    for (std::size_t s = 0; s < n; ++s) {
      if (frame.plane.side(day.light[s]) <= 0) continue;
      facing.push_back(s);
      add_light_segments(frame, day.sides[s], day.light[s], segments, scratch);
    }
    if (!facing.empty()) add_piercing_segments(frame, *t.index, segments, scratch);
    out.segments += segments.size();

    // Key k ≥ 1 stands for patterns[k - 1] (key 0 would read as "lit").
    std::vector<StepBits> patterns;
    std::map<StepBits, int> keys;
    std::vector<std::uint32_t> query_scratch;
    const Classifier classify = [&](const Point2& p) -> std::optional<int> {
      StepBits bits((n + 63) / 64, 0);
      const Point3 x = frame.plane.lift(p);
      for (std::size_t s : facing) {
        const std::optional<bool> shadowed =
            shadowed_from_light(*t.index, x, day.light[s], query_scratch);
        if (!shadowed) return std::nullopt;
        if (!*shadowed) bits[s / 64] |= std::uint64_t{1} << (s % 64);
      }
      const auto [it, added] = keys.emplace(bits, static_cast<int>(patterns.size()) + 1);
      if (added) patterns.push_back(bits);
      return it->second;
    };
    PartitionCounts counts;
    std::vector<PartitionRegion> parts =
        partition_receiver(frame.outline, segments, classify, counts);
    canonical_order(parts);
    out.faces += counts.classified_faces;
    const FT scale2 = frame.plane.area_scale_squared();
    for (const PartitionRegion& part : parts) {
      const StepBits& bits = patterns[static_cast<std::size_t>(part.key - 1)];
      SunHoursRegion r;
      r.model = model_index;
      r.polygon = polygon_index;
      r.triangle = unit.triangle;
      r.vertices = rounded_ring(frame.plane, part.ring);
      r.area = nearest_sqrt(part.area * part.area * scale2);
      for (std::uint64_t word : bits)
        r.lit_steps += static_cast<std::uint32_t>(std::popcount(word));
      r.lit_runs = lit_runs(bits, day.index);
      r.sun_hours = r.lit_steps * step_seconds / 3600.0;
      out.regions.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace

SunlightAreas sunlight_areas(const SunHours& sun_hours, double hours) {
  SunlightAreas out;
  const double need = hours * 3600.0;  // seconds; steps are whole seconds in practice
  for (const SunHoursRegion& r : sun_hours.regions) {
    const double n = r.lit_steps, runs = r.lit_runs, step = sun_hours.step_seconds;
    out.area += r.area;
    if (n * step >= need) out.counted += r.area;
    if ((n - runs) * step >= need) out.surely += r.area;
    if ((n + runs) * step > need) out.possibly += r.area;
  }
  return out;
}

SunFootprints::SunFootprints(const Scene& scene, const FootprintOptions& options)
    : threads_(options.threads) {
  // The scene's own lights are never used: every call sets its suns.
  tables_ = std::make_unique<FootprintTables>(scene, receiving_models(scene, options), false,
                                              options.threads);
}

SunFootprints::~SunFootprints() = default;

std::span<const std::uint32_t> SunFootprints::receivers() const { return tables_->receivers; }

Footprints SunFootprints::at(const Light& sun) {
  // One sun alone keeps footprints_of's statistics, which at_each's split
  // does not carry per sun.
  if (sun.dark) return {};
  tables_->scene.lights = {sun};
  const std::uint32_t only = 0;
  return footprints_of(*tables_, {&only, 1});
}

std::vector<Footprints> SunFootprints::at_each(std::span<const Light> suns) {
  std::vector<Footprints> out(suns.size());
  std::vector<std::uint32_t> lit;  // indices of the suns above the horizon
  tables_->scene.lights.clear();
  for (std::uint32_t i = 0; i < suns.size(); ++i) {
    if (suns[i].dark) continue;
    lit.push_back(static_cast<std::uint32_t>(tables_->scene.lights.size()));
    tables_->scene.lights.push_back(suns[i]);
  }
  if (lit.empty()) return out;
  Footprints all = footprints_of(*tables_, lit);
  // Split by light; each sun is light 0 of its own footprint, as at() has it.
  std::vector<std::size_t> slot;
  for (std::size_t i = 0; i < suns.size(); ++i)
    if (!suns[i].dark) slot.push_back(i);
  for (FootprintRegion& r : all.regions) {
    Footprints& f = out[slot[r.light]];
    f.stats.vertices += r.vertices.size();
    r.light = 0;
    f.regions.push_back(std::move(r));
  }
  for (ReceiverSummary& r : all.receivers) {
    Footprints& f = out[slot[r.light]];
    r.light = 0;
    f.receivers.push_back(r);
  }
  for (Footprints& f : out) {
    f.transmittance = all.transmittance;
    f.stats.regions = f.regions.size();
  }
  return out;
}

SunHours SunFootprints::sun_hours(const SunSeries& series) {
  SunHours out;
  out.step_seconds = series.step_seconds;
  out.steps = series.steps.size();
  DaylightSteps day;
  for (std::size_t i = 0; i < series.steps.size(); ++i) {
    if (series.steps[i].light.dark) continue;
    day.index.push_back(i);
    day.light.push_back(light_point(series.steps[i].light));
  }
  out.daylight_steps = day.index.size();
  for (std::size_t first = 0; first < day.index.size(); first += kLightsPerBatch) {
    const std::size_t last = std::min(day.index.size(), first + kLightsPerBatch);
    tables_->scene.lights.clear();
    std::vector<std::uint32_t> ids;
    for (std::size_t s = first; s < last; ++s) {
      ids.push_back(static_cast<std::uint32_t>(s - first));
      tables_->scene.lights.push_back(series.steps[day.index[s]].light);
    }
    for (LightSides& sides : light_sides(*tables_, ids)) day.sides.push_back(std::move(sides));
  }

  struct Item {
    std::uint32_t model, polygon;
  };
  std::vector<Item> items;
  for (std::uint32_t m : tables_->receivers)
    for (std::uint32_t p = 0; p < tables_->scene.models[m].polygons.size(); ++p)
      items.push_back({m, p});
  std::vector<ReceiverHours> results(items.size());
  util::parallel_for(items.size(), threads_, [&](std::size_t i) {
    results[i] = hours_of(*tables_, day, series.step_seconds, items[i].model, items[i].polygon);
  });
  for (ReceiverHours& r : results) {
    out.boundary_segments += r.segments;
    out.classified_faces += r.faces;
    for (SunHoursRegion& region : r.regions) out.regions.push_back(std::move(region));
  }
  return out;
}

}  // namespace umbra::geometry
