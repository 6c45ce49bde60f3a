#pragma once
// `umbra sunlight SCENE --area NAME[,NAME...] --date YYYY-MM-DD [--utc-offset ±HH:MM]
//                [--step PT5M] [--hours 2] [--json FILE|-] [--threads N] [-v|-q]`:
// BRE 209's sunlight test on a named receiver (docs/sun.md "umbra sunlight").
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace umbra::cli {

struct SunlightArgs {
  std::string scene;
  std::vector<std::string> area;  ///< receiving models, by name
  std::string date;               ///< YYYY-MM-DD
  std::string utc_offset;  ///< ±HH:MM or Z; empty: the site's longitude / 15, in whole hours
  std::string step = "PT5M";
  double hours = 2;
  std::string json;  ///< empty: none; "-": stdout
  unsigned threads = 0;
  bool quiet = false;
  bool verbose = false;
};

CLI::App* add_sunlight_command(CLI::App& app, SunlightArgs& args);

/// Returns the exit code; throws util::InputError on bad input.
int run_sunlight(const SunlightArgs& args);

}  // namespace umbra::cli
