#include "animate/svg_animation.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "animate/frame.hpp"
#include "render/painter.hpp"
#include "render/panel_drawing.hpp"
#include "render/pango_library.hpp"
#include "render/static_layers.hpp"
#include "text/html.hpp"

namespace pita::animate {

namespace {

using render::Item;
using render::LineStyle;
using render::ViewTransform;

std::string num(double x) {
  if (std::abs(x) < 5e-3) return "0";
  std::string text = fmt::format("{:.2f}", x);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

std::string rgb(const scene::Color& c) {
  const auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

std::string stroke(const LineStyle& line) {
  std::string text = fmt::format(" stroke=\"{}\" stroke-width=\"{}\"", rgb(line.color), num(line.width));
  const double opacity = line.color.a * line.opacity;
  if (opacity < 1.0) text += fmt::format(" stroke-opacity=\"{:.3g}\"", opacity);
  if (!line.dash.empty()) {
    text += " stroke-dasharray=\"";
    for (std::size_t i = 0; i < line.dash.size(); ++i) {
      if (i > 0) text += ',';
      text += num(line.dash[i]);
    }
    text += "\"";
  }
  return text;
}

std::string fill(const scene::Color& color, double opacity) {
  std::string text = fmt::format(" fill=\"{}\"", rgb(color));
  if (color.a * opacity < 1.0) text += fmt::format(" fill-opacity=\"{:.3g}\"", color.a * opacity);
  return text;
}

// Writes the moving items of a frame as SVG elements in canvas pixels,
// mirroring render/painter.cpp (round caps and joins, the same arrowheads).
struct ItemWriter {
  const ViewTransform& view;
  const std::map<std::string, std::string>& image_ids;
  std::string& out;

  std::string path(const std::vector<Point>& points, bool closed) const {
    std::string d;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point p = view(points[i]);
      d += fmt::format("{}{} {}", i == 0 ? "M" : "L", num(p.real()), num(p.imag()));
    }
    if (closed) d += "Z";
    return d;
  }

  void operator()(const render::Polyline& s) const {
    if (s.points.size() < 2) return;
    out += fmt::format("<path d=\"{}\" fill=\"none\"{}/>", path(s.points, s.closed), stroke(s.line));
  }
  void operator()(const render::FilledPath& s) const {
    std::string d;
    for (const auto& contour : s.contours) {
      if (contour.size() >= 3) d += path(contour, true);
    }
    if (d.empty()) return;
    out += fmt::format("<path d=\"{}\"{}{}/>", d, fill(s.fill, s.opacity), s.outline ? stroke(*s.outline) : "");
  }
  void operator()(const render::Circle& s) const {
    const Point c = view(s.center);
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"{}{}/>", num(c.real()), num(c.imag()),
                       num(s.radius * view.scale), s.fill ? fill(*s.fill, s.line.opacity) : " fill=\"none\"",
                       stroke(s.line));
  }
  void operator()(const render::ArrowShape& s) const {
    const Point from = view(s.from), to = view(s.to);
    const double length = std::abs(to - from);
    if (!(length > 0.0)) return;
    const double head = std::max(render::kHeadMin, render::kHeadPerWidth * s.line.width);
    const Point direction = (to - from) / length;
    const double h = std::min(head, length);
    const Point base = to - direction * h;
    const Point shaft_end = base + direction * (0.3 * h);
    const Point side = direction * Point{0.0, 1.0} * (0.4 * h);
    const Point left = base + side, right = base - side;
    out += fmt::format("<path d=\"M{} {}L{} {}\" fill=\"none\"{}/>", num(from.real()), num(from.imag()),
                       num(shaft_end.real()), num(shaft_end.imag()), stroke(s.line));
    out += fmt::format("<path d=\"M{} {}L{} {}L{} {}Z\"{}/>", num(to.real()), num(to.imag()), num(left.real()),
                       num(left.imag()), num(right.real()), num(right.imag()), fill(s.line.color, s.line.opacity));
  }
  void operator()(const render::Label&) const {}  // labels never move
  void operator()(const render::Image& s) const {
    const Affine2 m = render::image_to_canvas(s, view);
    out += fmt::format("<use xlink:href=\"#{}\" transform=\"matrix({:.6g} {:.6g} {:.6g} {:.6g} {:.6g} {:.6g})\"{}/>",
                       image_ids.at(s.path), m.L(0, 0), m.L(1, 0), m.L(0, 1), m.L(1, 1), m.b(0), m.b(1),
                       s.opacity < 1.0 ? fmt::format(" opacity=\"{:.3g}\"", s.opacity) : "");
  }
};

// A cairo SVG document nested as a child element: its XML declaration dropped.
std::string nested(const std::string& svg) {
  const std::size_t start = svg.find("<svg");
  return start == std::string::npos ? std::string() : svg.substr(start);
}

// Cairo's ids ("glyph0-1", "clip1", "surface5", "image7") renamed apart, so
// that the two nested documents do not share an id.
std::string prefixed_ids(std::string svg, const std::string& prefix) {
  for (const std::string_view key : {"id=\"", "href=\"#", "url(#"}) {
    std::size_t at = 0;
    while ((at = svg.find(key, at)) != std::string::npos) {
      at += key.size();
      svg.insert(at, prefix);
    }
  }
  return svg;
}

std::string base64_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const render::PangoLibrary& glib = render::pango();
  gchar* encoded = glib.base64_encode(reinterpret_cast<const guchar*>(bytes.data()), bytes.size());
  std::string text(encoded);
  glib.free(encoded);
  return text;
}

// The figure with only the items that do not move, before (`after` false) or
// after (true) the first moving item of each panel; legends come after.
render::Figure static_part(const render::Figure& frame, bool after) {
  render::Figure part;
  part.placements = frame.placements;
  for (const render::Drawing& drawing : frame.drawings) {
    render::Drawing kept;
    bool seen_moving = false;
    for (const Item& item : drawing.items) {
      seen_moving = seen_moving || item.moving;
      if (!item.moving && seen_moving == after) kept.items.push_back(item);
    }
    if (after) kept.legends = drawing.legends;
    part.drawings.push_back(std::move(kept));
  }
  return part;
}

// The shared geometry: the images (their ids into `image_ids`), and one clip
// rectangle per panel.
std::string svg_defs(const scene::Scene& scene, const std::vector<render::PanelPlacement>& placements,
                     std::map<std::string, std::string>& image_ids) {
  std::string svg = "<defs>\n";
  for (const scene::Panel& panel : scene.panels) {
    for (const scene::ShapeOutline& shape : scene::outlines_of(panel)) {
      if (!shape.image || image_ids.count(shape.image->path)) continue;
      const std::string id = fmt::format("pita-image-{}", image_ids.size());
      image_ids.emplace(shape.image->path, id);
      svg += fmt::format(
          "<image id=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" "
          "xlink:href=\"data:image/png;base64,{}\"/>\n",
          id, shape.image->width, shape.image->height, base64_file(shape.image->path));
    }
  }
  for (std::size_t i = 0; i < placements.size(); ++i) {
    const render::PanelPlacement& place = placements[i];
    svg +=
        fmt::format("<clipPath id=\"pita-clip-{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n",
                    i, num(place.cell.x), num(place.cell.y + place.title.height), num(place.cell.width),
                    num(place.cell.height - place.title.height));
  }
  svg += "</defs>\n";
  return svg;
}

// Frame k of n: its moving items, in a group visible from k/n to (k+1)/n of
// the animation's duration (discrete).
std::string frame_group(const render::Figure& frame, int k, const Timeline& timeline,
                        const std::map<std::string, std::string>& image_ids) {
  const int n = timeline.frames;
  std::string values, times;
  if (k == 0) {
    values = "visible;hidden";
    times = fmt::format("0;{:.6g}", 1.0 / n);
  } else if (k == n - 1) {
    values = "hidden;visible";
    times = fmt::format("0;{:.6g}", static_cast<double>(k) / n);
  } else {
    values = "hidden;visible;hidden";
    times = fmt::format("0;{:.6g};{:.6g}", static_cast<double>(k) / n, static_cast<double>(k + 1) / n);
  }
  std::string svg = fmt::format(
      "<g visibility=\"{}\"><animate attributeName=\"visibility\" values=\"{}\" keyTimes=\"{}\" "
      "dur=\"{:.6g}s\" calcMode=\"discrete\" {}/>",
      k == 0 ? "visible" : "hidden", values, times, timeline.seconds(),
      timeline.loop ? "repeatCount=\"indefinite\"" : "fill=\"freeze\"");
  for (std::size_t i = 0; i < frame.drawings.size(); ++i) {
    std::string items;
    const ItemWriter writer{frame.placements[i].transform, image_ids, items};
    for (const Item& item : frame.drawings[i].items) {
      if (item.moving) std::visit(writer, item.shape);
    }
    if (!items.empty()) {
      svg += fmt::format(
          "<g clip-path=\"url(#pita-clip-{})\" stroke-linecap=\"round\" stroke-linejoin=\"round\">{}</g>", i, items);
    }
  }
  svg += "</g>\n";
  return svg;
}

// Above the frames: the layers drawn after the first that moves, and the
// legends, on a transparent canvas.
std::string above_frames(const scene::Scene& scene, const render::Figure& first) {
  scene::Scene above = scene;
  above.canvas.background.reset();
  above.title.clear();
  for (scene::Panel& panel : above.panels) panel.title.clear();
  return prefixed_ids(nested(render::render_figure(above, static_part(first, true), render::Format::svg)),
                      "pita-above-");
}

}  // namespace

