// "property-table" in an arrow scene (Fig. 10): the properties of Sec. 4
// measured as `pita audit` does, drawn as a table (render/property_table.hpp).
#include <utility>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "render/property_table.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::PropertyTableLayer& layer) {
  analysis::AuditOptions options;
  options.methods = layer.methods;
  options.configs = layer.configs;
  options.seed = static_cast<std::uint64_t>(layer.seed);
  options.jobs = 1;  // figures are drawn in parallel already
  const PropertyTable table = property_table(analysis::run_audit(options));
  for (const Item& item : table.drawing.items) {
    // The table is laid out with y down; on mathematical axes it is mirrored
    // back so that it reads top to bottom.
    const auto place = [&](Point x) {
      return layer.at + (scene_.canvas.y_up ? Point{x.real(), -x.imag()} : x);
    };
    Shape shape = item.shape;
    std::visit([&](auto& s) {
      using S = std::decay_t<decltype(s)>;
      if constexpr (std::is_same_v<S, Polyline>) {
        for (Point& x : s.points) x = place(x);
      } else if constexpr (std::is_same_v<S, FilledPath>) {
        for (auto& contour : s.contours) for (Point& x : contour) x = place(x);
      } else if constexpr (std::is_same_v<S, Label>) {
        s.at = place(s.at);
      }
    }, shape);
    push(-1, std::move(shape));
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
