// Two measures that compare a panel's motion with another motion through
// related keyframes, printed by the "measures" layer (docs/reference/render.md "Figure fields"):
//   - "angle:M@t" (PITA Fig. 5): the angle between the panel's D(t).w and the
//     D(t).w of method M through the same keyframes (0 for -Po against -LP:
//     both take the winding from the same Lagrange blend, Sec. 3.1);
//   - "handle-shift" (PITA Sec. 4.5, Fig. 11): how far the shapes carried by
//     the panel's handle and keyframes land from where the scene's handle and
//     keyframes carry them under the same method (0 for a handle-invariant
//     PITA when the two handles mark the same key-shapes).
#pragma once

#include <cstddef>
#include <optional>

#include "core/pitas/registry.hpp"
#include "motion/stage.hpp"
#include "scene/layers.hpp"

namespace pita::analysis {

// Times at which "handle-shift" compares the carried shapes: dense against
// the patterns the figures draw (9 to 17 frames), cheap (two motions).
inline constexpr int kHandleShiftSamples = 129;

// Below this fraction of the largest keyframe magnitude a frame vector has no
// direction to speak of: rounding alone turns it (P1 passes through a zero
// vector at t = (1 - 1/sqrt 2)/2 for some keyframes, docs/paper-notes.md N66).
inline constexpr double kAngleVectorFloor = 1e-12;

// The largest magnitude of the panel's keyframes (which it must have): the
// scale of kAngleVectorFloor and of analysis/frame_steps.hpp.
double largest_keyframe_magnitude(const scene::Panel& panel);

// The signed angle arg(D_M(t).w / D(t).w) in (-pi, pi] from the frame
// vector of the stage's panel `index` at scene time t to that of `other`
// (the panel's keyframes, options and timing with `other` as the method);
// NaN when either vector is shorter than kAngleVectorFloor times the largest
// keyframe magnitude (the angle is undefined). Throws motion::NoMotion.
double vector_angle(const motion::Stage& stage, std::size_t index, Method other, double t);

// max over kHandleShiftSamples times of [first knot, last knot] and over the
// points of the panel's shapes x of |S(t) x - S0(t) x|, world units, where
// S(t) takes the panel's handle onto the panel's D(t) and S0(t) takes the
// scene's handle onto D0(t), the panel's method (and options, timing) through
// the scene's keyframes (PITA Sec. 4.5; core/carrier.hpp). The panel must
// have shapes (the caller refuses a panel without: there is nothing to
// carry). For the stage's panel `index`. Throws motion::NoMotion.
double handle_shift(const motion::Stage& stage, std::size_t index);

// Two panels of one scene, compared (claims, docs/reference/check.md "Claims"):
// The signed angle arg(D_k(t).w / D(t).w) in (-pi, pi] from the frame vector
// of the stage's panel `index` at scene time t to that of its panel `other`
// (Fig. 19: a tweak that turns a short frame around); NaN when either vector
// is shorter than kAngleVectorFloor (analysis/comparison.hpp) times the
// largest keyframe magnitude of the two. Throws motion::NoMotion.
double panel_angle(const motion::Stage& stage, std::size_t index, std::size_t other, double t);

// Times at which "frame-distance" compares two panels' frames.
inline constexpr int kFrameDistanceSamples = 201;

// max over kFrameDistanceSamples times of the knot range both panels share
// of max(|p - p_k|, |q - q_k|), world units: how far the frames of the
// stage's panel `index` are from those of its panel `other` (Fig. D.37's d);
// for poses, the largest distance between the images of a corner of the
// reference simplex (the triangle, the tetrahedron) under the two motions.
// NaN when the knots share no range. Throws motion::NoMotion (a panel of
// points); 0 for the panel itself. With `at`, the distance at that scene
// time alone ("frame-distance:/panels/K@t"), also outside the knots, where
// both motions extrapolate (Fig. 28's X(1.5)).
double frame_distance(const motion::Stage& stage, std::size_t index, std::size_t other,
                      std::optional<double> at = std::nullopt);

// frame_distance of arrow panels with panel `other`'s frames first carried by
// the similarity that takes its first keyframe (the one of the smallest knot)
// onto the first keyframe of panel `index` ("carried-distance:/panels/K"):
// 0 when the method moves with its keyframes, as P5 does under a translation
// and He-G does not (Fig. C.31's d). NaN when the knots share no range.
// Throws motion::NoMotion (a panel of points or poses).
double carried_distance(const motion::Stage& stage, std::size_t index, std::size_t other);

// frame_distance between two motions of keyframes (a panel's, a layer's).
double frame_distance(const motion::SceneMotion& mine, const motion::SceneMotion& theirs);

// max over the panel's keyframes K of max(|D(t_K).p - K.p|, |D(t_K).q - K.q|),
// world units: 0 (to rounding) when the motion the panel draws interpolates
// its keyframes (Fig. 1), which a timing that moves the knots breaks. For a
// panel of keyframes. Throws motion::NoMotion.
double knot_distance(const motion::Stage& stage, std::size_t index);

// What a "guesses" layer prints for its arrow `guess` (Figs. 16, 18): the
// discrepancy E(G, D(t)) of PITA Eq. 47 (docs/paper-notes.md N5), or the
// distance max(|G.p - D(t).p|, |G.q - D(t).q|) (N53), D(t) the panel's frame
// at the guess's time. Throws motion::NoMotion.
double guess_gap(const motion::Stage& stage, std::size_t index, const scene::Guess& guess, bool discrepancy);

// The same between the stage's panel `index` and `method` (of the panel's
// kind) through the panel's keyframes or poses, options and timing
// ("frame-distance:M": how far P10 pops from P3, Fig. B.30; Fig. 4's mid-way
// poses of SAM and Alexa; 0 for the panel's own method). Throws
// motion::NoMotion when either motion does not exist.
double method_distance(const motion::Stage& stage, std::size_t index, const AnyMethod& method);

}  // namespace pita::analysis
