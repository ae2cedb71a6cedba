#include "lint/checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "lint/occlusion.hpp"

namespace pita::lint {

namespace {

// Boxes and lines within this many pixels of each other do not count as
// touching: antialiasing and the ink's own rounding.
constexpr double kSlack = 1.0;

bool has_ink(const TextBox& t) { return t.box.width > 0.0 && t.box.height > 0.0; }

std::string quoted(const std::string& text) {
  std::size_t end = std::min(text.find('\n'), std::size_t{40});
  while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;  // whole UTF-8 characters
  std::string shown = text.substr(0, end);
  if (shown.size() < text.size()) shown += "...";
  return "\"" + shown + "\"";
}

std::string hex(const scene::Color& c) { return color_text(c); }

std::string named(const std::string& pointer) { return pointer.empty() ? "the scene" : pointer; }

// The layers whose data lies under the box, in order met. The layer that
// draws the text counts by its strokes only: a text on its own layer's fill
// (a table's cell) is how that layer shows it.
std::vector<std::string> layers_under(const PanelGeometry& panel, const Rect& box, const std::string& owner) {
  std::vector<std::string> layers;
  for (const DataShape& shape : panel.data) {
    if (std::find(layers.begin(), layers.end(), shape.layer) != layers.end()) continue;
    if (render::lies_under(shape, box, shape.layer != owner)) layers.push_back(shape.layer);
  }
  return layers;
}

std::string layer_list(const PanelGeometry& panel, const std::vector<std::string>& layers) {
  std::string out;
  for (std::size_t k = 0; k < layers.size(); ++k) {
    std::string type;
    for (const DataShape& s : panel.data) {
      if (s.layer == layers[k]) {
        type = s.type;
        break;
      }
    }
    out += fmt::format("{}{} ({})", k == 0 ? "" : ", ", layers[k], type.empty() ? "data" : type);
  }
  return out;
}

// How far the box `inner` reaches beyond `outer`, in pixels (0 if within).
double overhang(const Rect& inner, const Rect& outer) {
  return std::max({outer.x - inner.x, inner.x + inner.width - (outer.x + outer.width), outer.y - inner.y,
                   inner.y + inner.height - (outer.y + outer.height), 0.0});
}

void text_overlap(const FigureGeometry& figure, const scene::LintSettings&, std::vector<Finding>& findings) {
  std::vector<const TextBox*> texts;
  for (const TextBox& t : figure.titles) texts.push_back(&t);
  for (const PanelGeometry& panel : figure.panels) {
    for (const TextBox& t : panel.texts) texts.push_back(&t);
  }
  for (std::size_t j = 0; j < texts.size(); ++j) {
    if (!has_ink(*texts[j])) continue;
    for (std::size_t i = 0; i < j; ++i) {
      if (!has_ink(*texts[i]) || !intersects(shrunk(texts[i]->box, kSlack), shrunk(texts[j]->box, kSlack))) continue;
      findings.push_back(
          {"text-overlap", texts[j]->owner,
           fmt::format("the text {} overlaps the text {} of {}", quoted(texts[j]->text), quoted(texts[i]->text),
                       named(texts[i]->owner)),
           std::string("move one of them (a label layer's \"at\", a legend's \"corner\"), shorten a title, or make the "
                       "canvas larger (\"canvas\": \"width\", \"height\")"),
           "", ""});
    }
  }
}

void text_over_data(const FigureGeometry& figure, const scene::LintSettings&, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) {
    for (const TextBox& t : panel.texts) {
      if (t.kind != TextKind::label || !has_ink(t)) continue;
      const std::vector<std::string> layers = layers_under(panel, shrunk(t.box, kSlack), t.owner);
      if (layers.empty()) continue;
      findings.push_back(
          {"text-over-data", t.owner,
           fmt::format("the label {} lies over the data of {} in {}", quoted(t.text), layer_list(panel, layers),
                       panel.name),
           fmt::format("move the label off the data ({}'s \"at\"), or, when the overlap is the point, accept it under "
                       "\"lint\": {{\"allow\": [{{\"check\": \"text-over-data\", \"pointer\": \"{}\", "
                       "\"reason\": ...}}]}}",
                       t.owner, t.owner),
           "", ""});
    }
  }
}

void legend_over_data(const FigureGeometry& figure, const scene::LintSettings&, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) {
    for (const LegendBox& legend : panel.legends) {
      const std::vector<std::string> layers = layers_under(panel, shrunk(legend.box, kSlack), legend.layer);
      if (layers.empty()) continue;
      findings.push_back(
          {"legend-over-data", legend.layer,
           fmt::format("the legend ({:.0f}x{:.0f} px) lies over the data of {} in {}", legend.box.width,
                       legend.box.height, layer_list(panel, layers), panel.name),
           std::string("put the legend in another corner (its \"corner\"), or leave room for it (\"canvas\": "
                       "\"margin\", or a larger \"view\")"),
           "", ""});
    }
  }
}

