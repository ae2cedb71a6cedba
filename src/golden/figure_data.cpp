#include "golden/figure_data.hpp"

#include <cmath>

#include <fmt/format.h>

#include "golden/image_compare.hpp"
#include "scene/json_text.hpp"

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
  void operator()(const render::ArrowShape& s) const { item["arrow"] = Json::array({point(s.from), point(s.to)}); }
  void operator()(const render::Label& s) const { item["label"] = Json{{"text", s.text}, {"at", point(s.at)}}; }
  // An image by its file's name as the scene gives it and its corners.
  void operator()(const render::Image& s) const {
    const auto corners = render::image_corners(s);
    item["image"] = Json{{"file", s.name}, {"corners", points({corners.begin(), corners.end()})}};
  }
};

// What read_figure_data requires, with the pointer of the first thing wrong.
class DataShape {
 public:
  explicit DataShape(const std::string& file) : file_(file) {}

  void document(const Json& data) const {
    if (!data.is_object()) fail("", "the golden data must be a JSON object");
    const Json& panels = member(data, "", "panels");
    if (!panels.is_array()) fail("/panels", "must be an array of panels");
    for (std::size_t i = 0; i < panels.size(); ++i) panel(panels[i], "/panels/" + std::to_string(i));
  }

 private:
  void panel(const Json& p, const std::string& at) const {
    if (!p.is_object()) fail(at, "a panel must be an object");
    if (!member(p, at, "pointer").is_string()) fail(at + "/pointer", "must be a string");
    const Json& extent = member(p, at, "extent");
    if (!extent.is_number() || !(extent.get<double>() >= 0.0) || !std::isfinite(extent.get<double>())) {
      fail(at + "/extent", "must be a finite number >= 0");
    }
    const Json& items = member(p, at, "items");
    if (!items.is_array()) fail(at + "/items", "must be an array of drawn shapes");
    for (std::size_t k = 0; k < items.size(); ++k) {
      const std::string item_at = at + "/items/" + std::to_string(k);
      const Json& item = items[k];
      if (!item.is_object()) fail(item_at, "a drawn shape must be an object");
      if (const auto layer = item.find("layer"); layer != item.end() && !layer->is_string()) {
        fail(item_at + "/layer", "must be a string");
      }
      if (const auto index = item.find("index"); index != item.end() && !index->is_number_integer()) {
        fail(item_at + "/index", "must be an integer");
      }
    }
  }

  const Json& member(const Json& object, const std::string& at, const char* key) const {
    const auto found = object.find(key);
    if (found == object.end()) fail(at, fmt::format("missing field \"{}\"", key));
    return *found;
  }

  [[noreturn]] void fail(const std::string& pointer, const std::string& reason) const {
    throw GoldenError(scene::located(file_, pointer, reason));
  }

  const std::string& file_;
};

}  // namespace

Json read_figure_data(std::string_view text, const std::string& file) {
  Json data = scene::parse_json(text, file);
  DataShape(file).document(data);
  return data;
}

Json figure_data(const std::string& scene_name, const scene::Scene& scene, const render::Figure& figure) {
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
    text += "{\"pointer\": " + panel.at("pointer").dump() +
            ", \"title\": " + panel.at("title").dump(-1, ' ', false, Json::error_handler_t::replace) +
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
