// What `pita serve --edit` lets the page drag, and what a drag writes into
// the scene file: the tail and the tip of each keyframe arrow, and the
// corners of each pose of the plane, as drawn in a panel of the figure.
// A drag becomes changes of JSON values at pointers (json_edit.hpp keeps the
// rest of the file as it is); the result is checked as any scene before it
// is written (server.cpp).
#pragma once

#include <string>
#include <vector>

#include "core/arrow.hpp"
#include "motion/stage.hpp"
#include "render/layout.hpp"
#include "scene/scene.hpp"

namespace pita::serve {

struct Handle {
  std::size_t panel = 0;
  std::string pointer;  // the keyframe or pose: "/keyframes/1", "/panels/2/poses/0"
  std::string part;     // "tail", "tip", "corner0" ... "corner2" ("corner3" in space)
  Point at;             // in canvas pixels (the SVG's user units)
};

// Every handle of the figure's panels, for the scene read from `text` (the
// stage's): a panel that gives its own "keyframes" or "poses" edits those,
// the others the scene's. A pose of space has a handle per corner of the
// reference tetrahedron, where the panel's camera as drawn ("auto"
// included) shows it; none for a corner behind a perspective camera.
// Moving keyframes and timed points have none.
std::vector<Handle> handles(const std::string& text, const motion::Stage& stage,
                            const std::vector<render::PanelPlacement>& placements);

// The value at `pointer` becomes `value` (JSON text), added when the file
// lacks it; or, with `remove`, the member at `pointer` goes (the undo of an
// added one).
struct Change {
  std::string pointer;
  std::string value;
  bool remove = false;
};

// What moving `part` of `pointer`, as drawn in panel `panel`, to the canvas
// point `to` changes in the scene file `text` (the scene read from it):
//   tail: "p"; tip: "q" when the keyframe gives q, else "m" and "w" (the
//   winding moved by less than half a turn, so its turns stay);
//   a corner: that point of "triangle" ("tetrahedron"), else the entries of
//   "matrix" (of the affinity that maps the reference simplex onto the moved
//   one) that changed by more than the drag resolves; the others keep their
//   text. In space the corner moves in the plane through it parallel to the
//   image: along the camera's right and up, at the depth it had.
// Dragged numbers are rounded to a tenth of the pixel (rounded_json; in
// space, of the pixel at the corner's depth).
// Throws std::invalid_argument for a handle the figure does not have.
// Changes a page sends back (undo) are checked by checked_change.
std::vector<Change> drag(const std::string& text, const motion::Stage& stage,
                         const std::vector<render::PanelPlacement>& placements, std::size_t panel,
                         const std::string& pointer, const std::string& part, Point to);

// A change as the page may send it: the pointer names a value a handle
// writes (p, q, m, w, a triangle's or tetrahedron's point, a matrix or one
// of its entries) of a keyframe or pose, or
// the time "t" of a keyframe, point or pose the timeline moves, and the value
// is one JSON value; or it is what "Save view" writes (camera_edit.hpp:
// /camera/azimuth, elevation, distance or auto, within the reader's limits),
// or the undo of it (the camera's object, or one of those removed). Throws
// std::invalid_argument otherwise.
void check_change(const std::string& text, const Change& change);

// The times the timeline shows: each keyframe's, point's or pose's "t", by
// where the keys are given (the scene's "/keyframes", or a panel's own
// "/panels/1/poses"), with the panels that draw them.
struct KeyTime {
  std::string pointer;  // the keyframe, point or pose: "/keyframes/1"
  double t = 0.0;
};
struct KeyRow {
  std::string keys;                 // "/keyframes", "/panels/1/poses"
  std::vector<std::size_t> panels;  // the panels that draw these keys
  std::vector<KeyTime> times;       // in the file's order
};
std::vector<KeyRow> key_rows(const std::string& text, const scene::Scene& scene);

// Moving the time of `pointer` (one of key_rows') to `t`, rounded to the
// decimals that resolve `step` (what the timeline resolves: a pixel of it).
// Whether the times still increase is the scene's own check, when the
// edited text is read. Throws std::invalid_argument for another pointer or
// a t that is not finite.
Change time_change(const std::string& text, const scene::Scene& scene, const std::string& pointer, double t,
                   double step);

// A number as the edits write it: the shortest text that reads back to it.
std::string number_json(double x);

// A dragged number: `x` rounded to the decimals that resolve `step` (what the
// drag resolves: a tenth of a pixel, in the value's units), in its shortest
// text, so that a drag writes 0.827, not 0.8274027248313519.
std::string rounded_json(double x, double step);

}  // namespace pita::serve
