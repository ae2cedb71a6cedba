// A fixed number of places, the oldest holder told to leave when one more
// comes: how `pita serve` bounds its event streams and the requests still
// being received, so that a flood of them (or of tabs) cannot lock the
// page's own requests out: the newest always gets in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <set>

namespace pita::serve {

class OldestFirst {
 public:
  explicit OldestFirst(std::size_t capacity) : capacity_(capacity) {}

  // A place for one more: when all are taken, the oldest holder is told to
  // leave (told_to_leave turns true for its ticket).
  std::uint64_t enter() {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::uint64_t ticket = next_++;
    holders_.push_back(ticket);
    if (holders_.size() > capacity_) {
      told_.insert(holders_.front());
      holders_.pop_front();
    }
    return ticket;
  }

  bool told_to_leave(std::uint64_t ticket) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return told_.count(ticket) != 0;
  }

  void leave(std::uint64_t ticket) {
    const std::lock_guard<std::mutex> lock(mutex_);
    told_.erase(ticket);
    for (auto it = holders_.begin(); it != holders_.end(); ++it) {
      if (*it == ticket) {
        holders_.erase(it);
        break;
      }
    }
  }

  std::size_t held() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return holders_.size();
  }

 private:
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::deque<std::uint64_t> holders_;  // oldest first
  std::set<std::uint64_t> told_;
  std::uint64_t next_ = 0;
};

// Holds a place of an OldestFirst for its lifetime.
class Place {
 public:
  explicit Place(OldestFirst& places) : places_(places), ticket_(places.enter()) {}
  ~Place() { places_.leave(ticket_); }
  Place(const Place&) = delete;
  Place& operator=(const Place&) = delete;
  bool told_to_leave() const { return places_.told_to_leave(ticket_); }

 private:
  OldestFirst& places_;
  std::uint64_t ticket_;
};

}  // namespace pita::serve
