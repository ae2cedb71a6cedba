// The environment pita reads, in one place: the layers below take these as
// options (animate::Request, sweep::SweepOptions, animate::Progress) and never
// read the environment themselves.
//   PITA_THREADS  threads of `pita animate` (1 to 64; default: every core)
//   PITA_FFMPEG   the ffmpeg to run for videos (default: ffmpeg on PATH)
//   PATH          where that ffmpeg is looked for
//   CI            when set and not empty, no progress bar or lines (CI logs)
#pragma once

#include <string>

namespace pita::cli {

// PITA_THREADS when it is a whole number from 1 to 64, else every core (1 to 64).
int threads_from_environment();

// Whether progress may be shown: not --quiet, and not in CI (CI set, not empty).
bool progress_allowed(bool quiet);

// The ffmpeg that writes videos: PITA_FFMPEG, else ffmpeg on PATH
// (animate::find_ffmpeg); "" when there is none.
std::string ffmpeg_from_environment();

}  // namespace pita::cli