std::string animated_svg(const scene::Scene& scene, const Timeline& timeline, const std::function<void(int)>& progress,
                         const motion::Stage* given, render::StaticLayers* layers) {
  // The motions, built once for the layout and every frame ("pattern" changes
  // the scene per frame).
  std::optional<motion::Stage> stage;
  if (timeline.what != scene::Animation::What::pattern && given == nullptr) stage.emplace(scene);
  const motion::Stage* shared = timeline.what == scene::Animation::What::pattern ? nullptr
                                : given != nullptr                               ? given
                                                                                 : &*stage;
  render::StaticLayers own;  // drawn once for every frame (render/static_layers.hpp)
  if (layers == nullptr) layers = &own;
  const std::vector<render::PanelPlacement> placements = animation_layout(scene, timeline, shared, layers);
  const render::Figure first = frame_figure(scene, timeline, timeline.time(0), placements, shared, layers);
  const int width = scene.canvas.width, height = scene.canvas.height;

  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"{0}px\" height=\"{1}px\" viewBox=\"0 0 {0} {1}\">\n"
      "<title>{2}</title>\n"
      "<desc>pita animate: {3} frames at {4:g} frames per second ({5:g} s), {6}, {7}</desc>\n",
      width, height, text::html_escaped(scene.title.empty() ? scene.path : scene.title), timeline.frames, timeline.fps,
      timeline.seconds(), what_name(timeline.what), timeline.loop ? "looping" : "once");
  std::map<std::string, std::string> image_ids;
  svg += svg_defs(scene, placements, image_ids);

  // Below the frames: background, titles and the layers drawn before the
  // first that moves.
  svg +=
      prefixed_ids(nested(render::render_figure(scene, static_part(first, false), render::Format::svg)), "pita-below-");
  svg += "\n";
  for (int k = 0; k < timeline.frames; ++k) {
    const render::Figure frame =
        k == 0 ? first : frame_figure(scene, timeline, timeline.time(k), placements, shared, layers);
    svg += frame_group(frame, k, timeline, image_ids);
    if (progress) progress(k);
  }
  svg += above_frames(scene, first);
  svg += "\n</svg>\n";
  return svg;
}

}  // namespace pita::animate
