// Clean interruption: SIGINT, SIGTERM and SIGHUP remove the temporary files
// that are being written (output_file.cpp writes every output to a hidden
// temporary beside its target and renames it into place) and exit with
// 128 + the signal's number, as a shell reports a process killed by it.
//
// The registry of temporaries in flight is read by the signal handler, so it
// is built from what a handler may touch: fixed static slots of characters
// and lock-free atomic flags, no allocation, and unlink(2) and write(2), which
// are async-signal-safe. A signal arriving at any point leaves either no
// temporary file or a registered one, never a stray one: the slot holds the
// name before mkstemp creates the file, and is released only after the file
// was renamed into place or removed.
#pragma once

#include <cstddef>
#include <string_view>

namespace pita::io {

// Temporary files that can be in flight at once. Writers reserve their slots
// first (InFlightReservation) and wait while all are taken, so that this is
// never a limit a user meets: `pita sweep --jobs 256` writes 64 files at a
// time, the other writers wait for a slot instead of failing.
inline constexpr std::size_t kInFlightSlots = 64;
// Longest registered path, with its terminating NUL: the kernel refuses longer ones.
inline constexpr std::size_t kInFlightPathMax = 4096;

// The right to register `count` temporaries: blocks until that many slots are
// free of other reservations, and holds them until destroyed. A writer
// reserves every file of its set at once (never one by one, which could
// deadlock writers each holding part of a set). Throws std::length_error when
// `count` exceeds kInFlightSlots.
class InFlightReservation {
 public:
  explicit InFlightReservation(std::size_t count);
  ~InFlightReservation();
  InFlightReservation(const InFlightReservation&) = delete;
  InFlightReservation& operator=(const InFlightReservation&) = delete;

 private:
  std::size_t count_;
};

// Claims a free slot and copies `path` into it; call it under a reservation. Returns the slot's number, or
// -1 when every slot is taken or the path is too long (the caller then must not
// create the file). The returned slot's characters may be changed in place
// (slot_path: mkstemp fills in its XXXXXX there) until it is released.
int register_in_flight(std::string_view path);

// The registered path of `slot`, writable: mkstemp(slot_path(slot)) creates the
// temporary under the very name the handler would remove.
char* slot_path(int slot);

// Forgets `slot` without removing its file (it was renamed into place, or the
// caller removed it). A slot of -1 is ignored.
void release_in_flight(int slot);

// Unlinks every registered file; returns how many paths were registered. The
// slots stay taken (their owners release them). Async-signal-safe: this is
// what the handler calls.
std::size_t remove_in_flight() noexcept;

// Installs the SIGINT, SIGTERM and SIGHUP handler, once, from main(): it
// calls remove_in_flight(), writes "pita: interrupted (SIGTERM); removed
// unfinished outputs" to stderr and _exit(128 + signal). A signal that was
// ignored when pita started (nohup, a background job of a non-interactive
// shell) stays ignored.
void install_interrupt_cleanup();

// Work that cleans up after itself (an animation's frames are written by
// several threads into a temporary directory, and ffmpeg runs beside pita):
// while a DeferredInterrupts lives, the first SIGINT, SIGTERM or SIGHUP is
// only recorded (pending_interrupt() returns it); the owner notices it between
// frames, stops its threads and ffmpeg, removes what it wrote and calls
// exit_interrupted(). A second signal ends the process at once, as outside.
class DeferredInterrupts {
 public:
  DeferredInterrupts();
  ~DeferredInterrupts();
  DeferredInterrupts(const DeferredInterrupts&) = delete;
  DeferredInterrupts& operator=(const DeferredInterrupts&) = delete;
};

// The signal recorded while deferring, 0 when none.
int pending_interrupt();

// Removes the registered temporaries, says "pita: interrupted (SIGTERM);
// removed unfinished outputs" and exits with 128 + sig.
[[noreturn]] void exit_interrupted(int sig);

}  // namespace pita::io
