#include "serve/live_scenes.hpp"

#include <ctime>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/claims.hpp"
#include "analysis/measure.hpp"
#include "analysis/measure_report.hpp"
#include "animate/frame.hpp"
#include "animate/output.hpp"
#include "animate/svg_animation.hpp"
#include "animate/timeline.hpp"
#include "core/fnv1a.hpp"
#include "io/output_file.hpp"
#include "motion/stage.hpp"
#include "render/budget.hpp"
#include "render/panel_drawing.hpp"
#include "scene/image_file.hpp"
#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/located_error.hpp"
#include "serve/edit_request.hpp"
#include "serve/json_edit.hpp"
#include "serve/scene_edit.hpp"

namespace pita::serve {

namespace {

// The processor time this thread has used, in seconds.
double thread_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

std::string digest_of(const std::string& text) {
  Fnv1a hash;
  hash.add(text);
  return fmt::format("{:016x}", hash.value());
}

Json handles_json(const std::vector<Handle>& all) {
  Json out = Json::array();
  for (const Handle& handle : all) {
    out.push_back({{"panel", handle.panel},
                   {"pointer", handle.pointer},
                   {"part", handle.part},
                   {"at", {handle.at.real(), handle.at.imag()}}});
  }
  return out;
}

// The timeline's rows: each keyframe's, point's or pose's time, by where the keys are given.
Json key_rows_json(const std::vector<KeyRow>& rows) {
  Json out = Json::array();
  for (const KeyRow& row : rows) {
    Json times = Json::array();
    for (const KeyTime& time : row.times) times.push_back({{"pointer", time.pointer}, {"t", time.t}});
    out.push_back({{"keys", row.keys}, {"panels", row.panels}, {"times", times}});
  }
  return out;
}

}  // namespace

Json error_json(const std::exception_ptr& thrown, const std::string& path) {
  Json error{{"file", path}, {"line", 0}, {"column", 0}, {"pointer", ""}, {"reason", ""}, {"message", ""}};
  try {
    std::rethrow_exception(thrown);
  } catch (const scene::LocatedError& e) {
    error.update({{"file", e.file()},
                  {"line", e.line()},
                  {"column", e.column()},
                  {"pointer", e.pointer()},
                  {"reason", e.reason()},
                  {"message", e.what()}});
  } catch (const std::exception& e) {
    error.update({{"reason", e.what()}, {"message", path + ": " + e.what()}});
  }
  return error;
}

int error_status(const std::exception_ptr& thrown) {
  try {
    std::rethrow_exception(thrown);
  } catch (const scene::LocatedError& e) {
    return scene::answer(e.kind()).http_status;
  } catch (...) {
    return 422;
  }
}

LiveScenes::LiveScenes(const Settings& settings) : settings_(settings) {
  for (const fs::path& path : settings.scenes) {
    auto state = std::make_unique<SceneState>();
    state->path = path;
    state->files = {path};
    scenes_.push_back(std::move(state));
  }
}

void LiveScenes::render(std::size_t i, bool saved) {
  SceneState& state = *scenes_[i];
  std::shared_ptr<const scene::Scene> scene;
  std::string svg;
  std::optional<Json> error;
  render::Figure figure;
  Json claims = Json::array();
  Json camera;
  Json edit_handles = Json::array(), edit_views = Json::array();
  std::string text;
  try {
    text = scene::read_input_file(state.path, scene::kMaxSceneFileBytes, "scene file");
    scene = std::make_shared<const scene::Scene>(scene::parse_scene(text, state.path.string(), read_options()));
    const motion::Stage stage(*scene);
    figure = render::build_figure(stage);
    svg = render::render_figure(*scene, figure, render::Format::svg);
    camera = camera_json(stage);
    if (settings_.edit) {
      // What the page drags, and the world view of each panel it holds while it edits (edit_request.hpp).
      edit_handles = handles_json(handles(text, stage, figure.placements));
      edit_views = views_json(stage, figure.placements);
    }
    for (const analysis::ClaimOutcome& claim : analysis::check_claims(stage)) {
      claims.push_back(
          {{"pointer", claim.pointer}, {"says", claim.says}, {"held", claim.held}, {"measured", claim.measured}});
    }
  } catch (...) {
    error = error_json(std::current_exception(), state.path.string());
  }
  // What the terminal says of it (before `error` and `claims` move into the state).
  std::optional<std::string> error_line;
  if (error) error_line = error->at("message").get<std::string>();
  std::string claims_line;
  if (!claims.empty()) {
    const auto failing =
        std::count_if(claims.begin(), claims.end(), [](const Json& c) { return !c.at("held").get<bool>(); });
    claims_line = failing == 0 ? fmt::format(" ({} claims hold)", claims.size())
                               : fmt::format(" ({} of {} claims fail)", failing, claims.size());
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!error) {
      state.scene = scene;
      state.svg = std::move(svg);
      state.placements = figure.placements;
      state.claims = std::move(claims);
      state.camera = std::move(camera);
      state.handles = std::move(edit_handles);
      state.views = std::move(edit_views);
      state.text = std::move(text);
      state.files = {state.path};
      state.animation.reset();  // made again when asked for
      state.layout.reset();
      state.turned_layout.reset();
      for (const fs::path& image : scene::image_files(*scene)) state.files.push_back(image);
    }
    state.error = std::move(error);
    ++state.version;
  }
  changed_.notify_all();
  if (error_line) {
    say(*error_line + (saved ? "; the page keeps the last good figure" : ""));
  } else if (saved) {
    say(fmt::format("{}: saved, figure updated{}", state.path.string(), claims_line));
  }
}

