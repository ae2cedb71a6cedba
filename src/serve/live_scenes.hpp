// The scenes of `pita serve`: each one's last good figure, what is wrong
// with its file now, its claims measured, and the edits written into it.
// The routes of server.cpp answer from here; the watching thread renders
// each saved scene again (render).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/figure.hpp"
#include "scene/scene.hpp"
#include "serve/camera_edit.hpp"
#include "serve/server.hpp"

namespace pita::serve {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// What the page shows of an error: where (file, line:column or JSON Pointer) and why.
Json error_json(const std::exception_ptr& thrown, const std::string& path);

// The HTTP status of the answer to a request that met the error: its kind's
// row of scene::kLocatedAnswers for a located error, else 422 (the scene, as
// it is, cannot be drawn or measured).
int error_status(const std::exception_ptr& thrown);

// The animated SVG of one good state of a scene (`pita animate OUT.svg`'s),
// made when first asked for and kept until the next good save: the page
// seeks it for every frame, so that no frame waits for the server.
struct AnimationCache {
  std::mutex mutex;  // held while it is made: a second request waits for it
  bool made = false;
  std::string svg;
  std::exception_ptr error;  // why there is none (AnimationError: no motion, or too large)
};

// The largest animated SVG the page is sent, and the longest it may take to
// make, in processor time of the thread that makes it (judged after each
// frame: the time so far, and the frames to come at the pace so far): beyond
// either it is refused (409) and the page fetches each frame from the server
// instead. The figures of scenes/ take 0.03 to 3.6 s (the layers that read
// nothing of the frame are drawn once: render/static_layers.hpp).
inline constexpr std::size_t kMaxPageAnimationBytes = 32U << 20U;
inline constexpr double kMaxPageAnimationSeconds = 20.0;

// The view every frame of one good state shares (animate::animation_layout),
// made once for the frames fetched one by one.
struct LayoutCache {
  std::mutex mutex;
  bool made = false;
  std::vector<render::PanelPlacement> placements;
  std::exception_ptr error;
  // For the frames of a view turned in the page: its camera ("AZ,EL,DIST") and the turned scene.
  std::string turn;
  std::shared_ptr<const scene::Scene> scene;
};

// One scene of the command line: its last good figure and what is wrong now.
struct SceneState {
  fs::path path;
  std::uint64_t version = 0;
  std::shared_ptr<const scene::Scene> scene;       // the last good one
  std::string svg;                                 // its figure
  std::optional<Json> error;                       // the last save's, when it could not be drawn
  std::vector<fs::path> files;                     // the scene and its images (what is watched)
  std::vector<render::PanelPlacement> placements;  // where the last good figure drew each panel
  Json claims = Json::array();                     // its caption's claims, measured (as pita check does)
  std::string text;                                // the file it was read from
  std::shared_ptr<AnimationCache> animation;       // its animated SVG, once asked for
  std::shared_ptr<LayoutCache> layout;             // its frames' view, once asked for
  std::shared_ptr<LayoutCache> turned_layout;      // that of the camera last turned in the page
  Json camera;                                     // a 3D scene's camera (camera_json), else null
  Json handles = Json::array();                    // --edit: its handles (scene_edit.hpp)
  Json views = Json::array();                      // --edit: each panel's view (views_json)
};

class LiveScenes {
 public:
  explicit LiveScenes(const Settings& settings);

  // Renders scene i from its file; keeps the last good figure when it fails.
  // Says on the log what became of a save (`saved`), and any error.
  void render(std::size_t i, bool saved = false);

  // The terminal's log: one line per save, error, edit and refusal (none until set).
  void set_log(std::ostream* log) { log_ = log; }
  // Writes "pita: LINE" to the log, one line at a time across threads.
  void say(const std::string& line);

  std::vector<fs::path> watched();

  // The scenes whose files are among `saved`.
  std::vector<std::size_t> scenes_of(const std::set<fs::path>& saved);

  Json scenes_json();

  // The last good figure, or its frame at `at`; with `turn`, those of the
  // scene with its camera turned (turned_scene: throws CameraRefused for a
  // scene of the plane).
  std::optional<std::string> figure(std::size_t i, std::optional<double> at,
                                    const std::optional<CameraTurn>& turn = std::nullopt);

  std::optional<std::string> measures(std::size_t i);

  // The animated SVG of the last good figure, as `pita animate -o OUT.svg`
  // writes it (made once per good save, when first asked for); nullopt
  // without a good figure. Throws animate::AnimationError when the scene has
  // no animation, or its SVG would exceed an animation's work or
  // kMaxPageAnimationBytes, and what drawing throws.
  std::optional<std::string> animation(std::size_t i);

  // The bytes `pita render SCENE [--at t] -o OUT.svg|.png` writes for the
  // last good figure; nullopt without one. Throws what rendering throws.
  // With `turn`, of the scene with that camera written in.
  std::optional<std::string> export_figure(std::size_t i, std::optional<double> at, render::Format format,
                                           const std::optional<CameraTurn>& turn = std::nullopt);

  // Waits (at most `wait`) for a render newer than `seen`; the versions now.
  std::vector<std::uint64_t> versions_after(const std::vector<std::uint64_t>& seen, std::chrono::milliseconds wait);

  // Applies an edit (edit_request.hpp: a drag, a time, changes) to scene i's file: checks the result as a scene (and
  // draws it) before writing it atomically. Returns the changes that undo
  // it; throws what reading or drawing the result throws, and
  // std::invalid_argument for a request that names no handle or value.
  Json edit(std::size_t i, const Json& request);

  // The figure of the last good state of scene i, drawn in the request's
  // "views" when given (edit_request.hpp), with its "drag" made in memory
  // when given (nothing is written): {"version", "svg", "handles"}, the
  // handles where that figure draws them; nullopt without a good state.
  // Throws as edit does for a drag it would refuse.
  std::optional<Json> preview(std::size_t i, const Json& request);

  // The digest of scene i's file as it is now (FNV-1a, hexadecimal), "" when it cannot be read;
  // scenes_json gives each good state's as "digest".
  std::string file_digest(std::size_t i) const;

  void stop();
  bool stopping();
  std::size_t size() const { return scenes_.size(); }

 private:
  // How the scene files are read (--allow-absolute-paths).
  scene::ReadOptions read_options() const {
    scene::ReadOptions options;
    options.allow_absolute_paths = settings_.allow_absolute_paths;
    return options;
  }

  // The scene of the last good state of scene i and its frames' view (made
  // once per good state, when first asked for; with `turn`, the turned
  // scene's, made once per camera); a null scene without one.
  std::pair<std::shared_ptr<const scene::Scene>, std::shared_ptr<const std::vector<render::PanelPlacement>>>
  frame_layout(std::size_t i, const std::optional<CameraTurn>& turn = std::nullopt);

  const Settings& settings_;
  std::vector<std::unique_ptr<SceneState>> scenes_;
  std::mutex mutex_;
  std::mutex edit_mutex_;  // one edit of the files at a time
  std::mutex log_mutex_;
  std::ostream* log_ = nullptr;
  std::condition_variable changed_;
  bool stopping_ = false;
};

}  // namespace pita::serve
