#include <cli/csv_parts.h>
#include <cli/part_times.h>
#include <umbra/util/input_error.h>
#include <umbra/util/input_file.h>

#include <fmt/format.h>

#include <string_view>

namespace umbra::cli {

namespace fs = std::filesystem;

std::string join_csv_parts(const std::vector<fs::path>& parts) {
  std::string out, header;
  bool timed = false;
  PartTimes times("rows");
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string text = util::read_input_file(parts[k], "table part");
    const std::size_t eol = text.find('\n');
    if (eol == std::string::npos)
      throw util::InputError(parts[k].string(), "no header line: not a part of a table");
    const std::string_view first(text.data(), eol + 1);
    if (k == 0) {
      header = std::string(first);
      timed = header.rfind("time,", 0) == 0;
      out = header;
    } else if (first != header) {
      throw util::InputError(
          parts[k].string(),
          fmt::format("its header is not {}'s: parts of another table", parts[0].string()));
    }
    // A timed table's rows: the time is each row's first column.
    if (timed) {
      times.start_part();
      for (std::size_t pos = eol + 1; pos < text.size();) {
        const std::size_t end = text.find('\n', pos);
        const std::size_t comma = text.find(',', pos);
        times.next(std::string_view(text).substr(pos, comma - pos), parts[k]);
        if (end == std::string::npos) break;
        pos = end + 1;
      }
    }
    out.append(text, eol + 1, std::string::npos);
  }
  return out;
}

}  // namespace umbra::cli
