// Where `pita animate` writes (docs/reference/animate.md "Animation"), chosen by OUT:
//   OUT.svg            one animated SVG (svg_animation.hpp);
//   OUT.mp4, OUT.webm  a video, raw frames piped into Debian's ffmpeg;
//   OUT (no extension, or ending in "/")  a directory of frames
//                      frame-0001.png ... (or .svg) and frames.json.
// Everything is written to a temporary beside OUT and renamed into place: a
// failed or interrupted run (SIGINT, SIGTERM, SIGHUP) leaves no partial output
// and an older OUT as it was.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

#include "animate/timeline.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::animate {

// What OUT of `pita animate` is: an animated SVG, a folder of frames, or a video.
enum class AnimationOutput { svg, directory, mp4, webm };

// The total work of an animation, beyond one frame's budget (render/budget.hpp):
// raster frames (PNG, video) at most kMaxPixelFrames pixels in all (about 4
// minutes on 2 cores), vector frames (the animated SVG, SVG frames) at most
// kMaxVectorFrames frames; and for every output the frames' drawing, frames x
// the figure's estimated units (render/budget.hpp), at most kMaxAnimationUnits
// (PNG or SVG frames of a 1000-keyframe track: about 6e6 units a second on
// one core, so about 50 s on 2 cores; the animated SVG draws the layers that
// do not move once and costs less). --budget F multiplies all three.
inline constexpr double kMaxPixelFrames = 1e10;
inline constexpr double kMaxVectorFrames = 5000;
inline constexpr double kMaxAnimationUnits = 5e8;

// Throws AnimationError naming --frames (or the scene's animation) when the
// request exceeds the limits above.
void check_total_work(const scene::Scene& scene, const Timeline& timeline, const struct Request& request);

// The kind of OUT. Throws AnimationError for an extension pita does not write
// (".gif", ".png": frames go into a directory).
AnimationOutput output_kind(const std::string& out);

struct Request {
  std::filesystem::path out;
  AnimationOutput kind = AnimationOutput::directory;
  render::Format frame_format = render::Format::png;  // directory frames: png or svg
  double scale = 1.0;                                 // PNG and video pixels per canvas pixel
  double budget = 1.0;                                // render --budget
  bool progress = true;                               // a bar on a terminal's stderr
  int threads = 1;
  std::string ffmpeg;  // the ffmpeg that writes videos; "" when none is installed
  // Polled between frames on the calling thread (the Python module's
  // Ctrl-C): when it returns true, write_animation removes its temporaries
  // and throws Cancelled (frame_runner.hpp) instead of exiting. Empty for
  // the command line, which only sees signals.
  std::function<bool()> cancelled;
};

// Renders every frame and writes OUT. Returns the paths written (OUT; for a
// directory, OUT itself). Throws AnimationError or RenderError (exit 2),
// OutputError (exit 3), and on a signal removes its temporaries and exits
// with 128 + signal (io/interrupt.hpp); Cancelled when request.cancelled asked.
std::vector<std::filesystem::path> write_animation(const scene::Scene& scene, const Timeline& timeline,
                                                   const Request& request);

// The frame files' names: frame-0001.png, with at least 4 digits (more when
// the count needs them), numbered from 1.
std::string frame_file_name(int k, int count, render::Format format);

namespace detail {  // shared by the writers of output.cpp and video.cpp

// Throws io::OutputError "PATH: cannot write: REASON".
[[noreturn]] void output_failed(const std::filesystem::path& path, const std::string& reason);

// The ordinary permissions of a new file or directory (0666 or 0777 less the
// umask): mkstemp creates 0600 and mkdtemp 0700, which the rename would keep.
mode_t ordinary_mode(mode_t full);

// A directory that pita's frame writer made: empty, or holding only
// frame-NNNN.png/.svg files and a frames.json of ours (a JSON object with
// "frame_list"). Only such a directory is ever replaced.
bool is_frame_directory(const std::filesystem::path& path);

}  // namespace detail

}  // namespace pita::animate
