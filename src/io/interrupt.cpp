#include "io/interrupt.hpp"

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include <signal.h>
#include <unistd.h>

namespace pita::io {

namespace {

// A slot is free, claimed (its owner is copying a path in or out: the handler
// leaves it alone) or ready (its path names a file the handler must remove).
enum SlotState : int { kFree = 0, kClaimed = 1, kReady = 2 };

// Lock-free, or the handler could wait on a lock the interrupted code holds.
static_assert(std::atomic<int>::is_always_lock_free);

struct Slot {
  std::atomic<int> state{kFree};
  char path[kInFlightPathMax] = {};
};

// Static storage: 256 KiB of zeros in .bss, nothing allocated.
std::array<Slot, kInFlightSlots> slots;

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

// write(2) of a NUL-terminated string, all of it (stderr may be a pipe).
void write_all(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;  // nothing better to do in a handler
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

// Deferred mode (DeferredInterrupts): the first signal is only recorded.
std::atomic<int> deferring{0};
std::atomic<int> pending{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_interrupt(int sig) {
  if (deferring.load() > 0) {
    int expected = 0;
    if (pending.compare_exchange_strong(expected, sig)) return;  // the owner cleans up and exits
  }
  const bool removed = remove_in_flight() > 0;
  write_all("pita: interrupted (");
  write_all(signal_name(sig));
  write_all(removed ? "); removed unfinished outputs\n" : ")\n");
  ::_exit(128 + sig);
}

constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

// Reservations (InFlightReservation): ordinary threads only, never the handler.
std::mutex reservation_mutex;
std::condition_variable reservation_freed;
std::size_t reserved = 0;

}  // namespace

InFlightReservation::InFlightReservation(std::size_t count) : count_(count) {
  if (count > kInFlightSlots) {
    throw std::length_error("cannot write " + std::to_string(count) + " files as one set (at most " +
                            std::to_string(kInFlightSlots) + ")");
  }
  std::unique_lock lock(reservation_mutex);
  reservation_freed.wait(lock, [count] { return reserved + count <= kInFlightSlots; });
  reserved += count;
}

InFlightReservation::~InFlightReservation() {
  {
    const std::lock_guard lock(reservation_mutex);
    reserved -= count_;
  }
  reservation_freed.notify_all();
}

int register_in_flight(std::string_view path) {
  if (path.size() >= kInFlightPathMax) return -1;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(slots[i].path, path.data(), path.size());
    slots[i].path[path.size()] = '\0';
    // From here on a signal removes the file; it may not exist yet (mkstemp
    // fills in the name first and creates the file under it afterwards).
    slots[i].state.store(kReady);
    return static_cast<int>(i);
  }
  return -1;
}

char* slot_path(int slot) { return slots.at(static_cast<std::size_t>(slot)).path; }

void release_in_flight(int slot) {
  if (slot < 0) return;
  slots.at(static_cast<std::size_t>(slot)).state.store(kFree);
}

std::size_t remove_in_flight() noexcept {
  std::size_t count = 0;
  for (Slot& slot : slots) {
    // The slot stays taken: its owner releases it (in a handler the process
    // ends here anyway). A file already gone (renamed just before the signal)
    // makes unlink fail harmlessly.
    if (slot.state.load() != kReady) continue;
    ::unlink(slot.path);
    ++count;
  }
  return count;
}

DeferredInterrupts::DeferredInterrupts() { deferring.fetch_add(1); }
DeferredInterrupts::~DeferredInterrupts() { deferring.fetch_sub(1); }

int pending_interrupt() { return pending.load(); }

void exit_interrupted(int sig) {
  const bool removed = remove_in_flight() > 0;
  write_all("pita: interrupted (");
  write_all(signal_name(sig));
  write_all(removed ? "); removed unfinished outputs\n" : "); removed unfinished outputs\n");
  ::_exit(128 + sig);
}

void install_interrupt_cleanup() {
  static std::atomic<bool> installed{false};
  if (installed.exchange(true)) return;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  // One handler at a time: a second signal waits until the first has exited.
  sigemptyset(&action.sa_mask);
  for (const int sig : kSignals) sigaddset(&action.sa_mask, sig);
  action.sa_flags = 0;
  for (const int sig : kSignals) {
    struct sigaction previous {};
    if (::sigaction(sig, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &action, nullptr);
  }
}

}  // namespace pita::io
