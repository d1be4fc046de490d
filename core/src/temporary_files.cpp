#include "koppel/core/temporary_files.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>
#include <unistd.h>

namespace koppel::io {
namespace {

// A slot is free, being filled, or holds a path the handler removes. Only lock-free atomics and
// a fixed buffer: the handler may run at any instruction of any thread.
enum SlotState : int { kFree = 0, kFilling = 1, kHeld = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxTemporaryPath] = {};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' states");

// constinit: zero-filled by the loader, no code at start-up (a dynamic initialiser wrote every
// slot's state, touching each slot's page: the largest initialiser of koppel's start, issue 25)
constinit Slot slots[kMaxTemporaryFiles];

extern "C" void RemoveAndReraise(int signal_number) {
  for (Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) == kHeld) ::unlink(slot.path);
  }
  // the default action once more, raised again: blocked while this handler runs, it ends the
  // process as soon as the handler returns, and the parent sees the signal
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void InstallUnlessIgnored(int signal_number) {
  struct sigaction old {};
  if (::sigaction(signal_number, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) return;
  struct sigaction action {};
  action.sa_handler = RemoveAndReraise;
  ::sigemptyset(&action.sa_mask);
  // the other two wait while one of them removes the files
  for (int other : {SIGINT, SIGTERM, SIGHUP}) ::sigaddset(&action.sa_mask, other);
  ::sigaction(signal_number, &action, nullptr);
}

}  // namespace

int RegisterTemporaryFile(const char* path) {
  const std::size_t length = std::strlen(path);
  if (length >= static_cast<std::size_t>(kMaxTemporaryPath)) return -1;
  for (int i = 0; i < kMaxTemporaryFiles; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) continue;
    std::memcpy(slots[i].path, path, length + 1);
    slots[i].state.store(kHeld, std::memory_order_release);
    return i;
  }
  return -1;
}

void ForgetTemporaryFile(int slot) {
  if (slot >= 0 && slot < kMaxTemporaryFiles) slots[slot].state.store(kFree, std::memory_order_release);
}

void RemoveTemporaryFilesOnSignals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) InstallUnlessIgnored(signal_number);
  });
}

}  // namespace koppel::io
