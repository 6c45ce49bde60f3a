#pragma once
// What the bad-input tests ask of a thrown InputError.
#include <umbra/util/input_error.h>

#include <gtest/gtest.h>

#include <string>

namespace umbra::geometry::test {

/// The message of the InputError `f` throws ("" and a failure if none).
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const util::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

inline ::testing::AssertionResult starts_with(const std::string& text, const std::string& prefix) {
  if (text.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not start with '" << prefix << "'";
}

}  // namespace umbra::geometry::test
