#include "sweep/unchanged_axes.hpp"

#include <cstddef>

namespace pita::sweep {

namespace {

// The first-value digests kept over all axes, at most (8 bytes each): beyond,
// the axes whose first values are the most are not tracked.
constexpr std::int64_t kMaxFirstsKept = std::int64_t{1} << 20;

}  // namespace

UnchangedAxes::UnchangedAxes(const Grid& grid) : zip_(grid.zip()) {
  if (zip_) {
    for (const Axis& axis : grid.axes()) tracks_.push_back({axis.pointer, 1, 1, {}, true, false});
    return;
  }
  const std::vector<Axis>& axes = grid.axes();
  std::int64_t stride = 1, kept = 0;
  std::vector<Track> tracks(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    tracks[k].pointer = axes[k].pointer;
    tracks[k].stride = stride;
    tracks[k].size = static_cast<std::int64_t>(axes[k].size());
    stride *= tracks[k].size;
  }
  for (Track& track : tracks) {
    const std::int64_t firsts = grid.size() / track.size;
    if (track.size < 2 || kept + firsts > kMaxFirstsKept) continue;
    kept += firsts;
    track.first.assign(static_cast<std::size_t>(firsts), 0);
    tracks_.push_back(std::move(track));
  }
}

void UnchangedAxes::add(std::int64_t index, std::uint64_t digest) {
  if (digest == 0) return;
  if (zip_) {
    if (zip_first_ == 0) zip_first_ = digest;
    zip_same_ = zip_same_ && digest == zip_first_;
    ++zip_compared_;
    return;
  }
  for (Track& track : tracks_) {
    if (!track.same) continue;
    const std::int64_t at = (index / track.stride) % track.size;
    // The other axes' position: the index without this axis's digit.
    const std::int64_t rest = (index / (track.stride * track.size)) * track.stride + index % track.stride;
    std::uint64_t& first = track.first[static_cast<std::size_t>(rest)];
    if (at == 0) {
      first = digest;
    } else if (first != 0) {
      track.compared = true;
      track.same = digest == first;
    }
  }
}

std::vector<std::string> UnchangedAxes::unchanged() const {
  std::vector<std::string> out;
  if (zip_) {
    if (zip_same_ && zip_compared_ >= 2) {
      for (const Track& track : tracks_) out.push_back(track.pointer);
    }
    return out;
  }
  for (const Track& track : tracks_) {
    if (track.same && track.compared) out.push_back(track.pointer);
  }
  return out;
}

}  // namespace pita::sweep
