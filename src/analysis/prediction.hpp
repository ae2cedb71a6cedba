// Predicting a frame of a motion from its neighbours (PITA paper Sec. 6.1),
// the predictions the discrepancy measure E (Sec. 6.2, PITA Eq. 47) compares each
// frame with (Fig. 17; docs/paper-notes.md N9).
#pragma once

#include <optional>
#include <span>

#include "core/arrow.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/registry.hpp"
#include "scene/figure.hpp"

namespace pita::analysis {

// previous: D(t_{i-1}); average: the steady average M(D(t_{i-1}), D(t_{i+1}))
// (PITA Eq. 23); pita: the method through the frames just before (three, or two for
// SMA), at t_i (Sec. 7.5). The scene model names them ("predictor").
using Predictor = scene::Predictor;

// The prediction of frames[i] (taken at times[i]), or nullopt where the
// predictor has too few neighbours. `method` and `options` serve the pita
// predictor. Throws what make_motion throws when that motion does not exist.
std::optional<Arrow> predict_frame(Predictor predictor, Method method, const MethodOptions& options,
                                   std::span<const double> times, std::span<const Arrow> frames, std::size_t i);

// E(frames[i], prediction) for each frame, nullopt where there is no prediction.
std::optional<double> frame_discrepancy(Predictor predictor, Method method, const MethodOptions& options,
                                        std::span<const double> times, std::span<const Arrow> frames, std::size_t i);

}  // namespace pita::analysis
