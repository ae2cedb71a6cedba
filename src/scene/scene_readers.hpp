// The readers of a scene document, one concept per file (internal to
// src/scene/): arrow scenes (arrow_scene_reader.cpp), pose scenes of the
// plane and of space (pose_scene_reader.cpp), panels of both
// (panel_reader.cpp), the golden tolerances (golden_reader.cpp) and the
// tail every scene shares (scene_tail_reader.cpp). scene.cpp parses the text (json_text.cpp)
// and chooses the reader.
#pragma once

#include <string>
#include <vector>

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {

// Whether any of these pose layers draws a motion (every one but
// "existence", "sam3d-existence", "label" and "patch"), so that the panel
// needs poses.
bool needs_motion(const std::vector<PoseLayer>& layers);

// A pose scene has "poses", or a pose method such as "SAM" and no "keyframes".
bool is_pose_scene(const Json& document);

Scene read_arrow_scene(const JsonReader& reader, const Json& document);
Scene read_pose_scene(const JsonReader& reader, const Json& document);

// "panels" of an arrow scene (each a method name or an object) and of a pose scene.
std::vector<Panel> read_panels(const JsonReader& reader, const Json& value, const std::string& pointer,
                               const Scene& scene);
std::vector<Panel> read_pose_panels(const JsonReader& reader, const Json& value, const std::string& pointer,
                                    const Scene& scene);

// The chain of keyframes or points checked against their method and the
// track's length (JsonReader::check_chain), failing at `pointer`.
void check_track_chain(const JsonReader& reader, const TrackMethod& track, std::size_t length,
                       const std::string& pointer);
void check_track_chain(const JsonReader& reader, const MotionKeys& keys, const std::string& pointer);

// "golden": {"number_tolerance", "svg_tolerance", "pixel_tolerance", "max_differing"}.
void read_golden(const JsonReader& reader, const Json& value, Scene::GoldenTolerances& out);

// "claims" (scene/claim.hpp), read after the panels: each names a panel by
// its index and a measure the scene's kind has, the kind named by the family
// of its layers (Layer: an arrow scene; PoseLayer: a pose scene).
template <class LayerType>
std::vector<Claim> read_claims(const JsonReader& reader, const Json& value, const Scene& scene);

// "lint": {"min_content_share", "min_motion_share", "min_frame_pixels", "allow": [{"check", "pointer", "reason"}]}.
LintSettings read_lint(const JsonReader& reader, const Json& value);

// What every scene ends with, after its panels (scene_tail_reader.cpp):
// "golden", "claims", "lint" and "animation" (or its default). `moving`:
// whether a keyframe of a panel moves (never in a pose scene). LayerType: the
// family of the scene's layers (Layer: an arrow scene; PoseLayer: a pose scene).
template <class LayerType>
void read_scene_tail(const JsonReader& reader, const Json& document, Scene& scene, bool moving);

}  // namespace pita::scene::detail
