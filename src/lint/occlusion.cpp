#include "lint/occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include <fmt/format.h>

namespace pita::lint {

namespace {

// What a cell shows last: a drawn thing (a copy, or a pose, a patch's cube:
// one per layer and index).
struct Painter {
  std::string layer;
  int index = -1;
  std::string type;
  bool copy = false;
  Rect bounds = render::empty_rect();
  int painted = 0;  // copies: the cells they ever covered
};

bool is_copy(const DataShape& s) { return s.frame && s.type == "shapes" && !s.areas.empty(); }

bool hides(const DataShape& s) {
  return !s.areas.empty() && s.fill_opacity >= kOpaqueFill && s.layer != "/camera/shadow";
}

bool same_place(const Rect& a, const Rect& b) {
  constexpr double kTolerance = 1.5;  // pixels
  return std::abs(a.x - b.x) <= kTolerance && std::abs(a.y - b.y) <= kTolerance &&
         std::abs(a.x + a.width - b.x - b.width) <= kTolerance &&
         std::abs(a.y + a.height - b.y - b.height) <= kTolerance;
}

std::string what(const Painter& p) {
  return p.copy ? fmt::format("copy {}", p.index) : fmt::format("{} ({} {})", p.layer, p.type, p.index);
}

// The painters of a panel, one per layer and index, in the order first met,
// and which one paints each of its shapes (-1: none that hides).
struct Painters {
  std::vector<Painter> list;
  std::vector<int> of_shape;
  std::vector<int> stands_for;  // a pose drawn where a copy is: that copy
};

Painters painters_of(const PanelGeometry& panel) {
  Painters out;
  out.of_shape.assign(panel.data.size(), -1);
  std::map<std::pair<std::string, int>, int> id_of;
  for (std::size_t k = 0; k < panel.data.size(); ++k) {
    const DataShape& s = panel.data[k];
    if (!hides(s)) continue;
    auto [it, inserted] = id_of.try_emplace(std::make_pair(s.layer, s.index), static_cast<int>(out.list.size()));
    if (inserted) out.list.push_back({s.layer, s.index, s.type, is_copy(s)});
    Painter& p = out.list[static_cast<std::size_t>(it->second)];
    p.bounds = united(p.bounds, s.bounds);
    out.of_shape[k] = it->second;
  }
  // A pose drawn where a copy is (the copy at a pose's knot) stands for it:
  // what it covers of that copy is not hidden.
  out.stands_for.assign(out.list.size(), -1);
  for (std::size_t j = 0; j < out.list.size(); ++j) {
    if (out.list[j].copy) continue;
    for (std::size_t i = 0; i < out.list.size(); ++i) {
      if (out.list[i].copy && same_place(out.list[i].bounds, out.list[j].bounds)) {
        out.stands_for[j] = static_cast<int>(i);
      }
    }
  }
  return out;
}

// The panel painted on a raster of kOcclusionCell cells: who shows last in
// each cell, and which cells each copy ever covered (counted in `painted`).
struct Raster {
  std::vector<int> owner;
  std::vector<std::vector<bool>> covered;  // per painter; empty but for copies
};

Raster paint(const PanelGeometry& panel, Painters& painters) {
  const Rect& area = panel.area;
  const int columns = std::max(1, static_cast<int>(std::ceil(area.width / kOcclusionCell)));
  const int rows = std::max(1, static_cast<int>(std::ceil(area.height / kOcclusionCell)));
  Raster raster{std::vector<int>(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), -1),
                std::vector<std::vector<bool>>(painters.list.size())};
  const auto cell_of = [&](double x, double origin, int most) {
    return std::clamp(static_cast<int>(std::floor((x - origin) / kOcclusionCell)), 0, most - 1);
  };
  for (std::size_t k = 0; k < panel.data.size(); ++k) {
    const int id = painters.of_shape[k];
    if (id < 0) continue;
    const auto at = static_cast<std::size_t>(id);
    const DataShape& s = panel.data[k];
    Painter& p = painters.list[at];
    std::vector<bool>& covered = raster.covered[at];
    if (p.copy && covered.empty()) covered.assign(raster.owner.size(), false);
    const int c0 = cell_of(s.bounds.x, area.x, columns), c1 = cell_of(s.bounds.x + s.bounds.width, area.x, columns);
    const int r0 = cell_of(s.bounds.y, area.y, rows), r1 = cell_of(s.bounds.y + s.bounds.height, area.y, rows);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        const Point centre{area.x + (c + 0.5) * kOcclusionCell, area.y + (r + 0.5) * kOcclusionCell};
        if (std::none_of(s.areas.begin(), s.areas.end(),
                         [&](const std::vector<Point>& contour) { return render::inside(contour, centre); })) {
          continue;
        }
        const std::size_t cell =
            static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c);
        if (p.copy && !covered[cell]) {
          covered[cell] = true;
          ++p.painted;
        }
        int& owner = raster.owner[cell];
        if (painters.stands_for[at] < 0 || owner != painters.stands_for[at]) owner = id;
      }
    }
  }
  return raster;
}

