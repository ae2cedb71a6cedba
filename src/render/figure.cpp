#include "render/figure.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>

#include "core/overloaded.hpp"
#include "motion/moving_keyframes.hpp"
#include "motion/stage.hpp"
#include "render/budget.hpp"
#include "render/cairo_handles.hpp"
#include "render/image_cache.hpp"
#include "render/label_placement.hpp"
#include "render/painter.hpp"
#include "render/panel_drawing.hpp"
#include "render/png_writer.hpp"
#include "render/pose_drawing.hpp"

namespace pita::render {

namespace {

constexpr auto append = append_to_string;

bool finite_transform(const ViewTransform& t) {
  return std::isfinite(t.scale) && std::isfinite(t.world_center.real()) && std::isfinite(t.world_center.imag());
}

}  // namespace

void paint_figure(cairo_t* cr, const scene::Scene& scene, const Figure& figure, const FigurePart& part) {
  const scene::Canvas& canvas = scene.canvas;
  if (const auto* rest = std::get_if<RestPart>(&part)) {
    for (std::size_t i = 0; i < figure.drawings.size(); ++i) {
      paint_drawing(cr, figure.drawings[i], figure.placements[i], canvas.font, ItemRange{(*rest->leading)[i]});
    }
    return;
  }
  if (canvas.background) {
    const scene::Color& c = *canvas.background;
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
    cairo_paint(cr);
  }
  if (!scene.title.empty()) {
    const TextPlacement at = scene_title_placement(canvas);
    paint_text(cr, scene.title, canvas.font, kTitleSize, Color{0.05, 0.05, 0.05, 1.0}, at.x, at.y, at.align,
               is_markup(scene.title));
  }
  for (std::size_t i = 0; i < figure.drawings.size(); ++i) {
    const PanelPlacement& place = figure.placements[i];
    const std::string& title = scene.panels[i].title;
    if (!title.empty()) {
      const TextPlacement at = panel_title_placement(place);
      paint_text(cr, title, canvas.font, kPanelTitleSize, Color{0.1, 0.1, 0.1, 1.0}, at.x, at.y, at.align,
                 is_markup(title));
    }
    if (const auto* backdrop = std::get_if<BackdropPart>(&part)) {
      paint_drawing(cr, figure.drawings[i], place, canvas.font, ItemRange{0, (*backdrop->leading)[i], false});
    } else {
      paint_drawing(cr, figure.drawings[i], place, canvas.font);
    }
  }
}

namespace {

void check(cairo_status_t status, const scene::Scene& scene) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw RenderError(scene.path, "", fmt::format("cairo failed: {}", cairo_status_to_string(status)));
  }
}

// cairo numbers SVG surfaces ("surface5") and embedded images ("image176")
// with counters global to the process, so the second figure rendered by one
// process would differ from the same figure rendered alone. Renumber them 1,
// 2, ... in order of appearance. (Text is drawn as glyph outlines, so these
// words followed by digits occur only in cairo's ids.)
// Only where an id is named: after id=" or #, never inside embedded data.
std::string canonical_ids(const std::string& svg, std::string_view kPrefix) {
  std::map<std::string, std::string> renamed;
  std::string out;
  out.reserve(svg.size());
  std::size_t at = 0;
  while (true) {
    const std::size_t found = svg.find(kPrefix, at);
    if (found == std::string::npos) break;
    std::size_t end = found + kPrefix.size();
    while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
    out.append(svg, at, found + kPrefix.size() - at);
    const bool named = (found >= 4 && svg.compare(found - 4, 4, "id=\"") == 0) || (found >= 1 && svg[found - 1] == '#');
    if (named && end > found + kPrefix.size()) {
      const std::string number = svg.substr(found + kPrefix.size(), end - found - kPrefix.size());
      const auto [it, inserted] = renamed.emplace(number, std::to_string(renamed.size() + 1));
      out += it->second;
    }
    at = end;
  }
  out.append(svg, at, std::string::npos);
  return out;
}

}  // namespace

std::string canonical_svg_ids(const std::string& svg) { return canonical_ids(canonical_ids(svg, "surface"), "image"); }

std::optional<Format> format_from_name(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "svg") return Format::svg;
  if (lower == "png") return Format::png;
  if (lower == "pdf") return Format::pdf;
  return std::nullopt;
}

std::string_view extension(Format format) {
  switch (format) {
    case Format::svg:
      return "svg";
    case Format::png:
      return "png";
    case Format::pdf:
      return "pdf";
  }
  return "";
}

std::vector<Drawing> frame_drawings(const scene::Scene& scene, const FrameSelection* selection) {
  if (scene.panels.empty()) throw RenderError(scene.path, "/panels", "a figure needs a panel");
  return frame_drawings(motion::Stage(scene), selection);
}

std::vector<Drawing> frame_drawings(const motion::Stage& stage, const FrameSelection* selection, StaticLayers* cache) {
  const scene::Scene& scene = stage.scene();
  if (scene.panels.empty()) throw RenderError(scene.path, "/panels", "a figure needs a panel");
  std::vector<Drawing> drawings;
  for (std::size_t i = 0; i < stage.size(); ++i) {
    const scene::Panel& panel = stage.panel(i);
    const auto arrows = [&](const auto&) { return panel_drawing(stage, i, selection, cache); };
    Drawing drawing = std::visit(
        overloaded{
            [&](const scene::KeyframeKeys& given) { return arrows(given); },
            [&](const scene::PointKeys& given) { return arrows(given); },
            [&](const scene::PlanePoseKeys&) { return pose_panel_drawing<Affine2>(stage, i, selection, cache); },
            [&](const scene::SpacePoseKeys&) { return pose_panel_drawing<Affine3>(stage, i, selection, cache); }},
        panel.keys);
    if (!is_finite(drawing)) {
      throw RenderError(scene.path, panel.pointer, "the figure has non-finite coordinates (the motion overflows)");
    }
    drawings.push_back(std::move(drawing));
  }
  return drawings;
}