void outside(const FigureGeometry& figure, const scene::LintSettings&, std::vector<Finding>& findings) {
  for (std::size_t k = 0; k < figure.titles.size(); ++k) {
    const TextBox& t = figure.titles[k];
    const double beyond = overhang(t.box, figure.title_cells[k]);
    if (has_ink(t) && beyond > kSlack) {
      findings.push_back(
          {"outside", t.owner,
           fmt::format("the title {} is {:.0f} px wider than its space ({:.0f} px) and runs {:.0f} "
                       "px beyond it",
                       quoted(t.text), t.box.width - figure.title_cells[k].width, figure.title_cells[k].width, beyond),
           std::string("shorten the title, or widen the canvas (\"canvas\": {\"width\"}) or its columns"), "", ""});
    }
  }
  for (const PanelGeometry& panel : figure.panels) {
    std::map<std::string, Rect> layers;  // each layer's data, united
    std::vector<std::string> order;
    for (const DataShape& s : panel.data) {
      auto [it, inserted] = layers.try_emplace(s.layer, s.bounds);
      if (inserted) {
        order.push_back(s.layer);
      } else {
        it->second = united(it->second, s.bounds);
      }
    }
    for (const std::string& layer : order) {
      const double beyond = overhang(layers[layer], panel.area);
      if (beyond > kSlack) {
        findings.push_back(
            {"outside", layer,
             fmt::format("the data of {} reaches {:.0f} px beyond the edge of {}, where it is cut off", layer, beyond,
                         panel.name),
             std::string("widen the panel's view (\"canvas\": {\"view\": \"auto\"} fits the drawing, or a larger "
                         "{\"min\", \"max\"} box) or its \"margin\""),
             "", ""});
      }
    }
    for (const TextBox& t : panel.texts) {
      const double beyond = overhang(t.box, panel.area);
      if (has_ink(t) && beyond > kSlack) {
        findings.push_back(
            {"outside", t.owner,
             fmt::format("the {} {} reaches {:.0f} px beyond the edge of {}, where it is cut off",
                         t.kind == TextKind::legend ? "legend line" : "label", quoted(t.text), beyond, panel.name),
             std::string("move the text inward (its \"at\" or \"corner\"), or widen the view (\"canvas\": {\"view\"})"),
             "", ""});
      }
    }
  }
}

// A finding when `box` fills less than `least` of the panel's plot area along
// its better-filled side: "<what> fills 21% of its width and 47% of its height
// (less than <setting>, 50%): it could be drawn 2.1 times larger".
void small_box(const PanelGeometry& panel, const Rect& box, double least, const std::string& check,
               const std::string& what, std::string_view setting, std::string fix, std::vector<Finding>& findings) {
  const double share = std::max(box.width / panel.plot.width, box.height / panel.plot.height);
  if (share >= least) return;
  findings.push_back({check, panel.pointer,
                      fmt::format("{} fills {:.0f}% of its width and {:.0f}% of its height (less than {}, {:.0f}%): "
                                  "it could be drawn {:.1f} times larger",
                                  what, 100.0 * box.width / panel.plot.width, 100.0 * box.height / panel.plot.height,
                                  setting, 100.0 * least, 1.0 / share),
                      std::move(fix), "", ""});
}

