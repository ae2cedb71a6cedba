// "guesses" in an arrow scene (Sec. 6.1, 6.3; Figs. 16, 18): drawn arrows
// against the frames at their times, with the measures asked for.
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "analysis/arrow_distance.hpp"
#include "core/discrepancy.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

// "guesses" (Sec. 6.1, 6.3; Figs. 16, 18): each drawn arrow G at its time t,
// the frame D(t) under it, and per measure shown a line
//   "E(L, D(2)) = 0.0123"  (PITA Eq. 47 as corrected, docs/paper-notes.md N5)
//   "d(L, D(2)) = 0.42"    (max(|dp|, |dq|), docs/paper-notes.md N53).
void PanelBuilder::add(const scene::GuessesLayer& layer) {
  std::vector<LegendEntry> lines;
  for (std::size_t i = 0; i < layer.guesses.size(); ++i) {
    const scene::Guess& guess = layer.guesses[i];
    const Arrow frame = frames({guess.t}).front();
    const int index = static_cast<int>(i);
    push(index, ArrowShape{frame.p, frame.q(), LineStyle{layer.frame_color, layer.width, 1.0, {}}});
    push(index, ArrowShape{guess.arrow.p, guess.arrow.q(), LineStyle{guess.color, layer.width, 1.0, {}}});
    for (const scene::GuessMeasure measure : layer.show) {
      const bool discrepancy = measure == scene::GuessMeasure::discrepancy;
      const double value =
          discrepancy ? pita::discrepancy(guess.arrow, frame) : analysis::endpoint_distance(guess.arrow, frame);
      if (!std::isfinite(value))
        fail(layer_, fmt::format("the {} of {} is not finite", discrepancy ? "discrepancy" : "distance", guess.name));
      lines.push_back(
          {guess.color, fmt::format("{}({}, D({:g})) = {:.3g}", discrepancy ? "E" : "d", guess.name, guess.t, value)});
    }
  }
  if (selection() == nullptr) add_lines(lines, layer.at, layer.corner, layer.size, layer.color);
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::GuessesLayer& l) {
  add(layer_ + "/guesses", fmt::format("{} guessed arrows", l.guesses.size()),
      static_cast<double>(l.guesses.size()) * (2 * kShapeUnits + motion::frame_cost(panel_)));
}

}  // namespace pita::render::detail