void check_panel(const PanelGeometry& panel, const scene::LintSettings& settings, std::vector<Finding>& findings) {
  Painters painters = painters_of(panel);
  if (std::none_of(painters.list.begin(), painters.list.end(), [](const Painter& p) { return p.copy; })) return;
  const Raster raster = paint(panel, painters);
  // Per layer of copies: how many are hidden, and the worst.
  struct Worst {
    int hidden = 0, total = 0;
    double share = -1.0;
    int copy = -1;
    std::string by;
  };
  std::map<std::string, Worst> layers;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < painters.list.size(); ++i) {
    const Painter& p = painters.list[i];
    if (!p.copy || p.painted == 0) continue;
    std::map<int, int> by;  // who shows in the copy's cells instead
    int seen = 0;
    for (std::size_t cell = 0; cell < raster.owner.size(); ++cell) {
      if (!raster.covered[i][cell]) continue;
      if (raster.owner[cell] == static_cast<int>(i)) {
        ++seen;
      } else {
        ++by[raster.owner[cell]];
      }
    }
    const double share = 1.0 - static_cast<double>(seen) / p.painted;
    if (!layers.contains(p.layer)) order.push_back(p.layer);
    Worst& w = layers[p.layer];
    ++w.total;
    if (share > settings.max_hidden_share) ++w.hidden;
    if (share > w.share) {
      const auto most =
          std::max_element(by.begin(), by.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
      w.share = share;
      w.copy = p.index;
      w.by = most == by.end() || most->first < 0 ? std::string()
                                                 : what(painters.list[static_cast<std::size_t>(most->first)]);
    }
  }
  for (const std::string& layer : order) {
    const Worst& w = layers[layer];
    if (w.hidden == 0) continue;
    findings.push_back(
        {"hidden-copy", layer,
         fmt::format("{} of the {} copies of {} in {} are hidden by more than max_hidden_share ({:.0f}%) of their "
                     "area; copy {} is {:.0f}% hidden{}",
                     w.hidden, w.total, layer, panel.name, 100.0 * settings.max_hidden_share, w.copy, 100.0 * w.share,
                     w.by.empty() ? "" : fmt::format(", mostly by {}", w.by)),
         std::string("turn the camera (\"camera\": {\"azimuth\", \"elevation\"}, or \"auto\": true, which avoids "
                     "hidden copies), draw the poses as outlines (\"fill_opacity\": 0 on the poses layer), or draw "
                     "fewer \"samples\""),
         "", ""});
  }
}

}  // namespace

void hidden_copy(const FigureGeometry& figure, const scene::LintSettings& settings, std::vector<Finding>& findings) {
  for (const PanelGeometry& panel : figure.panels) check_panel(panel, settings, findings);
}

}  // namespace pita::lint