void small_content(const FigureGeometry& figure, const scene::LintSettings& settings, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) {
    if (panel.data.empty()) continue;
    Rect content{0.0, 0.0, -1.0, -1.0};
    for (const DataShape& s : panel.data) content = united(content, s.bounds);
    for (const TextBox& t : panel.texts) {
      if (t.kind == TextKind::label && has_ink(t)) content = united(content, t.box);
    }
    small_box(panel, content, settings.min_content_share, "small-content", "the content of " + panel.name,
              "min_content_share",
              "fit the view to the content (\"canvas\": {\"view\": \"auto\"}, or a {\"min\", \"max\"} box around "
              "it), make the canvas smaller, or lower \"lint\": {\"min_content_share\"} and say why",
              findings);
  }
}

// The frames alone (patterns, shapes carried to frames): a view fitted to
// other things (the keyframes' centres, a far point, a plot) can leave the
// motion a strip of the panel, while the content as a whole fills it.
void small_motion(const FigureGeometry& figure, const scene::LintSettings& settings, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) {
    Rect motion{0.0, 0.0, -1.0, -1.0};
    for (const DataShape& s : panel.data) {
      if (s.frame) motion = united(motion, s.bounds);
    }
    if (motion.width < 0.0) continue;  // nothing moves in this panel
    small_box(panel, motion, settings.min_motion_share, "small-motion", "the motion of " + panel.name + " (its frames)",
              "min_motion_share",
              "fit the view to the motion (\"canvas\": {\"view\": {\"min\", \"max\"}} around the frames), move "
              "what else the view fits (keyframe centres, far points) into an inset or another panel, or lower "
              "\"lint\": {\"min_motion_share\"} and say why",
              findings);
  }
}

void short_frame(const FigureGeometry& figure, const scene::LintSettings& settings, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) {
    // Each frame's drawn size: a pattern's segment length, else the diagonal of its shapes.
    std::map<std::pair<std::string, int>, Rect> frames;
    std::map<std::pair<std::string, int>, double> lengths;
    std::vector<std::string> order;
    for (const DataShape& s : panel.data) {
      if (!s.frame) continue;
      if (std::find(order.begin(), order.end(), s.layer) == order.end()) order.push_back(s.layer);
      const auto key = std::make_pair(s.layer, s.index);
      auto [it, inserted] = frames.try_emplace(key, s.bounds);
      if (!inserted) it->second = united(it->second, s.bounds);
      if (s.type == "pattern" && s.edges.size() == 1) {
        lengths[key] = std::max(lengths[key], std::abs(s.edges.front().b - s.edges.front().a));
      } else {
        lengths[key] = std::hypot(it->second.width, it->second.height);
      }
    }
    for (const std::string& layer : order) {
      int total = 0, short_ones = 0, shortest_index = -1;
      double shortest = std::numeric_limits<double>::infinity();
      for (const auto& [key, length] : lengths) {
        if (key.first != layer) continue;
        ++total;
        if (length < settings.min_frame_pixels) ++short_ones;
        if (length < shortest) {
          shortest = length;
          shortest_index = key.second;
        }
      }
      if (short_ones == 0) continue;
      findings.push_back(
          {"short-frame", layer,
           fmt::format("{} of the {} frames of {} in {} are drawn shorter than min_frame_pixels "
                       "({:g} px); frame {} is {:.2g} px",
                       short_ones, total, layer, panel.name, settings.min_frame_pixels, shortest_index, shortest),
           std::string(
               "draw fewer, longer frames (fewer \"samples\", a longer handle, or a view closer to the motion), "
               "or lower \"lint\": {\"min_frame_pixels\"}"),
           "", ""});
    }
  }
}

