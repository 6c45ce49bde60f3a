// json_nesting_depth: brackets counted outside strings only (issue 17, row 2).
#include <umbra/geometry/io/json_depth.h>

#include <gtest/gtest.h>

#include <string>

namespace umbra::geometry {
namespace {

TEST(JsonDepth, CountsObjectsAndArrays) {
  EXPECT_EQ(json_nesting_depth(""), 0u);
  EXPECT_EQ(json_nesting_depth("1"), 0u);
  EXPECT_EQ(json_nesting_depth("{}"), 1u);
  EXPECT_EQ(json_nesting_depth(R"({"a": [1, {"b": [[]]}], "c": {}})"), 5u);
}

TEST(JsonDepth, IgnoresBracketsInsideStrings) {
  EXPECT_EQ(json_nesting_depth(R"({"[[[[": "{{{{"})"), 1u);
  // An escaped quote does not end the string; an escaped backslash does not
  // escape the quote after it.
  EXPECT_EQ(json_nesting_depth(R"(["\"[[[", "\\", [2]])"), 2u);
}

TEST(JsonDepth, MeasuresDeepTextInConstantStack) {
  const std::string deep = std::string(1000000, '[') + std::string(1000000, ']');
  EXPECT_EQ(json_nesting_depth(deep), 1000000u);
  // Unbalanced text is measured as far as it goes.
  EXPECT_EQ(json_nesting_depth("]]][["), 2u);
}

}  // namespace
}  // namespace umbra::geometry
