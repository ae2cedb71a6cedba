#include "golden/figure_data.hpp"

#include <cmath>

namespace pita::golden {

namespace {

Json point(Point p) { return Json::array({p.real(), p.imag()}); }

Json points(const std::vector<Point>& ps) {
  Json out = Json::array();
  for (Point p : ps) out.push_back(point(p));
  return out;
}

struct ItemData {
  Json& item;
  void operator()(const render::Polyline& s) const { item["polyline"] = points(s.points); }
  void operator()(const render::FilledPath& s) const {
    Json contours = Json::array();
    for (const auto& c : s.contours) contours.push_back(points(c));
    item["filled"] = std::move(contours);
  }
  void operator()(const render::Circle& s) const {
    item["circle"] = Json{{"center", point(s.center)}, {"radius", s.radius}};
  }
  void operator()(const render::ArrowShape& s) const {
    item["arrow"] = Json::array({point(s.from), point(s.to)});
  }
  void operator()(const render::Label& s) const {
    item["label"] = Json{{"text", s.text}, {"at", point(s.at)}};
  }
};

}  // namespace

Json figure_data(const std::string& scene_name, const scene::Scene& scene,
                 const render::Figure& figure) {
  Json panels = Json::array();
  for (std::size_t i = 0; i < figure.drawings.size(); ++i) {
    const render::Drawing& drawing = figure.drawings[i];
    double extent = 0.0;
    if (const auto box = render::bounds(drawing)) extent = std::abs(box->max - box->min);
    Json items = Json::array();
    for (const render::Item& item : drawing.items) {
      Json data{{"layer", item.layer}, {"index", item.index}};
      std::visit(ItemData{data}, item.shape);
      items.push_back(std::move(data));
    }
    panels.push_back(Json{{"pointer", scene.panels[i].pointer},
                          {"title", scene.panels[i].title},
                          {"extent", extent},
                          {"items", std::move(items)}});
  }
  return Json{{"scene", scene_name}, {"panels", std::move(panels)}};
}

std::string figure_data_text(const Json& data) {
  std::string text = "{\"scene\": " + data.at("scene").dump() + ", \"panels\": [\n";
  const Json& panels = data.at("panels");
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Json& panel = panels[i];
    text += "{\"pointer\": " + panel.at("pointer").dump() + ", \"title\": " +
            panel.at("title").dump(-1, ' ', false, Json::error_handler_t::replace) +
            ", \"extent\": " + panel.at("extent").dump() + ", \"items\": [\n";
    const Json& items = panel.at("items");
    for (std::size_t k = 0; k < items.size(); ++k) {
      text += "  " + items[k].dump(-1, ' ', false, Json::error_handler_t::replace);
      text += k + 1 < items.size() ? ",\n" : "\n";
    }
    text += i + 1 < panels.size() ? "]},\n" : "]}\n";
  }
  return text + "]}\n";
}

}  // namespace pita::golden
