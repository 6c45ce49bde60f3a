#pragma once
// The times of a sharded sun series' parts as `umbra merge` reads them
// (csv_parts, geojson_parts): given in shard order, times never go back
// within a part, and each part starts after the previous one ended. ISO
// 8601 texts in one offset (a series labels every step in START's) sort as
// text.
#include <umbra/util/input_error.h>

#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace umbra::cli {

class PartTimes {
 public:
  /// `items` names what carries the times in messages ("rows", "features").
  explicit PartTimes(std::string_view items) : items_(items) {}

  /// The next part begins: its first time must be after the last one seen.
  void start_part() { part_start_ = true; }

  /// The next time of the current part, `part`; throws util::InputError
  /// naming it when the time breaks the order (parts out of order or given
  /// twice).
  void next(std::string_view time, const std::filesystem::path& part) {
    if (part_start_ ? !last_.empty() && time <= last_ : time < last_)
      throw util::InputError(part.string(),
                             fmt::format("time {} is not after {}, the previous {}': give the "
                                         "parts in shard order, each once",
                                         time, last_, items_));
    last_ = time;
    part_start_ = false;
  }

 private:
  std::string items_;
  std::string last_;
  bool part_start_ = true;
};

}  // namespace umbra::cli
