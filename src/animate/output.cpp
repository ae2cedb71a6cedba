#include "animate/output.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>

#include <fcntl.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include "animate/frame.hpp"
#include "animate/frame_runner.hpp"
#include "animate/progress.hpp"
#include "animate/svg_animation.hpp"
#include "animate/video.hpp"
#include "io/interrupt.hpp"
#include "io/output_file.hpp"
#include "render/backdrop.hpp"
#include "render/budget.hpp"
#include "render/panel_drawing.hpp"
#include "render/static_layers.hpp"

namespace pita::animate {

namespace fs = std::filesystem;

namespace detail {

void output_failed(const fs::path& path, const std::string& reason) {
  throw io::OutputError(fmt::format("{}: cannot write: {}", path.string(), reason));
}

mode_t ordinary_mode(mode_t full) {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return full & ~mask;
}

}  // namespace detail

namespace {

using Json = nlohmann::ordered_json;
using detail::ordinary_mode;
using detail::output_failed;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

// ------------------------------------------------------------ directory

bool detail::is_frame_directory(const fs::path& path) {
  std::error_code error;
  if (!fs::is_directory(fs::symlink_status(path, error))) return false;
  bool has_index = false;
  for (const fs::directory_entry& entry : fs::directory_iterator(path, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file(error) || entry.is_symlink(error)) return false;
    if (name == "frames.json") {
      std::ifstream in(entry.path());
      const Json index = Json::parse(in, nullptr, false);
      if (index.is_discarded() || !index.is_object() || !index.contains("frame_list")) return false;
      has_index = true;
      continue;
    }
    const bool frame = name.starts_with("frame-") && (name.ends_with(".png") || name.ends_with(".svg")) &&
                       std::all_of(name.begin() + 6, name.end() - 4,
                                   [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (!frame) return false;
  }
  if (error) return false;
  return has_index || fs::is_empty(path, error);
}

namespace {

using detail::is_frame_directory;

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) output_failed(path, std::strerror(errno));
}

// A folder being made beside OUT, removed unless it is moved into place (path cleared).
struct TemporaryFolder {
  fs::path path;
  explicit TemporaryFolder(fs::path made) : path(std::move(made)) {}
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder() {
    if (!path.empty()) {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  }
  // Removes it now and exits as interrupted by `signal`.
  [[noreturn]] void exit_interrupted(int signal) {
    std::error_code error;
    fs::remove_all(path, error);
    path.clear();
    stop_interrupted(signal);
  }
};

// The folder OUT names (OUT/ names OUT), refused when it is something else
// than a frame directory pita wrote.
fs::path frame_folder(const fs::path& target) {
  std::error_code error;
  const fs::path directory = target.filename().empty() ? target.parent_path() : target;
  const fs::file_status status = fs::symlink_status(directory, error);
  if (fs::exists(status) && !fs::is_directory(status)) {
    output_failed(target, fs::is_symlink(status) ? "it is a symbolic link; give the directory itself"
                                                 : "it exists and is not a directory (frames go into a directory)");
  }
  if (fs::exists(status) && !is_frame_directory(directory)) {
    output_failed(target,
                  "it exists and is not a frame directory that pita wrote (only frame-NNNN files and "
                  "pita's frames.json): remove it or give another OUT");
  }
  return directory;
}

// Draws every frame into `folder` (frame-NNNN.png or .svg); their records for frames.json.
Json write_frames(const scene::Scene& scene, const Timeline& timeline, const Request& request,
                  const motion::Stage* stage, render::StaticLayers* layers,
                  const std::vector<render::PanelPlacement>& placements, TemporaryFolder& folder) {
  // PNG frames are painted over the layers every frame shares, painted once.
  std::optional<render::FrameBackdrop> backdrop;
  if (request.frame_format == render::Format::png) {
    const render::Figure first = frame_figure(scene, timeline, timeline.time(0), placements, stage, layers);
    const auto [width, height] = render::checked_png_size(scene, first, request.scale, request.budget);
    backdrop.emplace(scene, first, width, height, request.scale);
  }
  Progress progress("frames", timeline.frames, request.progress);
  Json records = Json::array();
  try {
    run_frames(
        timeline.frames, request.threads,
        [&](int k) {
          const render::Figure figure = frame_figure(scene, timeline, timeline.time(k), placements, stage, layers);
          if (!backdrop)
            return render::render_figure(scene, figure, request.frame_format, request.scale, request.budget);
          render::checked_png_size(scene, figure, request.scale, request.budget);
          return render::encode_png(scene, backdrop->paint(figure).get());
        },
        [&](int k, std::string&& bytes) {
          const std::string file = frame_file_name(k, timeline.frames, request.frame_format);
          write_bytes(folder.path / file, bytes);
          records.push_back(frame_record(scene, timeline, k, file, stage));
          progress.update(k + 1);
        },
        request.cancelled);
  } catch (const Interrupted& interrupted) {
    folder.exit_interrupted(interrupted.signal);
  }
  return records;
}

// frames.json: the animation and the record of every frame.
Json frames_index(const scene::Scene& scene, const Timeline& timeline, const Request& request, Json records) {
  const double scale = request.frame_format == render::Format::png ? request.scale : 1.0;
  return Json{{"scene", scene.path},
              {"what", what_name(timeline.what)},
              {"frames", timeline.frames},
              {"fps", timeline.fps},
              {"duration", timeline.seconds()},
              {"loop", timeline.loop},
              {"first", timeline.first},
              {"last", timeline.last},
              {"width", static_cast<int>(std::round(scene.canvas.width * scale))},
              {"height", static_cast<int>(std::round(scene.canvas.height * scale))},
              {"frame_list", std::move(records)}};
}

// Into place: a new directory is renamed; an older one is swapped with the
// new one atomically (renameat2 RENAME_EXCHANGE), then removed (as `folder`,
// which then holds the older frames).
void move_into_place(TemporaryFolder& folder, const fs::path& final_path, const fs::path& target) {
  std::error_code error;
  ::chmod(folder.path.c_str(), ordinary_mode(0777));
  if (!fs::exists(final_path, error)) {
    if (::rename(folder.path.c_str(), final_path.c_str()) != 0) output_failed(target, std::strerror(errno));
    folder.path.clear();
  } else if (::renameat2(AT_FDCWD, folder.path.c_str(), AT_FDCWD, final_path.c_str(), RENAME_EXCHANGE) != 0) {
    output_failed(target, std::strerror(errno));
  }
}

fs::path write_directory(const scene::Scene& scene, const Timeline& timeline, const Request& request,
                         const motion::Stage* stage, render::StaticLayers* layers,
                         const std::vector<render::PanelPlacement>& placements) {
  const fs::path target = request.out;
  std::error_code error;
  const fs::path directory = frame_folder(target);
  const fs::path parent = directory.parent_path().empty() ? fs::path(".") : directory.parent_path();
  const fs::path name = directory.filename();
  fs::create_directories(parent, error);
  std::string pattern = (parent / ("." + name.string() + ".XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) output_failed(target, std::strerror(errno));
  TemporaryFolder folder{pattern};
  Json records = write_frames(scene, timeline, request, stage, layers, placements, folder);
  write_bytes(folder.path / "frames.json", frames_index(scene, timeline, request, std::move(records)).dump(1) + "\n");
  if (const int sig = pending_stop(request.cancelled)) folder.exit_interrupted(sig);
  move_into_place(folder, parent / name, target);
  return target;
}

}  // namespace

AnimationOutput output_kind(const std::string& out) {
  if (out.empty()) throw AnimationError("-o: the output is empty: give OUT.svg, OUT.mp4, OUT.webm or a directory");
  const fs::path path(out);
  const fs::path last = path.filename().empty() ? path.parent_path().filename() : path.filename();
  if (last.empty() || last == "." || last == "..") {
    throw AnimationError(fmt::format("-o {}: not a directory pita can write frames into", out));
  }
  if (!path.has_filename() || !path.has_extension()) return AnimationOutput::directory;
  const std::string extension = lower(path.extension().string());
  if (extension == ".svg") return AnimationOutput::svg;
  if (extension == ".mp4") return AnimationOutput::mp4;
  if (extension == ".webm") return AnimationOutput::webm;
  throw AnimationError(
      fmt::format("-o {}: \"{}\" is not an output pita animates into: give OUT.svg (an animated SVG), "
                  "OUT.mp4 or OUT.webm (a video), or a directory (no extension, or ending in \"/\") "
                  "for a sequence of frames",
                  out, path.extension().string()));
}

std::string frame_file_name(int k, int count, render::Format format) {
  const int digits = std::max(4, static_cast<int>(std::to_string(count).size()));
  return fmt::format("frame-{:0{}}.{}", k + 1, digits, render::extension(format));
}

void check_total_work(const scene::Scene& scene, const Timeline& timeline, const Request& request) {
  const bool vector = request.kind == AnimationOutput::svg ||
                      (request.kind == AnimationOutput::directory && request.frame_format == render::Format::svg);
  const double limit = kMaxAnimationUnits * request.budget;
  // The motions: built once for a "motion" animation, once per frame and per
  // frame of the layout for "pattern" (the keyframes move).
  const render::MotionBuildCost build = render::motion_build_cost(scene);
  const double builds = timeline.what == scene::Animation::What::pattern ? timeline.frames + kLayoutFrames : 1.0;
  if (build.units * builds > 0.5 * limit) {
    throw AnimationError(
        fmt::format("{}{}: the animation would build the motions {:.0f} times ({}), about {:.3g} units each for the "
                    "arc-length timing ({:.3g} in all), beyond half the animation's drawing budget of {:.3g}; use "
                    "fewer frames or keyframes, drop \"arc_length\" or its \"per\": \"span\", or raise the budget "
                    "with --budget F",
                    scene.path.empty() ? "" : scene.path + ": ", build.pointer, builds,
                    builds > 1 ? "once per frame and per frame of the layout: the keyframes move" : "once", build.units,
                    build.units * builds, limit));
  }
  const double units = render::estimate_cost(scene).units * timeline.frames + build.units * builds;
  if (units > limit) {
    throw AnimationError(
        fmt::format("--frames: {} frames of a figure of about {:.3g} drawn points ({:.3g} in all) "
                    "exceed the animation's drawing budget of {:.3g}; use fewer frames or fewer "
                    "samples, or raise the budget with --budget F",
                    timeline.frames, units / timeline.frames, units, limit));
  }
  if (vector) {
    if (timeline.frames > kMaxVectorFrames * request.budget) {
      throw AnimationError(
          fmt::format("--frames: {} frames of vector output exceed the limit of {:.0f} (the file "
                      "grows with every frame); use fewer frames, PNG frames or a video, or raise "
                      "the limit with --budget F",
                      timeline.frames, kMaxVectorFrames * request.budget));
    }
    return;
  }
  const double pixels = static_cast<double>(timeline.frames) * std::round(scene.canvas.width * request.scale) *
                        std::round(scene.canvas.height * request.scale);
  if (pixels > kMaxPixelFrames * request.budget) {
    throw AnimationError(
        fmt::format("--frames: {} frames of {} x {} pixels ({:.3g} pixels in all) exceed the "
                    "animation budget of {:.3g} pixels (about 4 minutes on 2 cores); use fewer "
                    "frames or a smaller --scale, or raise the budget with --budget F",
                    timeline.frames, std::round(scene.canvas.width * request.scale),
                    std::round(scene.canvas.height * request.scale), pixels, kMaxPixelFrames * request.budget));
  }
}

std::vector<fs::path> write_animation(const scene::Scene& scene, const Timeline& timeline, const Request& request) {
  // One frame's budget first: its message names the field that costs most.
  render::check_budget(scene, render::estimate_cost(scene), request.budget);
  check_total_work(scene, timeline, request);
  render::check_images(scene);
  // The motions, built once for the layout and every frame ("pattern" changes
  // the scene per frame): an arc-length warp of a long track costs seconds
  // to build, and was built two to four times.
  std::optional<motion::Stage> stage;
  if (timeline.what != scene::Animation::What::pattern) stage.emplace(scene);
  const motion::Stage* shared = stage ? &*stage : nullptr;
  // The layers that read nothing of the frame: drawn once, for the layout and
  // every frame (render/static_layers.hpp).
  render::StaticLayers layers;
  const std::vector<render::PanelPlacement> placements = animation_layout(scene, timeline, shared, &layers);
  // The first frame before any output exists: a scene that cannot be drawn
  // fails here, having written nothing.
  frame_figure(scene, timeline, timeline.time(0), placements, shared, &layers);
  const io::DeferredInterrupts deferred;
  switch (request.kind) {
    case AnimationOutput::svg: {
      Progress progress("frames", timeline.frames, request.progress);
      const std::string svg = animated_svg(
          scene, timeline,
          [&](int k) {
            if (const int sig = pending_stop(request.cancelled)) stop_interrupted(sig);
            progress.update(k + 1);
          },
          shared, &layers);
      if (const int sig = pending_stop(request.cancelled)) stop_interrupted(sig);
      io::write_file_atomically(request.out, svg);
      return {request.out};
    }
    case AnimationOutput::directory:
      return {write_directory(scene, timeline, request, shared, &layers, placements)};
    case AnimationOutput::mp4:
    case AnimationOutput::webm:
      return {write_video(scene, timeline, request, shared, &layers, placements)};
  }
  return {};
}

}  // namespace pita::animate
