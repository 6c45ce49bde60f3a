#pragma once
// What every harness shares: the libFuzzer entry point's signature and a
// check that prints what failed and aborts (libFuzzer and the replay driver
// both report an abort as a crash, with the input that caused it).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace umbra::fuzz {

[[noreturn]] inline void fail(const char* harness, const std::string& what) {
  std::fprintf(stderr, "umbra fuzz %s: %s\n", harness, what.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace umbra::fuzz

/// Not `assert`: stays on in Release builds, where the replays run.
#define UMBRA_FUZZ_CHECK(harness, cond, what)                                           \
  do {                                                                                  \
    if (!(cond)) ::umbra::fuzz::fail(harness, std::string(#cond " failed: ") + (what)); \
  } while (0)
