#include <umbra/geometry/export/csv_text.h>
#include <umbra/geometry/export/indexed_faces.h>
#include <umbra/geometry/export/mesh_text.h>
#include <umbra/geometry/export/sun_series_export.h>

#include <fmt/format.h>

#include <array>
#include <map>
#include <stdexcept>

namespace umbra::geometry {

std::string sun_series_csv_header(const Scene& scene) {
  return std::string(
             "time,zenith_deg,azimuth_deg,model,model_name,polygon,facing,area,lit_area,"
             "shadowed_area,sunlit_fraction") +
         (names_polygons(scene.models) ? ",polygon_name\n" : "\n");
}

void append_sun_series_csv(std::string& out, const SunStep& step, const Footprints& footprint,
                           const Scene& scene) {
  std::string prefix = step.text + ',';
  append_double(prefix, step.light.sun->zenith_deg);
  prefix += ',';
  append_double(prefix, step.light.sun->azimuth_deg);
  const bool named = names_polygons(scene.models);
  for (const ReceiverSummary& r : footprint.receivers) {
    out += prefix;
    out += ',' + std::to_string(r.model) + ',' + csv_field(scene.models[r.model].name) + ',' +
           std::to_string(r.polygon) + ',' + std::to_string(r.facing);
    for (double v : {r.area, r.lit_area, r.shadowed_area, r.sunlit_fraction}) {
      out += ',';
      append_double(out, v);
    }
    if (named) out += ',' + csv_field(polygon_name(scene.models[r.model], r.polygon));
    out += '\n';
  }
}

std::vector<ScheduleColumn> schedule_columns(const Scene& scene,
                                             std::span<const std::uint32_t> receivers) {
  std::vector<ScheduleColumn> columns;
  std::map<std::string, std::size_t> seen;
  for (std::uint32_t m : receivers) {
    const Model& model = scene.models[m];
    if (model.name.empty() || model.name.find_first_of(",\"\r\n") != std::string::npos)
      throw std::invalid_argument(fmt::format(
          "--schedule: model {} is named '{}', which an EnergyPlus surface name cannot be (empty, "
          "or a comma, quote or line break in it)",
          m, model.name));
    for (std::uint32_t p = 0; p < model.polygons.size(); ++p) {
      ScheduleColumn c{
          m, p, model.polygons.size() == 1 ? model.name : fmt::format("{}:{}", model.name, p)};
      // A CityJSON surface's type says which surface it is ("b1:3:WallSurface").
      if (const std::string& name = polygon_name(model, p); !name.empty()) {
        if (name.find_first_of(",\"\r\n") != std::string::npos)
          throw std::invalid_argument(fmt::format(
              "--schedule: polygon {} of model {} is named '{}', which an EnergyPlus surface "
              "name cannot hold (a comma, quote or line break)",
              p, m, name));
        c.name += ':' + name;
      }
      const auto [it, added] = seen.emplace(c.name, columns.size());
      if (!added)
        throw std::invalid_argument(fmt::format(
            "--schedule: two columns would be named '{}' (models {} and {}); give the models "
            "distinct names",
            c.name, columns[it->second].model, m));
      columns.push_back(std::move(c));
    }
  }
  return columns;
}

std::string energyplus_schedule_header(std::span<const ScheduleColumn> columns) {
  std::string out = "Surface Name";
  for (const ScheduleColumn& c : columns) out += ',' + c.name;
  return out + '\n';
}

void append_energyplus_row(std::string& out, const SunStep& step,
                           std::span<const double> fractions) {
  out += fmt::format("{:02}/{:02} {:02}:{:02}", step.time.month, step.time.day, step.time.hour,
                     step.time.minute);
  for (double f : fractions) {
    out += ',';
    append_double(out, f);
  }
  out += '\n';
}

std::string sun_hours_ply(const SunHours& hours) {
  const IndexedFaces indexed = index_faces(
      hours.regions.size(),
      [&](std::size_t i) { return std::span<const Vec3>(hours.regions[i].vertices); },
      "sun_hours_ply: region");
  std::vector<FaceAttribute> ints{
      {"model", {}}, {"polygon", {}}, {"triangle", {}}, {"lit_steps", {}}, {"lit_runs", {}}};
  std::vector<FaceReal> reals{{"sun_hours", {}}};
  for (const SunHoursRegion& r : hours.regions) {
    ints[0].values.push_back(static_cast<std::int32_t>(r.model));
    ints[1].values.push_back(static_cast<std::int32_t>(r.polygon));
    ints[2].values.push_back(r.triangle);
    ints[3].values.push_back(static_cast<std::int32_t>(r.lit_steps));
    ints[4].values.push_back(static_cast<std::int32_t>(r.lit_runs));
    reals[0].values.push_back(r.sun_hours);
  }
  const std::array<std::string, 2> comments{
      "umbra sun hours: one face per region of a receiver lit by the same steps of a series",
      fmt::format("{} steps of {} s, {} with the sun up; sun_hours = lit_steps x step; the true "
                  "hours lie within lit_runs steps of it",
                  hours.steps, hours.step_seconds, hours.daylight_steps)};
  return ply_bytes(indexed, comments, ints, reals);
}

}  // namespace umbra::geometry