void LiveScenes::say(const std::string& line) {
  const std::lock_guard<std::mutex> lock(log_mutex_);
  if (log_ != nullptr) *log_ << "pita: " << line << '\n' << std::flush;
}

std::vector<fs::path> LiveScenes::watched() {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<fs::path> files;
  for (const auto& state : scenes_) files.insert(files.end(), state->files.begin(), state->files.end());
  return files;
}

std::vector<std::size_t> LiveScenes::scenes_of(const std::set<fs::path>& saved) {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < scenes_.size(); ++i) {
    for (const fs::path& file : scenes_[i]->files) {
      if (saved.count(fs::absolute(file).lexically_normal()) != 0) {
        which.push_back(i);
        break;
      }
    }
  }
  return which;
}

Json LiveScenes::scenes_json() {
  const std::lock_guard<std::mutex> lock(mutex_);
  Json all = Json::array();
  for (std::size_t i = 0; i < scenes_.size(); ++i) {
    const SceneState& state = *scenes_[i];
    Json entry{{"index", i},
               {"name", state.path.stem().string()},
               {"path", state.path.string()},
               {"version", state.version},
               {"title", state.scene ? state.scene->title : ""},
               {"description", state.scene ? state.scene->description : ""},
               {"error", state.error ? *state.error : Json(nullptr)},
               {"timeline", nullptr},
               {"handles", Json::array()},
               {"claims", state.claims},
               {"digest", digest_of(state.text)},
               {"camera", state.camera},
               {"panels", Json::array()}};
    // A 3D scene's camera, which the page turns; "Save view" writes it with --edit only.
    if (!state.camera.is_null()) entry["camera"]["save"] = settings_.edit;
    // Where each panel is drawn (canvas pixels): the page shows the measures of the one under the pointer.
    for (const render::PanelPlacement& placement : state.placements) {
      entry["panels"].push_back({placement.cell.x, placement.cell.y, placement.cell.width, placement.cell.height});
    }
    if (settings_.edit && state.scene) {
      entry["handles"] = state.handles;
      entry["views"] = state.views;  // the page holds them while it edits
    }
    if (state.scene) entry["keys"] = key_rows_json(key_rows(state.text, *state.scene));
    if (state.scene) {
      try {
        const animate::Timeline timeline = animate::make_timeline(*state.scene);
        entry["timeline"] = Json{{"first", timeline.first},
                                 {"last", timeline.last},
                                 {"frames", timeline.frames},
                                 {"fps", timeline.fps},
                                 {"loop", timeline.loop},
                                 {"what", timeline.what == scene::Animation::What::pattern ? "pattern" : "motion"}};
      } catch (const std::exception&) {
        // no motion to play (a figure without one)
      }
    }
    all.push_back(entry);
  }
  return all;
}

std::pair<std::shared_ptr<const scene::Scene>, std::shared_ptr<const std::vector<render::PanelPlacement>>>
LiveScenes::frame_layout(std::size_t i, const std::optional<CameraTurn>& turn) {
  std::shared_ptr<const scene::Scene> scene;
  std::shared_ptr<LayoutCache> cache;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    SceneState& state = *scenes_[i];
    if (!state.scene) return {};
    if (turn) {
      // One turned view kept: scrubbing a view held turned makes its layout once.
      const std::string key = fmt::format("{},{},{}", turn->azimuth, turn->elevation, turn->distance.value_or(0.0));
      if (!state.turned_layout || state.turned_layout->turn != key) {
        auto made = std::make_shared<LayoutCache>();
        made->turn = key;
        made->scene = std::make_shared<const scene::Scene>(turned_scene(*state.scene, *turn));
        state.turned_layout = made;
      }
      cache = state.turned_layout;
      scene = cache->scene;
    } else {
      if (!state.layout) state.layout = std::make_shared<LayoutCache>();
      scene = state.scene;
      cache = state.layout;
    }
  }
  const std::lock_guard<std::mutex> lock(cache->mutex);
  if (!cache->made) {
    try {
      cache->placements = animate::animation_layout(*scene, animate::make_timeline(*scene));
    } catch (...) {
      cache->error = std::current_exception();
    }
    cache->made = true;
  }
  if (cache->error) std::rethrow_exception(cache->error);
  // Shares the cache's lifetime: the placements stay while a frame is drawn with them.
  return {scene, std::shared_ptr<const std::vector<render::PanelPlacement>>(cache, &cache->placements)};
}

