// What a request of `pita serve --edit` asks of a scene file, as changes of
// its text (scene_edit.hpp): a drag of a handle, a time moved on the
// timeline, or changes the page sends back (undo, redo); and the world views
// the page holds while it edits, in which the figure is drawn and a drag is
// read, so that the figure does not refit under the pointer.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "render/layout.hpp"
#include "scene/scene.hpp"
#include "serve/scene_edit.hpp"

namespace pita::serve {

// The request's "views": one world box [xmin, ymin, xmax, ymax] per panel of
// the figure (`panels` of them), finite numbers with xmax > xmin and
// ymax > ymin; nullopt when not given. Throws std::invalid_argument saying
// what is wrong.
std::optional<std::vector<scene::Box>> views_of(const nlohmann::ordered_json& request, std::size_t panels);

// The views the page is told to hold: each panel's world view as `placements`
// draw it. The image plane of an orthographic camera is measured from the
// world's origin here, not from the camera's target (the centre of the
// solids, which a drag of a corner moves): so a held view stays put in space.
nlohmann::ordered_json views_json(const motion::Stage& stage, const std::vector<render::PanelPlacement>& placements);

// The figure as pita render draws it, or in the views given (views_json's:
// each panel's view held, the rest laid out as pita render does).
render::Figure figure_in(const motion::Stage& stage, const std::optional<std::vector<scene::Box>>& views);

// The request's "camera": {"azimuth", "elevation"}, which the page holds
// with the views while it edits a scene whose camera "auto" turns (the
// camera the panels were drawn with when the edit began): the scene with
// that camera (turned_scene, camera_edit.hpp), drawn and read so, since an
// edit could make "auto" turn the view under the pointer; nullopt when the
// request has none. Throws std::invalid_argument (CameraRefused) for
// numbers the scene's camera may not have, or a scene without a camera.
std::optional<scene::Scene> held_camera(const scene::Scene& scene, const nlohmann::ordered_json& request);

// The changes a request makes in `text` (`scene`, read from it):
//   {"drag": {"panel", "pointer", "part", "to": [x, y]}[, "views"][, "camera"]}:
//     the handle moved to the canvas point `to` of the figure drawn in the
//     views (with the camera held);
//   {"time": {"pointer", "t"[, "step"]}}: a keyframe's, point's or pose's time
//     (time_change; step: what the page's timeline resolves);
//   {"changes": [{"pointer", "value"}, ...]}: each checked by check_change.
// Throws std::invalid_argument for what names no handle, time or value,
// nlohmann::json's exceptions for a missing field, and what drawing throws.
std::vector<Change> request_changes(const std::string& text, const scene::Scene& scene,
                                    const nlohmann::ordered_json& request);

// `text` with the changes made, and the changes that undo them (the text
// each replaced, as it was: an undo gives the same bytes back).
struct Applied {
  std::string text;
  nlohmann::ordered_json previous = nlohmann::ordered_json::array();
};
Applied apply_changes(const std::string& text, const std::vector<Change>& changes);

}  // namespace pita::serve
