#include <umbra/util/temporary_files.h>

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace umbra::util {

namespace {

constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;

// A slot is free (0), being filled or emptied (1), or holds a path the
// handler may unlink (2). The handler reads only slots in state 2; the
// path's bytes are written before the state becomes 2 (release) and read
// after it is seen (acquire), so it never sees half a path.
enum SlotState : int { kFree = 0, kBusy = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes];
};

std::array<Slot, kSlots> g_slots;
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (Slot& slot : g_slots)
    if (slot.state.load(std::memory_order_acquire) == kReady) ::unlink(slot.path);
  // Default action, then the same signal again: the process ends as that
  // signal would have ended it (the signal is blocked in the handler, so it
  // is delivered when the handler returns).
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_reraise;
  sigemptyset(&action.sa_mask);
  // While one signal's handler runs, the others wait: one cleanup at a time.
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, s);
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &action, nullptr);
}

TemporaryFileGuard::TemporaryFileGuard(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= kPathBytes) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kBusy, std::memory_order_acquire))
      continue;
    std::memcpy(g_slots[i].path, text.c_str(), text.size() + 1);
    g_slots[i].state.store(kReady, std::memory_order_release);
    slot_ = i;
    return;
  }
}

TemporaryFileGuard::~TemporaryFileGuard() {
  if (slot_ >= 0)
    g_slots[static_cast<std::size_t>(slot_)].state.store(kFree, std::memory_order_release);
}

}  // namespace umbra::util
