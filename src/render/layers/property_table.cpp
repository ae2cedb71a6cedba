// "property-table" in an arrow scene (Fig. 10): the properties of Sec. 4
// measured as `pita audit` does, drawn as a table (render/audit_table.hpp).
#include <algorithm>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/decision_tree.hpp"
#include "render/audit_table.hpp"
#include "render/decision_tree.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "scene/did_you_mean.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::PropertyTableLayer& layer) {
  analysis::AuditOptions options;
  options.methods = layer.methods;
  options.configs = layer.configs;
  options.seed = static_cast<std::uint64_t>(layer.seed);
  options.jobs = 1;  // figures are drawn in parallel already
  const analysis::AuditReport report = analysis::run_audit(options);
  const PropertyTable table = property_table(report);
  // The table is laid out with y down; on mathematical axes it is mirrored
  // back so that it reads top to bottom.
  const auto place_at = [&](Point origin, Shape shape) {
    const auto place = [&](Point x) {
      const Point y_down = origin + x;
      return layer.at + (scene_.canvas.y_up ? Point{y_down.real(), -y_down.imag()} : y_down);
    };
    std::visit(
        [&](auto& s) {
          using S = std::decay_t<decltype(s)>;
          if constexpr (std::is_same_v<S, Polyline>) {
            for (Point& x : s.points) x = place(x);
          } else if constexpr (std::is_same_v<S, FilledPath>) {
            for (auto& contour : s.contours)
              for (Point& x : contour) x = place(x);
          } else if constexpr (std::is_same_v<S, Label>) {
            s.at = place(s.at);
          }
        },
        shape);
    push(-1, std::move(shape));
  };
  for (const Item& item : table.drawing.items) place_at({0.0, 0.0}, item.shape);

  // Fig. 10's decision trees, side by side below the table, from the same measurements.
  double x = 20.0;
  for (const scene::DecisionTreeSpec& spec : layer.trees) {
    std::vector<analysis::Property> order;
    for (std::size_t k = 0; k < spec.order.size(); ++k) {
      const analysis::PropertyInfo* property = analysis::find_property(spec.order[k]);
      if (property == nullptr) {
        std::vector<std::string_view> names;
        for (const analysis::PropertyInfo& p : analysis::all_properties()) names.push_back(p.id);
        fail(spec.pointer + "/order/" + std::to_string(k),
             fmt::format("unknown property \"{}\"{}; the properties are {}", spec.order[k],
                         scene::did_you_mean(scene::closest_names(spec.order[k], names)), fmt::join(names, ", ")));
      }
      order.push_back(property->property);
    }
    std::vector<Method> methods = spec.methods;
    if (methods.empty())
      methods = {Method::P1, Method::P2, Method::P3, Method::P4, Method::P5, Method::P6, Method::P7, Method::P8};
    for (std::size_t k = 0; k < methods.size(); ++k) {
      if (std::find(report.methods.begin(), report.methods.end(), methods[k]) == report.methods.end()) {
        fail(spec.methods.empty() ? spec.pointer : spec.pointer + "/methods/" + std::to_string(k),
             fmt::format("{} is not a column of the table (its \"methods\"), so it has no measurements",
                         info(methods[k]).id));
      }
    }
    const TreeDrawing tree =
        draw_decision_tree(analysis::decision_tree(report, methods, order), report, spec.title, scene_.canvas.font);
    for (const Shape& shape : tree.shapes) place_at({x, table.height}, shape);
    x += tree.width + 40.0;
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::PropertyTableLayer& l) {
  // About 10 units (27 us) per property, method and configuration, crafted
  // ones included (pita_bench BM_Audit/1: about 1 s of CPU for 14 x 13 x 208).
  const double methods = l.methods.empty() ? 14.0 : static_cast<double>(l.methods.size());
  add(layer_ + "/configs", fmt::format("{} configurations of a property table", l.configs),
      10.0 * 13.0 * methods * (l.configs + static_cast<double>(analysis::crafted_configs().size())));
}

}  // namespace pita::render::detail
