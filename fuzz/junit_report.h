#pragma once
// A fuzz summary (fuzz/check_run.h, fuzz/sweep_report.h, or a merge of
// them) as a JUnit XML report for CI dashboards: one <testsuite> with one
// <testcase> per scene, named as the scene is (`s<seed>-<i>` for `fuzz
// check`, `<mesh file>-s<seed>-<i>` for `fuzz real`, classname
// `fuzz.check` or `fuzz.real.<mesh file>`). A scene whose render differs
// from the oracle (or whose volumes do not close) holds a <failure>; a
// refused scene (the render stopped on an internal check) holds an
// <error>: it is a failure of the run too (exit 1), but not an answer to
// compare. Both carry the scene's one-line verdict as `message` and its
// recipe, failing lights and features as text. The testsuite counts tests,
// failures and errors; its `time` is the summary's seconds (no per-scene
// times: a merged report is then the one-process report but for `time`).
#include <nlohmann/json.hpp>

#include <string>

namespace umbra::fuzz {

/// The report of `summary` (a document parse_summary accepts).
std::string junit_xml(const nlohmann::ordered_json& summary);

}  // namespace umbra::fuzz