std::optional<std::string> LiveScenes::figure(std::size_t i, std::optional<double> at,
                                              const std::optional<CameraTurn>& turn) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!at && !turn) return scenes_[i]->scene ? std::optional<std::string>(scenes_[i]->svg) : std::nullopt;
  }
  return export_figure(i, at, render::Format::svg, turn);
}

std::optional<std::string> LiveScenes::animation(std::size_t i) {
  std::shared_ptr<const scene::Scene> scene;
  std::shared_ptr<AnimationCache> cache;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    SceneState& state = *scenes_[i];
    if (!state.scene) return std::nullopt;
    if (!state.animation) state.animation = std::make_shared<AnimationCache>();
    scene = state.scene;
    cache = state.animation;
  }
  const std::lock_guard<std::mutex> lock(cache->mutex);
  if (!cache->made) {
    try {
      // As `pita animate -o OUT.svg` checks and writes it.
      const animate::Timeline timeline = animate::make_timeline(*scene);
      animate::Request request;
      request.kind = animate::AnimationOutput::svg;
      render::check_budget(*scene, render::estimate_cost(*scene), request.budget);
      animate::check_total_work(*scene, timeline, request);
      render::check_images(*scene);
      // Given up once it would take longer than kMaxPageAnimationSeconds of
      // this thread's processor time: the work, not the wall clock, which
      // other scenes' animations made at the same time (a page of many
      // scenes asks for all of them at once) or a busy machine stretch. It
      // makes the frames' view first, as the fetched frames do: the view made
      // here (and kept for them) says how long making it again would take.
      const double started = thread_seconds();
      frame_layout(i);
      const double layout = thread_seconds() - started;
      if (layout > kMaxPageAnimationSeconds / 2) {
        throw animate::AnimationError(
            fmt::format("the animated SVG would take minutes to make (its view alone took {:.0f} s): its frames "
                        "are drawn one by one",
                        layout));
      }
      // The pace of the frames from the end of the first (the layout comes before it).
      double first = 0.0;
      const auto pace = [&](int k) {
        const double now = thread_seconds();
        if (k == 0) first = now;
        const double spent = now - started;
        const double each = k == 0 ? 0.0 : (now - first) / k;
        const double total = spent + each * (timeline.frames - 1 - k);
        {
          // A save since makes another: this one is left (its page asks again), as when stopping.
          const std::lock_guard<std::mutex> state_lock(mutex_);
          if (scenes_[i]->animation != cache || stopping_) {
            throw animate::AnimationError("the scene was saved again while its animated SVG was made");
          }
        }
        if (total > kMaxPageAnimationSeconds) {
          throw animate::AnimationError(fmt::format(
              "the animated SVG would take about {:.0f} s to make, more than the page waits ({:.0f} s): its frames "
              "are drawn one by one",
              total, kMaxPageAnimationSeconds));
        }
      };
      cache->svg = animate::animated_svg(*scene, timeline, pace);
      if (cache->svg.size() > kMaxPageAnimationBytes) {
        const std::size_t size = cache->svg.size();
        cache->svg.clear();
        throw animate::AnimationError(fmt::format(
            "the animated SVG would be {:.3g} MB, more than the page takes ({} MB): its frames are drawn one by one",
            static_cast<double>(size) / 1e6, kMaxPageAnimationBytes >> 20U));
      }
    } catch (...) {
      cache->error = std::current_exception();
    }
    cache->made = true;
  }
  if (cache->error) std::rethrow_exception(cache->error);
  return cache->svg;
}

