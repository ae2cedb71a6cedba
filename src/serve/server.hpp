// The server of `pita serve` (docs/reference/serve.md): each scene named on
// the command line as a live figure in a local page. A thread waits for saves
// of the scenes and their images (file_watch.hpp) and renders each saved
// scene again as `pita render` does; the page learns of it by server-sent
// events and fetches the new SVG. A bad save keeps the last good figure and
// shows the error. Every request must carry the token printed at start; only
// the fixed routes below are served (no file is served by its path).
//
//   GET /?token=T                      the page (src/serve/page/)
//   GET /api/scenes?token=T            every scene: name, title, version, error, time range, the
//                                      timeline's keys ("keys"); with --edit, the handles and
//                                      each panel's world view ("views")
//   GET /api/figure/N?token=T[&at=t]   scene N's SVG (its animation's frame at t)
//   GET /api/figure/N?token=T&camera=AZ,EL[,DIST]  a 3D scene's figure with its camera turned
//                                      (camera_edit.hpp); 400 with the reason for a bad camera
//   GET /api/measures/N?token=T        scene N's `pita measure --format json`
//   GET /api/animation/N?token=T       scene N's animated SVG (`pita animate -o OUT.svg`'s), made
//                                      once per save; 409 when it has none or it is too large
//   GET /api/export/N?token=T&what=W[&at=t]  a download (Content-Disposition: attachment): W = svg
//                                      or png, the bytes of `pita render [--at t] -o OUT.W`;
//                                      W = animation, those of `pita animate -o OUT.svg`
//   GET /api/events?token=T            server-sent events: {"scene": N, "version": V} per render
//   POST /api/edit/N?token=T           with --edit: a drag of a handle ({"drag": {"panel", "pointer",
//                                      "part", "to": [x, y]}}) or changes ({"changes": [{"pointer",
//                                      "value"}]}, undo and redo; "Save view": /camera/... values,
//                                      added when missing, or {"pointer", "remove": true}), or a
//                                      time moved on the timeline ({"time": {"pointer", "t",
//                                      "step"}}) written into scene N's file (edit_request.hpp);
//                                      a drag may give the "views" the page holds;
//                                      answers {"previous": [...]}, the changes that undo it
//   POST /api/preview/N?token=T        with --edit: {"drag": ..., "views": [...]} (both optional)
//                                      made in memory, nothing written: {"version", "svg",
//                                      "handles"} of the figure in those views, or why refused
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace pita::serve {

struct Settings {
  std::vector<std::filesystem::path> scenes;
  std::string host = "127.0.0.1";
  int port = 8765;    // 0: any free port
  std::string token;  // every request must give it
  bool allow_absolute_paths = false;
  bool edit = false;  // --edit: drags are written into the scene files
  bool open = false;  // --open: the page opened in the browser once served (xdg-open)
};

// One `pita serve`: its scenes, its routes and its HTTP server.
class Service {
 public:
  explicit Service(const Settings& settings);
  ~Service();
  Service(const Service&) = delete;
  Service& operator=(const Service&) = delete;

  // Renders every scene from its file (run does it first).
  void render_all();

  // Serves until `stopped` (as serve()).
  int run(std::ostream& log, const std::function<bool()>& stopped);

  // The bytes of the answer to one request given as bytes, through the
  // same bounds, token check and routes as a request on the socket (the
  // tests, the fuzz target). An event stream sends its head only: its
  // messages flow on a socket of a server that listens.
  std::string answer(std::string_view request);

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

// Serves until `stopped` returns true (it is asked every 100 ms) or a
// request fails to bind. Prints the page's address to `log` once listening.
// Returns 0 when stopped, 3 when the address cannot be bound.
int serve(const Settings& settings, std::ostream& log, const std::function<bool()>& stopped);

}  // namespace pita::serve
