// Which axes of a sweep changed nothing: an axis every value of which gave
// the same outputs as its first value, the other axes alike (with --zip, the
// axes move together: every variant the same). Fed each variant's digest of
// what its outputs show (sweep/run_variant.hpp) as the variants are journaled,
// in increasing index order; it keeps the digests of the variants at each
// axis's first value only, never one per variant.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sweep/grid.hpp"

namespace pita::sweep {

class UnchangedAxes {
 public:
  explicit UnchangedAxes(const Grid& grid);

  // Variant `index`'s digest, 0 for none (failed, resumed, another shard's):
  // not compared. Indices increase from call to call.
  void add(std::int64_t index, std::uint64_t digest);

  // The pointers of the axes that changed nothing, among those compared at
  // least once (an axis of one value, or one whose first values were too
  // many to keep, is never named).
  std::vector<std::string> unchanged() const;

 private:
  struct Track {
    std::string pointer;
    std::int64_t stride = 1;           // index step of one value of the axis
    std::int64_t size = 1;             // its values
    std::vector<std::uint64_t> first;  // digests at the axis's first value, by the other axes' position
    bool same = true;
    bool compared = false;
  };
  std::vector<Track> tracks_;
  bool zip_ = false;
  std::uint64_t zip_first_ = 0;
  bool zip_same_ = true;
  int zip_compared_ = 0;
};

}  // namespace pita::sweep