std::optional<std::string> LiveScenes::export_figure(std::size_t i, std::optional<double> at, render::Format format,
                                                     const std::optional<CameraTurn>& turn) {
  std::shared_ptr<const scene::Scene> scene;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    scene = scenes_[i]->scene;
    if (scene && !at && !turn && format == render::Format::svg) return scenes_[i]->svg;
  }
  if (!scene) return std::nullopt;
  // As pita render draws the file with the turned camera written in.
  if (turn && !at) scene = std::make_shared<const scene::Scene>(turned_scene(*scene, *turn));
  render::Figure figure;
  if (at) {
    // As pita render --at: one frame of the animation, in the view its frames
    // share (made once per good state, or per turned camera: it draws 33 frames of the figure).
    const auto [layout_scene, placements] = frame_layout(i, turn);
    if (!layout_scene) return std::nullopt;
    scene = layout_scene;
    const animate::Timeline timeline = animate::make_timeline(*scene);
    render::check_budget(*scene, render::estimate_cost(*scene), 1.0);
    render::check_images(*scene);
    figure = animate::frame_figure(*scene, timeline, *at, *placements);
  } else {
    const motion::Stage stage(*scene);
    figure = render::build_figure(stage);
  }
  return render::render_figure(*scene, figure, format);
}

std::optional<std::string> LiveScenes::measures(std::size_t i) {
  std::shared_ptr<const scene::Scene> scene;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    scene = scenes_[i]->scene;
  }
  if (!scene) return std::nullopt;
  analysis::check_measure_work(*scene);
  return analysis::measures_json(scene->path, analysis::measure_scene(*scene));
}

std::vector<std::uint64_t> LiveScenes::versions_after(const std::vector<std::uint64_t>& seen,
                                                      std::chrono::milliseconds wait) {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto now = [&] {
    std::vector<std::uint64_t> versions;
    for (const auto& state : scenes_) versions.push_back(state->version);
    return versions;
  };
  changed_.wait_for(lock, wait, [&] { return now() != seen || stopping_; });
  return now();
}

Json LiveScenes::edit(std::size_t i, const Json& request) {
  const std::lock_guard<std::mutex> one_at_a_time(edit_mutex_);
  const fs::path path = scenes_[i]->path;
  const std::string text = scene::read_input_file(path, scene::kMaxSceneFileBytes, "scene file");
  // Where the page drew the handle is where the figure it showed put it.
  if (request.contains("drag") && request.at("drag").contains("version")) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (request.at("drag").at("version").get<std::uint64_t>() != scenes_[i]->version) {
      throw std::invalid_argument("the figure changed while dragging: drag again");
    }
  }
  const scene::Scene scene = scene::parse_scene(text, path.string(), read_options());
  const Applied applied = apply_changes(text, request_changes(text, scene, request));
  const std::string& edited = applied.text;
  const Json& previous = applied.previous;
  // Refused unless the result is a scene pita draws.
  const scene::Scene checked = scene::parse_scene(edited, path.string(), read_options());
  const motion::Stage stage(checked);
  render::render_figure(checked, render::build_figure(stage), render::Format::svg);
  // The file itself (through a link, its target), with the permissions it had.
  const fs::path target = fs::canonical(path);
  const fs::perms permissions = fs::status(target).permissions();
  // Not over a save made since the edit read the file (an editor's, while
  // the edit was checked): the file is left as it is when it changed.
  if (!io::replace_file_if_unchanged(target, text, edited)) {
    throw std::invalid_argument(
        "the file changed while the edit was checked (saved by another program): it is kept as it is; drag again");
  }
  fs::permissions(target, permissions);
  return Json{{"previous", previous}};
}

std::optional<Json> LiveScenes::preview(std::size_t i, const Json& request) {
  std::shared_ptr<const scene::Scene> shown;
  std::string text;
  std::uint64_t version = 0;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!scenes_[i]->scene) return std::nullopt;
    shown = scenes_[i]->scene;
    text = scenes_[i]->text;
    version = scenes_[i]->version;
  }
  const auto views = views_of(request, shown->panels.size());
  // The drag made in the text of the figure shown, in memory: nothing is written.
  std::optional<scene::Scene> edited;
  if (request.contains("drag")) {
    text = apply_changes(text, request_changes(text, *shown, request)).text;
    edited = scene::parse_scene(text, shown->path, read_options());
  }
  const std::optional<scene::Scene> held = held_camera(edited ? *edited : *shown, request);
  const scene::Scene& scene = held ? *held : edited ? *edited : *shown;
  const motion::Stage stage(scene);
  const render::Figure figure = figure_in(stage, views);
  return Json{{"version", version},
              {"svg", render::render_figure(scene, figure, render::Format::svg)},
              {"handles", handles_json(handles(text, stage, figure.placements))}};
}

void LiveScenes::stop() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
}

bool LiveScenes::stopping() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return stopping_;
}

std::string LiveScenes::file_digest(std::size_t i) const {
  try {
    return digest_of(scene::read_input_file(scenes_.at(i)->path, scene::kMaxSceneFileBytes, "scene file"));
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace pita::serve
