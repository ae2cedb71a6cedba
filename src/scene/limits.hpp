// Every limit on what a scene may ask for, in one place. Each error that
// enforces one names the field (its JSON Pointer) and the bound, and
// schema/scene.schema.json states the same bounds (tests/scene/test_limits.cpp
// checks both sides of each). They keep every figure and evaluation within
// bounded memory and time while leaving room far beyond the papers' figures.
#pragma once

#include <cstddef>

namespace pita::scene {

// ---------------------------------------------------------------- files

// A scene file's size: the largest legitimate scene (64 shapes of 10 000
// points) is about 25 MB of JSON.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{32} << 20;
// Arrays and objects inside one another: scenes need about 8 levels. Checked
// before the document is built (json_text.cpp), also for golden data files.
inline constexpr std::size_t kMaxJsonDepth = 256;

// ---------------------------------------------------------------- evaluation

// Uniformly spaced samples ("samples" in a scene, --samples on the command
// line), and the default when neither is given.
inline constexpr int kMinSamples = 2;
inline constexpr int kMaxSamples = 1'000'000;
// `pita eval`'s work: frames printed times what one frame costs in frames of
// a plain method (motion::frame_cost; a neville chain over 64 keyframes costs
// about 1950), at most this many (about 6 s on one core).
inline constexpr double kMaxEvalWork = 1e8;
inline constexpr int kDefaultSamples = 9;
// `pita eval --batch`: a request line of at most 32 MiB (a --t list of a
// million times fits), at most 100 000 requests, and requests taken while the
// batch's work is at most 100 times one evaluation's limit (about 10 min).
inline constexpr std::size_t kMaxBatchLineBytes = std::size_t{32} << 20;
inline constexpr std::size_t kMaxBatchRequests = 100'000;
inline constexpr double kMaxBatchWork = 100 * kMaxEvalWork;

// Keyframe values. Knots, coordinates and magnitudes beyond 1e100 (or
// magnitudes below 1e-100) leave the methods no room before their
// intermediate numbers overflow; windings beyond 1e6 rad (~159 000 turns) lose
// the angle's precision in w + 2 pi k.
inline constexpr double kMaxKeyframeValue = 1e100;
inline constexpr double kMinMagnitude = 1e-100;
inline constexpr double kMaxWinding = 1e6;

// Pose scenes: entries of matrices and coordinates within kMaxKeyframeValue;
// at most this many poses.
inline constexpr int kMaxPoses = 1000;
// 3D scenes: solids ("shapes") and their sizes; the faces drawn per figure
// (each frame of each layer draws every face of every solid) are bounded by
// the render budget's frames.
inline constexpr int kMaxSolids = 64;
inline constexpr int kMaxSolidVertices = 10'000;
inline constexpr int kMaxSolidFaces = 10'000;
// The camera of a 3D scene: its azimuth within +-kMaxCameraAzimuth degrees
// (a turn either way), its elevation within +-kMaxCameraElevation (straight
// down to straight up).
inline constexpr double kMaxCameraAzimuth = 360.0;
inline constexpr double kMaxCameraElevation = 90.0;
// Arrow scenes: keyframes of a track (the chains of core/chains/chain.hpp;
// "neville" takes at most limits::kMaxNevilleKeyframes of them).
inline constexpr int kMaxKeyframes = 1000;
// "points" (the PITA curve through them chains kMaxKeyframes edge arrows).
inline constexpr int kMinPoints = 4;
inline constexpr int kMaxPoints = kMaxKeyframes + 1;

// ---------------------------------------------------------------- poses
// The pose reader's numerical tests (scene/pose_reader.cpp). They are
// relative, so that a pose's units do not matter, and the schema cannot state
// them.

// A reference triangle is degenerate when twice its area is at most this
// fraction of the product of its two edges from the first point; a reference
// tetrahedron, when six times its volume is at most this fraction of the
// product of its three edges from the first point.
inline constexpr double kDegenerateSimplex = 1e-12;
// A pose is too close to singular to invert when |det L| is at most this
// fraction of |L|_F^2 (in the plane: about the ratio of its singular values,
// |det| = |L|_F^2 / 2 for a similarity) or of |L|_F^3 (in space). The readers'
// messages quote it ("1e-16", "differ by more than 1e16").
inline constexpr double kSingularPose = 1e-16;
// A 3D pose that fails that test is called singular (it flattens space), not
// only ill-conditioned, when its smallest singular value is at most this
// fraction of its largest.
inline constexpr double kSingularValueRatio = 1e-15;

// ---------------------------------------------------------------- figures

inline constexpr int kMinCanvasSide = 16;    // pixels
inline constexpr int kMaxCanvasSide = 8192;  // pixels, per side
inline constexpr int kMaxColumns = 64;       // "columns" of the panel grid
inline constexpr int kMaxPanels = 64;
inline constexpr int kMaxLayers = 64;                  // per scene or panel
inline constexpr int kMaxClaims = 64;                  // "claims" of a scene
inline constexpr std::size_t kMaxClaimText = 400;      // characters of a claim's "says"
inline constexpr int kMaxFigureSamples = 10'000;       // frames of a drawn pattern, stroke, banner
inline constexpr int kMaxTrajectorySamples = 100'000;  // points of a trajectory, path or plot
inline constexpr int kDefaultFigureSamples = 17;       // frames of a pattern when nothing says
inline constexpr std::size_t kMaxTextLength = 1000;    // characters of a banner or label
inline constexpr std::size_t kMaxDashes = 16;          // lengths of a "dash" pattern
inline constexpr std::size_t kMaxKeyframeColors = 16;  // "colors" of a keyframes or poses layer

// Pose layers and shapes.
inline constexpr int kMaxShapes = 64;
inline constexpr int kMaxShapePoints = 10'000;
inline constexpr int kMaxExistenceSide = 4000;            // "columns", "rows" of "existence"
inline constexpr int kMaxExistenceCells = 4'000'000;      // columns x rows of "existence"
inline constexpr int kMaxPatchSide = 100;                 // "columns", "rows" of "patch"
inline constexpr int kMaxSam3dExistenceSteps = 720;       // "steps" of "sam3d-existence"
inline constexpr int kMaxSam3dExistenceSubdivisions = 4;  // "subdivisions" of "sam3d-existence" (1281 axes)

// Images in "shapes" (PITA Sec. 7.1): PNG files of at most this many pixels a
// side (8192 x 8192 x 4 bytes = 256 MiB decoded), at most kMaxImages per list
// of shapes, and at most kMaxImagePixels pixels in all.
inline constexpr int kMaxImageSide = 8192;
// An image file at most 272 MiB: the largest image's 256 MiB of pixels stored
// without compression, with room for its chunks. Larger is refused before it
// is read.
inline constexpr std::size_t kMaxImageFileBytes = std::size_t{272} << 20;
inline constexpr int kMaxImages = 16;
// Pixels of all the images of one list of shapes together: decoded, 4 bytes
// each, once per drawing thread (256 MiB a thread at most).
inline constexpr double kMaxImagePixels = 8192.0 * 8192.0;

// "animation" and `pita animate` (docs/reference/animate.md "Animation").
inline constexpr double kMaxFps = 240.0;
inline constexpr int kMinAnimationFrames = 2;
inline constexpr int kMaxAnimationFrames = 100'000;
inline constexpr double kMaxAnimationDuration = 86'400.0;  // a day of video, in seconds
inline constexpr int kMaxTrail = 100;                      // "trail": earlier frames shown
inline constexpr int kMaxOverlay = 64;                     // "overlay": taus of a static figure

}  // namespace pita::scene