void check_images(const scene::Scene& scene) {
  for (const scene::Panel& panel : scene.panels) {
    for (const scene::ShapeOutline& shape : scene::outlines_of(panel)) {
      if (!shape.image) continue;
      try {
        cached_image(shape.image->path, shape.image->given);
      } catch (const ImageError& error) {  // named by the scene and the image's pointer
        throw RenderError(scene.path, shape.image->pointer, error.what());
      }
    }
  }
}

std::vector<PanelPlacement> checked_layout(const scene::Scene& scene, const std::vector<Drawing>& drawings,
                                           const std::vector<scene::Box>* views) {
  std::vector<PanelPlacement> placements =
      views != nullptr ? layout_in_views(scene, drawings, *views) : layout_panels(scene, drawings);
  for (std::size_t i = 0; i < placements.size(); ++i) {
    if (!finite_transform(placements[i].transform)) {
      throw RenderError(scene.path, scene.panels[i].pointer,
                        "the figure's extent is too large to draw (coordinates overflow)");
    }
  }
  return placements;
}

namespace {

Figure built_figure(const scene::Scene& scene, const motion::Stage* stage, double budget,
                    const std::vector<scene::Box>* views = nullptr) {
  Figure figure;
  if (scene.panels.empty()) throw RenderError(scene.path, "/panels", "a figure needs a panel");
  check_images(scene);
  if (!motion::has_moving_keyframes(scene)) {
    check_budget(scene, estimate_cost(scene), budget);
    // The motions are built after the budget is checked (unless given).
    figure.drawings = stage != nullptr ? frame_drawings(*stage, nullptr) : frame_drawings(scene, nullptr);
  } else {
    // Moving keyframes (Sec. 7.4, Fig. 27): the figure overlays the pattern
    // at each tau of "overlay", in order; the legends are drawn once.
    const std::vector<double>& overlay = scene.animation.overlay;
    for (std::size_t k = 0; k < overlay.size(); ++k) {
      const scene::Scene at = motion::scene_at(scene, overlay[k]);
      if (k == 0) check_budget(scene, estimate_cost(scene), budget);  // all the overlaid copies
      std::vector<Drawing> drawings = frame_drawings(at, nullptr);
      if (k == 0) {
        figure.drawings = std::move(drawings);
        continue;
      }
      for (std::size_t i = 0; i < drawings.size(); ++i) {
        for (Item& item : drawings[i].items) figure.drawings[i].items.push_back(std::move(item));
      }
    }
  }
  figure.placements = checked_layout(scene, figure.drawings, views);
  place_labels(scene, figure.drawings, figure.placements);
  return figure;
}

}  // namespace

Figure build_figure(const scene::Scene& scene, double budget) { return built_figure(scene, nullptr, budget); }

Figure build_figure(const motion::Stage& stage, double budget) { return built_figure(stage.scene(), &stage, budget); }

Figure build_figure_in_views(const motion::Stage& stage, const std::vector<scene::Box>& views, double budget) {
  return built_figure(stage.scene(), &stage, budget, &views);
}

std::pair<int, int> checked_png_size(const scene::Scene& scene, const Figure& figure, double scale, double budget) {
  const double width = scene.canvas.width, height = scene.canvas.height;
  const double w = std::round(width * scale), h = std::round(height * scale);
  if (!(scale >= kMinScale && scale <= kMaxScale) || w > kMaxPngSide || h > kMaxPngSide) {
    throw RenderError(scene.path, "/canvas",
                      fmt::format("a PNG of {}x{} pixels at scale {} exceeds the limit of {} "
                                  "pixels per side",
                                  width, height, scale, kMaxPngSide));
  }
  check_pixel_budget(scene, scale, budget);
  check_ink_budget(scene, figure, scale, budget);
  return {static_cast<int>(w), static_cast<int>(h)};
}

std::string encode_png(const scene::Scene& scene, cairo_surface_t* surface) {
  std::string bytes;
  check(write_png(surface, bytes), scene);
  return bytes;
}

std::string render_figure(const scene::Scene& scene, const Figure& figure, Format format, double scale, double budget) {
  const double width = scene.canvas.width, height = scene.canvas.height;
  std::string bytes;
  SurfacePtr surface;
  switch (format) {
    case Format::svg:
      surface.reset(cairo_svg_surface_create_for_stream(append, &bytes, width, height));
      cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
      break;
    case Format::pdf:
      surface.reset(cairo_pdf_surface_create_for_stream(append, &bytes, width, height));
      // A fixed date keeps the output byte-identical from run to run.
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "pita");
      if (!scene.title.empty()) {
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, scene.title.c_str());
      }
      break;
    case Format::png: {
      const auto [w, h] = checked_png_size(scene, figure, scale, budget);
      surface.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
      break;
    }
  }
  check(cairo_surface_status(surface.get()), scene);
  {
    ContextPtr cr(cairo_create(surface.get()));
    if (format == Format::png) cairo_scale(cr.get(), scale, scale);
    paint_figure(cr.get(), scene, figure);
    check(cairo_status(cr.get()), scene);
  }
  if (format == Format::png) bytes = encode_png(scene, surface.get());
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), scene);
  return format == Format::svg ? canonical_svg_ids(bytes) : bytes;
}

}  // namespace pita::render
