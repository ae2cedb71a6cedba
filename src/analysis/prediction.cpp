#include "analysis/prediction.hpp"

#include <vector>

#include "core/discrepancy.hpp"
#include "core/keyframe.hpp"
#include "core/steady_morph.hpp"

namespace pita::analysis {

std::optional<Arrow> predict_frame(Predictor predictor, Method method, const MethodOptions& options,
                                   std::span<const double> times, std::span<const Arrow> frames, std::size_t i) {
  switch (predictor) {
    case Predictor::previous:
      if (i < 1) return std::nullopt;
      return frames[i - 1];
    case Predictor::average:
      if (i < 1 || i + 1 >= frames.size()) return std::nullopt;
      return steady_average(frames[i - 1], frames[i + 1]);
    case Predictor::pita: {
      const auto count = static_cast<std::size_t>(info(method).keyframe_count);
      if (i < count) return std::nullopt;
      std::vector<Keyframe> observed;
      for (std::size_t k = i - count; k < i; ++k) observed.push_back({times[k], frames[k]});
      return make_motion(method, observed, options)->at(times[i]);
    }
  }
  return std::nullopt;
}

std::optional<double> frame_discrepancy(Predictor predictor, Method method, const MethodOptions& options,
                                        std::span<const double> times, std::span<const Arrow> frames, std::size_t i) {
  const std::optional<Arrow> predicted = predict_frame(predictor, method, options, times, frames, i);
  if (!predicted) return std::nullopt;
  return discrepancy(frames[i], *predicted);
}

}  // namespace pita::analysis