// A claim that two drawn motions differ (a distance above a bound) whose
// distance the figure draws shorter than min_feature_pixels, at the scale of
// the claim's panel (and of the panel it compares with, if smaller).
void small_feature(const FigureGeometry& figure, const scene::LintSettings& settings, std::vector<Finding>& findings) {
  for (const ClaimedDistance& claimed : figure.claimed) {
    if (claimed.panel >= figure.panels.size()) continue;
    const PanelGeometry* panel = &figure.panels[claimed.panel];
    if (claimed.other && *claimed.other < figure.panels.size() && figure.panels[*claimed.other].scale < panel->scale) {
      panel = &figure.panels[*claimed.other];
    }
    const double pixels = claimed.value * panel->scale;
    if (pixels >= settings.min_feature_pixels) continue;
    findings.push_back(
        {"small-feature", claimed.claim,
         fmt::format("{} ({}) is about a distance of {:.3g} in the scene's units, drawn {:.2g} px long in {}: "
                     "shorter than min_feature_pixels ({:g} px)",
                     claimed.claim, quoted(claimed.says), claimed.value, pixels, panel->name,
                     settings.min_feature_pixels),
         std::string("draw it larger: a panel whose \"view\" enlarges where the motions differ, a larger "
                     "\"canvas\", or keyframes that make the difference larger; or lower \"lint\": "
                     "{\"min_feature_pixels\"}"),
         "", ""});
  }
}

void same_color_series(const FigureGeometry& figure, const scene::LintSettings&, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) {
    struct LayerColors {
      std::string type;
      std::map<int, scene::Color> of_index;  // keyframes, poses: the colour of each
      std::map<std::string, int> counts;     // style -> shapes drawn in it
      bool frames = false;
    };
    std::map<std::string, LayerColors> layers;
    std::vector<std::string> order;
    for (const DataShape& s : panel.data) {
      auto [it, inserted] = layers.try_emplace(s.layer);
      if (inserted) {
        order.push_back(s.layer);
        it->second.type = s.type;
      }
      LayerColors& c = it->second;
      c.frames = c.frames || s.frame;
      if (s.index >= 0 && s.stroked) c.of_index.try_emplace(s.index, s.color);
      ++c.counts[s.style];
    }
    // Within a layer that colours its keyframes or poses apart (three colours
    // or more: two would be a highlight, or a role such as "inserted"): two of them alike.
    for (const std::string& layer : order) {
      const LayerColors& c = layers[layer];
      if (c.frames) continue;
      std::map<std::string, std::vector<int>> by_color;
      for (const auto& [index, color] : c.of_index) by_color[hex(color)].push_back(index);
      if (by_color.size() < 3) continue;
      for (const auto& [color, indices] : by_color) {
        if (indices.size() < 2) continue;
        findings.push_back(
            {"same-color", layer,
             fmt::format("{} colours its items apart, and items {} and {} of it in {} are both {}", layer, indices[0],
                         indices[1], panel.name, color),
             fmt::format("give {} one colour per item in its \"colors\" (or remove \"colors\": the default "
                         "series gives any number of keyframes or poses distinct colours)",
                         layer),
             "", ""});
      }
    }
    // Two layers of one kind, each mainly in one style (colour, width, dash): the same one.
    const auto main_color = [](const LayerColors& c) {
      const auto best = std::max_element(c.counts.begin(), c.counts.end(),
                                         [](const auto& a, const auto& b) { return a.second < b.second; });
      return best->first;
    };
    for (std::size_t j = 0; j < order.size(); ++j) {
      for (std::size_t i = 0; i < j; ++i) {
        const LayerColors &a = layers[order[i]], &b = layers[order[j]];
        if (a.type.empty() || a.type != b.type || main_color(a) != main_color(b)) continue;
        findings.push_back({"same-color", order[j],
                            fmt::format("{} and {} are both \"{}\" layers of {} drawn in {}: a reader cannot tell "
                                        "them apart",
                                        order[i], order[j], a.type, panel.name, main_color(a)),
                            fmt::format("give {} another \"color\", \"width\" or \"dash\"", order[j]), "", ""});
      }
    }
  }
}

constexpr std::array<Check, scene::kLintChecks.size()> kChecks = {
    text_overlap, text_over_data, legend_over_data, outside,           small_content,
    small_motion, short_frame,    small_feature,    same_color_series, hidden_copy};

}  // namespace

std::span<const Check> check_functions() { return kChecks; }

}  // namespace pita::lint
