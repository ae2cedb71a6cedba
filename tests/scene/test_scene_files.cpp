// The files of the repository that the scene layer reads: the published
// schema (schema/scene.schema.json) and every starter scene (scenes/*.json).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/affine_power.hpp"
#include "core/chains/chain.hpp"
#include "core/pitas/registry.hpp"
#include "core/point_curves.hpp"
#include "core/pose_motion.hpp"
#include "core/steady_morph.hpp"
#include "scene/figure_reader.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::kSourceDir;
using test::read_json;

std::set<std::string> keys_of(const nlohmann::json& object) {
  std::set<std::string> keys;
  for (const auto& [key, value] : object.items()) keys.insert(key);
  return keys;
}

std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kSourceDir / "scenes")) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The schema's definition of a layer kind: "point-trajectory" is described
// by "pointTrajectoryLayer".
std::string layer_definition(const std::string& type) {
  std::string camel;
  for (std::size_t i = 0; i < type.size(); ++i) {
    if (type[i] == '-' && i + 1 < type.size()) {
      camel += static_cast<char>(std::toupper(static_cast<unsigned char>(type[++i])));
    } else {
      camel += type[i];
    }
  }
  return camel + "Layer";
}

TEST(SceneSchema, IsJsonSchemaDraft07) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  EXPECT_EQ(schema.at("$schema"), "http://json-schema.org/draft-07/schema#");
  EXPECT_EQ(schema.at("type"), "object");
  // Pose scenes (with "poses", or a pose method and no "keyframes") and arrow
  // scenes each have their schema; the other branch's errors never show.
  // Among pose scenes, "dimension": 3 selects the 3D ones.
  EXPECT_EQ(schema.at("then").at("then").at("$ref"), "#/definitions/spacePoseScene");
  EXPECT_EQ(schema.at("then").at("else").at("$ref"), "#/definitions/poseScene");
  EXPECT_EQ(schema.at("definitions").at("spacePoseScene").at("additionalProperties"), false);
  EXPECT_EQ(schema.at("else").at("$ref"), "#/definitions/arrowScene");
  EXPECT_EQ(schema.at("definitions").at("arrowScene").at("additionalProperties"), false);
  EXPECT_EQ(schema.at("definitions").at("poseScene").at("additionalProperties"), false);
  EXPECT_TRUE(schema.contains("definitions"));
  EXPECT_FALSE(schema.contains("$defs"));  // 2019-09 and later; draft 7 says "definitions"
}

// The schema lists exactly the fields the parser accepts (tests/scene/test_scene.cpp
// and test_schema.cpp check that the parser refuses every other one).
TEST(SceneSchema, DescribesExactlyTheAcceptedFields) {
  const nlohmann::json document = read_json(kSourceDir / "schema/scene.schema.json");
  const nlohmann::json& definitions = document.at("definitions");
  const nlohmann::json& schema = definitions.at("arrowScene");
  EXPECT_EQ(keys_of(schema.at("properties")),
            (std::set<std::string>{"$schema", "description", "method", "keyframes", "points", "chain", "samples",
                                   "options", "title", "canvas", "layers", "panels", "golden", "claims", "lint",
                                   "timing", "shapes", "handle", "animation"}));
  // The chains are core/chains/chain.hpp's table, in its order.
  nlohmann::json chains = nlohmann::json::array();
  for (const ChainInfo& about : all_chains()) chains.push_back(std::string(about.name));
  EXPECT_EQ(definitions.at("chain").at("enum"), chains);
  EXPECT_EQ(schema.at("required"), (nlohmann::json{"method"}));
  EXPECT_EQ(schema.at("oneOf"), nlohmann::json::parse(R"([{"required": ["keyframes"]}, {"required": ["points"]}])"));
  // The point curves are core/point_curves.hpp's table, in its order.
  nlohmann::json curves = nlohmann::json::array();
  for (const PointCurveInfo& about : all_point_curves()) curves.push_back(std::string(about.name));
  EXPECT_EQ(definitions.at("pointTrajectoryLayer").at("properties").at("curve").at("enum"), curves);
  const nlohmann::json& keyframe = definitions.at("keyframe");
  EXPECT_EQ(keys_of(keyframe.at("properties")), (std::set<std::string>{"t", "p", "m", "w", "q", "turns"}));
  EXPECT_EQ(keyframe.at("additionalProperties"), false);
  // A handle, and the "from" and "to" of a moving keyframe: a keyframe without its knot.
  const nlohmann::json& arrow = definitions.at("arrow");
  EXPECT_EQ(keys_of(arrow.at("properties")), (std::set<std::string>{"p", "m", "w", "q", "turns"}));
  EXPECT_EQ(arrow.at("additionalProperties"), false);
  EXPECT_EQ(arrow.at("oneOf"), keyframe.at("oneOf"));
  const nlohmann::json& moving = definitions.at("movingKeyframe");
  EXPECT_EQ(keys_of(moving.at("properties")), (std::set<std::string>{"t", "from", "to"}));
  EXPECT_EQ(moving.at("required"), (nlohmann::json{"t", "from", "to"}));
  EXPECT_EQ(moving.at("additionalProperties"), false);
  // "animation": the fields and bounds of animation_reader.cpp and limits.hpp.
  const nlohmann::json& animation = definitions.at("animation");
  EXPECT_EQ(keys_of(animation.at("properties")),
            (std::set<std::string>{"duration", "fps", "frames", "loop", "what", "trail", "overlay"}));
  EXPECT_EQ(animation.at("additionalProperties"), false);
  EXPECT_EQ(animation.at("properties").at("duration").at("maximum"), kMaxAnimationDuration);
  EXPECT_EQ(animation.at("properties").at("fps").at("maximum"), kMaxFps);
  EXPECT_EQ(animation.at("properties").at("frames").at("minimum"), kMinAnimationFrames);
  EXPECT_EQ(animation.at("properties").at("frames").at("maximum"), kMaxAnimationFrames);
  EXPECT_EQ(animation.at("properties").at("trail").at("maximum"), kMaxTrail);
  EXPECT_EQ(animation.at("properties").at("overlay").at("maxItems"), kMaxOverlay);
  EXPECT_EQ(animation.at("properties").at("what").at("enum"), (nlohmann::json{"motion", "pattern"}));
  EXPECT_EQ(schema.at("properties").at("shapes").at("maxItems"), kMaxShapes);
  const nlohmann::json& options = definitions.at("options");
  EXPECT_EQ(keys_of(options.at("properties")),
            (std::set<std::string>{"anchor", "path_mean", "magnitude_mean", "knots", "permutation", "symmetrize"}));
  EXPECT_EQ(options.at("properties").at("permutation").at("enum"),
            (nlohmann::json{"ABC", "ACB", "BAC", "BCA", "CAB", "CBA"}));
  EXPECT_EQ(options.at("additionalProperties"), false);
  const nlohmann::json& samples = schema.at("properties").at("samples");
  EXPECT_EQ(samples.at("minimum"), kMinSamples);
  EXPECT_EQ(samples.at("maximum"), kMaxSamples);

  const nlohmann::json& canvas = definitions.at("canvas");
  EXPECT_EQ(keys_of(canvas.at("properties")),
            (std::set<std::string>{"width", "height", "background", "view", "margin", "y_axis", "columns", "font"}));
  EXPECT_EQ(canvas.at("additionalProperties"), false);
  EXPECT_EQ(canvas.at("properties").at("width").at("minimum"), kMinCanvasSide);
  EXPECT_EQ(canvas.at("properties").at("width").at("maximum"), kMaxCanvasSide);
  EXPECT_EQ(canvas.at("properties").at("height").at("minimum"), kMinCanvasSide);
  EXPECT_EQ(canvas.at("properties").at("height").at("maximum"), kMaxCanvasSide);
  EXPECT_EQ(definitions.at("layers").at("maxItems"), kMaxLayers);
  EXPECT_EQ(schema.at("properties").at("panels").at("minItems"), 1);
  EXPECT_EQ(schema.at("properties").at("panels").at("maxItems"), kMaxPanels);
  EXPECT_EQ(definitions.at("figureSamples").at("maximum"), kMaxFigureSamples);
  EXPECT_EQ(definitions.at("text").at("maxLength"), kMaxTextLength);
  EXPECT_EQ(definitions.at("trajectoryLayer").at("properties").at("samples").at("maximum"), kMaxTrajectorySamples);

  // Every layer kind of the reader's tables (arrow_layer_reader.cpp, pose_layer_reader.cpp), with its fields.
  std::vector<std::string> types;
  for (const detail::LayerKindInfo& kind : detail::arrow_layer_kinds()) {
    const std::string type(kind.type);
    SCOPED_TRACE(type);
    types.push_back(type);
    const nlohmann::json& layer = definitions.at(layer_definition(type));
    EXPECT_EQ(keys_of(layer.at("properties")), std::set<std::string>(kind.fields.begin(), kind.fields.end()));
    EXPECT_EQ(layer.at("additionalProperties"), false);
    EXPECT_EQ(layer.at("properties").at("type").at("const"), type);
  }
  EXPECT_EQ(definitions.at("layer").at("properties").at("type").at("enum"), nlohmann::json(types));
  const nlohmann::json& panel = definitions.at("panel").at("else");
  EXPECT_EQ(keys_of(panel.at("properties")), (std::set<std::string>{"method", "options", "keyframes", "points", "chain",
                                                                    "title", "samples", "layers", "timing", "handle"}));
  EXPECT_EQ(panel.at("additionalProperties"), false);
}

TEST(SceneSchema, DescribesExactlyThePoseSceneFields) {
  const nlohmann::json document = read_json(kSourceDir / "schema/scene.schema.json");
  const nlohmann::json& definitions = document.at("definitions");
  const nlohmann::json& scene = definitions.at("poseScene");
  EXPECT_EQ(keys_of(scene.at("properties")),
            (std::set<std::string>{"$schema", "description", "method", "poses", "reference_triangle", "shapes",
                                   "samples", "title", "canvas", "layers", "panels", "golden", "claims", "lint",
                                   "subdivisions", "timing", "animation", "dimension"}));
  // 3D pose scenes (src/scene/space_pose_reader.cpp's kSpaceSceneFields).
  EXPECT_EQ(keys_of(definitions.at("spacePoseScene").at("properties")),
            (std::set<std::string>{"$schema", "description", "dimension", "method", "poses", "reference_tetrahedron",
                                   "samples", "subdivisions", "timing", "golden", "claims", "lint", "shapes", "camera",
                                   "layers", "title", "canvas", "panels", "animation"}));
  // Their panels (panel_reader.cpp's PosePanelSpace<Affine3>): no shapes, the solids are the scene's.
  EXPECT_EQ(keys_of(definitions.at("spacePosePanel").at("anyOf").at(1).at("properties")),
            (std::set<std::string>{"method", "poses", "title", "samples", "layers", "subdivisions", "timing"}));
  EXPECT_EQ(keys_of(definitions.at("pose").at("properties")), (std::set<std::string>{"t", "matrix", "triangle"}));
  EXPECT_EQ(keys_of(definitions.at("shape").at("properties")),
            (std::set<std::string>{"polygon", "polyline", "triangle", "outline", "image", "box", "color"}));
  std::vector<std::string> methods;
  for (const PoseMethodInfo& method : all_pose_methods()) methods.emplace_back(method.id);
  EXPECT_EQ(definitions.at("poseMethod").at("examples").get<std::vector<std::string>>(), methods);
  std::vector<std::string> types;
  for (const detail::LayerKindInfo& kind : detail::pose_layer_kinds()) {
    const std::string type(kind.type);
    SCOPED_TRACE(type);
    types.push_back(type);
    const nlohmann::json& layer = definitions.at(layer_definition(type));
    EXPECT_EQ(keys_of(layer.at("properties")), std::set<std::string>(kind.fields.begin(), kind.fields.end()));
    EXPECT_EQ(layer.at("additionalProperties"), false);
  }
  EXPECT_EQ(definitions.at("poseLayer").at("properties").at("type").at("enum"), nlohmann::json(types));
  EXPECT_EQ(
      keys_of(definitions.at("posePanel").at("anyOf").at(1).at("properties")),
      (std::set<std::string>{"method", "poses", "shapes", "title", "samples", "layers", "subdivisions", "timing"}));
}

TEST(SceneSchema, ListsEveryMethodForAutocomplete) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  std::vector<std::string> ids;
  for (const MethodInfo& method : all_methods()) ids.emplace_back(method.id);
  EXPECT_EQ(schema.at("definitions").at("method").at("examples").get<std::vector<std::string>>(), ids);
}

TEST(SceneFiles, EveryStarterSceneParses) {
  const std::vector<std::filesystem::path> files = scene_files();
  ASSERT_FALSE(files.empty()) << "no scenes in " << kSourceDir / "scenes";
  for (const std::filesystem::path& path : files) {
    SCOPED_TRACE(path.string());
    Scene scene;
    EXPECT_NO_THROW(scene = load_scene(path));
    EXPECT_FALSE(scene.description.empty());
    // Each names the schema, by a path that resolves from the scene's folder.
    const nlohmann::json document = read_json(path);
    ASSERT_TRUE(document.contains("$schema"));
    const std::filesystem::path schema = path.parent_path() / document["$schema"].get<std::string>();
    EXPECT_TRUE(std::filesystem::exists(schema)) << schema;
  }
}

// figNN-*.json for the PITA paper's figures, sam-figNN-*.json for the SAM
// paper's (pose scenes).
TEST(SceneFiles, NamedAfterTheirFigure) {
  for (const std::filesystem::path& path : scene_files()) {
    std::string name = path.stem().string();
    const bool sam = name.rfind("sam-", 0) == 0;
    if (sam) name = name.substr(4);
    // 3D versions of the SAM paper's figures (docs/paper-notes.md N59): sam-3d-figNN-*.json.
    if (sam && name.rfind("3d-", 0) == 0) name = name.substr(3);
    // The interpolation chapter's figures (Fig. 3.NN), for time warps.
    if (name.rfind("chapter-", 0) == 0) name = name.substr(8);
    // The course project on drawn targets, and keyframe tracks beyond the
    // papers' three keyframes (docs/paper-notes.md N32, N33).
    if (name.rfind("project-", 0) == 0) name = name.substr(8);
    if (name.rfind("tracks-", 0) == 0) name = name.substr(7);
    // Figures that extend the papers, of either kind (the PITAs over affine
    // poses, docs/paper-notes.md N73): ext-figNN-*.json.
    const bool extension = name.rfind("ext-", 0) == 0;
    if (extension) name = name.substr(4);
    // The PITA paper's appendix figures, named by their appendix: appB-fig30-*.json.
    if (name.size() > 5 && name.rfind("app", 0) == 0 && name[3] >= 'A' && name[3] <= 'Z' && name[4] == '-') {
      name = name.substr(5);
    }
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    EXPECT_TRUE(name.size() > 6 && name.rfind("fig", 0) == 0 && digit(name[3]) && digit(name[4]) && name[5] == '-')
        << path.stem() << " is not named figNN-*.json (or sam-, chapter-, project-, tracks-, ext-, appX-figNN-*.json)";
    if (!extension) {
      EXPECT_EQ(is_pose_scene(load_scene(path)), sam)
          << path.stem() << ": pose scenes (SAM paper) and only they are named sam-figNN-*.json (or ext-figNN-*.json)";
    }
  }
}

// The numbers the appendix figures print in their titles, recomputed from
// the panels' motions: max over t in [0, 1] (201 samples) of the larger of
// |dp| and |dq| between two frame functions.
template <class F, class G>
double largest_gap(F&& f, G&& g) {
  double d = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const double t = i / 200.0;
    const Arrow x = f(t), y = g(t);
    d = std::max({d, std::abs(x.p - y.p), std::abs(x.q() - y.q())});
  }
  return d;
}

std::unique_ptr<Motion> panel_motion(const Panel& panel) {
  return make_motion(track_keys(panel).method, arrow_keys(panel).keyframes, track_keys(panel).options,
                     track_keys(panel).chain);
}

bool title_says(const Panel& panel, const std::string& text) { return panel.title.find(text) != std::string::npos; }

// Fig. C.31: translating the keyframes by (6, 0) moves P5 rigidly and changes
// He-G; each right panel prints its change.
TEST(SceneFiles, AppendixC31PrintsTheMeasuredChanges) {
  const Scene scene = load_scene(kSourceDir / "scenes/appC-fig31-homogeneous-origin.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  const Vector shift{6.0, 0.0};
  for (std::size_t i : {0u, 2u}) {
    const Panel& before = scene.panels[i];
    const Panel& after = scene.panels[i + 1];
    ASSERT_EQ(track_keys(before).method, track_keys(after).method);
    for (std::size_t k = 0; k < 3; ++k) {
      ASSERT_EQ(arrow_keys(after).keyframes[k].arrow.p, arrow_keys(before).keyframes[k].arrow.p + shift);
    }
    const auto x = panel_motion(before), y = panel_motion(after);
    const double d = largest_gap([&](double t) { return y->at(t); },
                                 [&](double t) {
                                   Arrow a = x->at(t);
                                   a.p += shift;
                                   return a;
                                 });
    if (track_keys(before).method == Method::P5) {
      EXPECT_LT(d, 1e-12);
      EXPECT_TRUE(title_says(after, "d < 1e-12")) << after.title;
    } else {
      EXPECT_EQ(track_keys(before).method, Method::HeG);
      EXPECT_GT(d, 0.1);
      EXPECT_TRUE(title_says(after, fmt::format("d = {:.2g}", d))) << after.title << " vs " << d;
    }
  }
}

// Fig. D.35: the average of M_ACB and M_BAC is close to M_ABC (e), much closer
// than M_ACB and M_BAC are to each other (f). Each panel overlays the four
// as pattern layers: the panel's own (M_ABC), then three with their options.
TEST(SceneFiles, AppendixD35PrintsHowCloseTheAverageIsToP9) {
  const Scene scene = load_scene(kSourceDir / "scenes/appD-fig35-neville-variants.json");
  ASSERT_EQ(scene.panels.size(), 2u);
  for (const Panel& panel : scene.panels) {
    ASSERT_TRUE(figure_of<KeyframeKeys>(panel).layers.has_value());
    std::vector<MethodOptions> drawn;
    for (const Layer& layer : *figure_of<KeyframeKeys>(panel).layers) {
      if (const auto* pattern = std::get_if<PatternLayer>(&layer)) {
        EXPECT_FALSE(pattern->method.has_value());
        drawn.push_back(pattern->options.over(track_keys(panel).options));
      }
    }
    ASSERT_EQ(drawn.size(), 4u);
    EXPECT_EQ(track_keys(panel).method, Method::NeM);
    EXPECT_EQ(drawn[0].permutation, Permutation::ABC);
    EXPECT_FALSE(drawn[0].symmetrize);
    EXPECT_EQ(drawn[1].permutation, Permutation::ACB);
    EXPECT_EQ(drawn[2].permutation, Permutation::BAC);
    EXPECT_TRUE(drawn[3].symmetrize);
    const auto motion = [&](const MethodOptions& options) {
      return make_motion(track_keys(panel).method, arrow_keys(panel).keyframes, options, track_keys(panel).chain);
    };
    const auto abc = motion(drawn[0]), acb = motion(drawn[1]), bac = motion(drawn[2]), average = motion(drawn[3]);
    // M_ABC is P9, independently of the variant code.
    const auto p9 = make_motion(Method::P9, arrow_keys(panel).keyframes);
    EXPECT_LT(largest_gap([&](double t) { return abc->at(t); }, [&](double t) { return p9->at(t); }), 1e-9);
    const double e = largest_gap([&](double t) { return abc->at(t); }, [&](double t) { return average->at(t); });
    const double f = largest_gap([&](double t) { return acb->at(t); }, [&](double t) { return bac->at(t); });
    EXPECT_LT(e, f / 3.0);
    EXPECT_TRUE(title_says(panel, fmt::format("e = {:.2g}, f = {:.2g}", e, f)))
        << panel.title << " vs " << e << ", " << f;
  }
}

// Fig. D.34: P9's construction. L and R (the right panel's keyframes) are the
// timed SMAs M(a, A, b, B) and M(b, B, c, C) at t = 1/4 (PITA Eq. 20, by core's
// steady_morph, not by the motion stage), and the SMA from L to R at 1/4 is
// P9's D(1/4), as the title prints.
TEST(SceneFiles, AppendixD34BuildsP9FromTwoSteadyMorphs) {
  const Scene scene = load_scene(kSourceDir / "scenes/appD-fig34-p9-construction.json");
  ASSERT_EQ(scene.panels.size(), 4u);  // the fourth draws P9 itself (its claims)
  const Panel &left = scene.panels[0], &middle = scene.panels[1], &right = scene.panels[2];
  ASSERT_EQ(arrow_keys(left).keyframes.size(), 2u);
  ASSERT_EQ(arrow_keys(middle).keyframes.size(), 2u);
  ASSERT_EQ(arrow_keys(right).keyframes.size(), 2u);
  const Keyframe &A = arrow_keys(left).keyframes[0], &B = arrow_keys(left).keyframes[1],
                 &C = arrow_keys(middle).keyframes[1];
  ASSERT_EQ(arrow_keys(middle).keyframes[0].arrow.p, B.arrow.p);
  const double t = A.t + 0.25 * (C.t - A.t);
  const Arrow L = steady_morph(A.t, A.arrow, B.t, B.arrow, t);
  const Arrow R = steady_morph(B.t, B.arrow, C.t, C.arrow, t);
  const auto gap = [](const Arrow& x, const Arrow& y) {
    return std::max({std::abs(x.p - y.p), std::abs(x.q() - y.q()), std::abs(x.w - y.w)});
  };
  EXPECT_LT(gap(arrow_keys(right).keyframes[0].arrow, L), 1e-14);
  EXPECT_LT(gap(arrow_keys(right).keyframes[1].arrow, R), 1e-14);
  EXPECT_EQ(arrow_keys(right).keyframes[0].t, A.t);
  EXPECT_EQ(arrow_keys(right).keyframes[1].t, C.t);
  const std::vector<Keyframe> abc{A, B, C};
  const Arrow p9 = make_motion(Method::P9, abc)->at(t);
  const Arrow built = steady_morph(A.t, L, C.t, R, t);
  EXPECT_LT(gap(built, p9), 1e-12);
  EXPECT_TRUE(title_says(right, "d < 1e-12")) << right.title;
  // And not trivially: L, R and D(1/4) are three different arrows.
  EXPECT_GT(gap(L, p9), 0.1);
  EXPECT_GT(gap(R, p9), 0.1);
}

// Fig. D.37: P6 and P9 are close for the tame configuration, not for the
// challenging one; the P9 panels print d.
TEST(SceneFiles, AppendixD37PrintsTheDistanceBetweenP6AndP9) {
  const Scene scene = load_scene(kSourceDir / "scenes/appD-fig37-p6-versus-p9.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  double tame = 0.0;
  for (std::size_t i : {0u, 2u}) {
    ASSERT_EQ(track_keys(scene.panels[i]).method, Method::P6);
    ASSERT_EQ(track_keys(scene.panels[i + 1]).method, Method::P9);
    const auto p6 = panel_motion(scene.panels[i]), p9 = panel_motion(scene.panels[i + 1]);
    const double d = largest_gap([&](double t) { return p6->at(t); }, [&](double t) { return p9->at(t); });
    EXPECT_TRUE(title_says(scene.panels[i + 1], fmt::format("d = {:.2g}", d)))
        << scene.panels[i + 1].title << " vs " << d;
    if (i == 0)
      tame = d;
    else
      EXPECT_GT(d, 5.0 * tame);
  }
}

// Fig. D.37 for affine poses (ext-fig03): P6 and P9 through a tame triple of
// triangles agree; through a wild one P9 departs from P6 near the ends. Each
// P9 panel prints d, the largest distance between corresponding corners of
// the two motions' reference triangles over t in [0, 1] (201 samples).
TEST(SceneFiles, PosePitasP6AndP9PrintTheirDistance) {
  const Scene scene = load_scene(kSourceDir / "scenes/ext-fig03-p6-p9-affine.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  double tame = 0.0;
  for (std::size_t i : {0u, 2u}) {
    const Panel& panel = scene.panels[i];
    ASSERT_EQ(plane_keys(panel).poses.size(), 3u);
    const PoseMotion p6(PoseMethod::p6, plane_keys(panel).poses);
    const PoseMotion p9(PoseMethod::p9, plane_keys(scene.panels[i + 1]).poses);
    const auto& corners = figure_of<PlanePoseKeys>(scene).reference;
    double d = 0.0, middle = 0.0, t_of_d = 0.0;
    for (int k = 0; k <= 200; ++k) {
      const double t = k / 200.0;
      for (const Point corner : corners) {
        const double gap = std::abs(pita::apply(p6.at(t), corner) - pita::apply(p9.at(t), corner));
        if (gap > d) std::tie(d, t_of_d) = std::pair{gap, t};
        if (k >= 70 && k <= 130) middle = std::max(middle, gap);
      }
    }
    EXPECT_TRUE(title_says(scene.panels[i + 1], fmt::format("d = {:.2g}", d)))
        << scene.panels[i + 1].title << " vs " << d;
    if (i == 0) {
      tame = d;
    } else {
      EXPECT_GT(d, 10.0 * tame);
      EXPECT_TRUE(t_of_d < 0.25 || t_of_d > 0.75) << t_of_d;  // near the ends
      EXPECT_LT(middle, 0.1 * d);                             // and not in the middle
    }
  }
}

// Fig. D.36: P9 with WGM lies between its WAM and WHM variants (the three
// panels; the fourth overlays them).
TEST(SceneFiles, AppendixD36PrintsTheDistancesBetweenTheMeans) {
  const Scene scene = load_scene(kSourceDir / "scenes/appD-fig36-neville-means.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  EXPECT_EQ(track_keys(scene.panels[0]).options.path_mean, MeanKind::arithmetic);
  EXPECT_EQ(track_keys(scene.panels[1]).options.path_mean, MeanKind::geometric);
  EXPECT_EQ(track_keys(scene.panels[2]).options.magnitude_mean, MeanKind::harmonic);
  const auto am = panel_motion(scene.panels[0]), gm = panel_motion(scene.panels[1]), hm = panel_motion(scene.panels[2]);
  const double am_gm = largest_gap([&](double t) { return am->at(t); }, [&](double t) { return gm->at(t); });
  const double gm_hm = largest_gap([&](double t) { return gm->at(t); }, [&](double t) { return hm->at(t); });
  const double am_hm = largest_gap([&](double t) { return am->at(t); }, [&](double t) { return hm->at(t); });
  EXPECT_TRUE(title_says(scene.panels[0], fmt::format("d(WAM, WGM) = {:.2g}", am_gm))) << am_gm;
  EXPECT_TRUE(title_says(scene.panels[3], fmt::format("d(WAM, WHM) = {:.2g}", am_hm))) << am_hm;  // the overlay
  EXPECT_TRUE(title_says(scene.panels[2], fmt::format("d(WGM, WHM) = {:.2g}", gm_hm))) << gm_hm;
  EXPECT_GT(am_hm, std::max(am_gm, gm_hm));
}
// The texts of a pose panel's label layers (the panel's own layers, else the scene's).
std::vector<std::string> label_texts(const Scene& scene, const Panel& panel) {
  std::vector<std::string> texts;
  for (const PoseLayer& layer : layers_of<PoseLayer>(scene, panel).layers) {
    if (const auto* label = std::get_if<LabelLayer>(&layer)) texts.push_back(label->text);
  }
  return texts;
}

bool some_text_has(const std::vector<std::string>& texts, const std::string& part) {
  return std::any_of(texts.begin(), texts.end(),
                     [&](const std::string& text) { return text.find(part) != std::string::npos; });
}

// "-3.000" as the labels print it (a minus sign, three decimals).
std::string printed(double value) {
  std::string text = fmt::format("{:.3f}", value);
  if (text == "-0.000") text = "0.000";
  if (text.front() == '-') text = "\u2212" + text.substr(1);
  return text;
}

// SAM Fig. 4 (docs/paper-notes.md N46): the numbers the figure prints,
// recomputed from the scene's poses with core's SAM and Alexa, against the
// paper's closed forms.
TEST(SceneFiles, SamFig04PrintsItsMeasuredNumbers) {
  const Scene scene = load_scene(kSourceDir / "scenes/sam-fig04-alexa-midway.json");
  ASSERT_EQ(scene.panels.size(), 1u);
  const Panel& panel = scene.panels.front();
  ASSERT_EQ(plane_keys(panel).poses.size(), 2u);
  const Affine2 B = plane_keys(panel).poses[0].pose, C = plane_keys(panel).poses[1].pose;
  const PoseMotion sam(PoseMethod::sam, plane_keys(panel).poses), alexa(PoseMethod::alexa, plane_keys(panel).poses);
  const double middle = 0.5 * (plane_keys(panel).poses[0].t + plane_keys(panel).poses[1].t);
  const Affine2 x_sam = compose(sam.at(middle), inverse(B)), x_alexa = compose(alexa.at(middle), inverse(B));
  const std::optional<Eigen::Vector2d> q = fixed_point(x_sam);
  ASSERT_TRUE(q.has_value());
  const Affine2 sam_squared = compose(compose(x_sam, x_sam), B);
  const Affine2 alexa_squared = compose(compose(x_alexa, x_alexa), B);
  // The paper's closed forms (Sec. 3.3.2).
  EXPECT_LT((*q - Eigen::Vector2d(3.0, -3.0)).norm(), 1e-13);
  EXPECT_LT((sam_squared.b - C.b).norm() + (sam_squared.L - C.L).norm(), 1e-13);
  EXPECT_NEAR(alexa_squared.b.x(), 12.0 * std::sqrt(2.0) / std::numbers::pi, 1e-13);
  EXPECT_NEAR(alexa_squared.b.y(), 0.0, 1e-13);
  EXPECT_LT((alexa_squared.L - Eigen::Matrix2d::Identity()).norm(), 1e-13);
  // Printed as measured.
  const std::vector<std::string> texts = label_texts(scene, panel);
  EXPECT_TRUE(some_text_has(texts, fmt::format("q = ({}, {})", printed(q->x()), printed(q->y()))));
  EXPECT_TRUE(some_text_has(
      texts, fmt::format("X_SAM² ∘ B: translation ({}, {})", printed(sam_squared.b.x()), printed(sam_squared.b.y()))));
  EXPECT_TRUE(some_text_has(texts, fmt::format("X_Alexa² ∘ B: translation ({}, {})", printed(alexa_squared.b.x()),
                                               printed(alexa_squared.b.y()))))
      << printed(alexa_squared.b.x());
}

// SAM Fig. 5 (N46): the barycentre steps the figure prints, at the panel's
// equal time steps: all equal for SAM (a rigid SAM turns about its fixed
// point), uneven for Alexa.
TEST(SceneFiles, SamFig05PrintsItsMeasuredSteps) {
  const Scene scene = load_scene(kSourceDir / "scenes/sam-fig05-sam-vs-alexa.json");
  ASSERT_EQ(scene.panels.size(), 1u);
  const Panel& panel = scene.panels.front();
  ASSERT_EQ(plane_keys(panel).poses.size(), 2u);
  const std::vector<ShapeOutline>& shapes = figure_of<PlanePoseKeys>(panel).shapes;
  ASSERT_EQ(shapes.size(), 1u);  // the reference triangle
  Point centre{0.0, 0.0};
  for (const Point p : shapes.front().points) centre += p;
  centre /= static_cast<double>(shapes.front().points.size());
  const auto steps = [&](PoseMethod method) {
    const PoseMotion motion(method, plane_keys(panel).poses);
    const double t0 = plane_keys(panel).poses[0].t, t1 = plane_keys(panel).poses[1].t;
    std::vector<double> lengths;
    for (int i = 0; i + 1 < panel.samples; ++i) {
      const double a = t0 + (t1 - t0) * i / (panel.samples - 1);
      const double b = t0 + (t1 - t0) * (i + 1) / (panel.samples - 1);
      lengths.push_back(std::abs(pita::apply(motion.at(b), centre) - pita::apply(motion.at(a), centre)));
    }
    return std::pair{*std::min_element(lengths.begin(), lengths.end()),
                     *std::max_element(lengths.begin(), lengths.end())};
  };
  const auto [sam_min, sam_max] = steps(PoseMethod::sam);
  const auto [alexa_min, alexa_max] = steps(PoseMethod::alexa);
  // Steady, and rigid to the 6 decimals of the scene's second triangle (a
  // turn of the first): equal steps to about 1e-6.
  EXPECT_LT(sam_max - sam_min, 1e-5);
  EXPECT_GT(alexa_max, 1.5 * alexa_min);  // not: the caption's uneven spacing
  const std::vector<std::string> texts = label_texts(scene, panel);
  EXPECT_TRUE(some_text_has(texts, fmt::format("SAM: barycentre steps {} to {}", printed(sam_min), printed(sam_max))))
      << printed(sam_min) << " " << printed(sam_max);
  EXPECT_TRUE(
      some_text_has(texts, fmt::format("Alexa: barycentre steps {} to {}", printed(alexa_min), printed(alexa_max))))
      << printed(alexa_min) << " " << printed(alexa_max);
}

// SAM Fig. 7: what panel (a) says and no claim can measure (a claim
// measures a motion that exists): no SAM from F_A to F_C, while the polySAM
// and the bi-arc through the middle pose F_B exist.
TEST(SceneFiles, SamFig07HasNoSamFromFirstToLastPose) {
  const Scene scene = load_scene(kSourceDir / "scenes/sam-fig07-no-sam-biarc.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  const std::vector<TimedPose>& poses = plane_keys(scene.panels.front()).poses;
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_THROW(PoseMotion(PoseMethod::sam, {poses[0], poses[2]}), NoSamBetweenPoses);
  EXPECT_NO_THROW(PoseMotion(PoseMethod::poly_sam, poses));
  EXPECT_NO_THROW(PoseMotion(PoseMethod::biarc_sam, poses));
}

// SAM Fig. 3 (N46): the starting and ending poses of the columns are poses
// of two SAMs, at tau = j/(n-1) for column j.
TEST(SceneFiles, SamFig03PairsArePosesOfTwoSams) {
  const Scene scene = load_scene(kSourceDir / "scenes/sam-fig03-series.json");
  const std::size_t n = scene.panels.size();
  ASSERT_GE(n, 5u);
  const Affine2 P0 = plane_keys(scene.panels.front()).poses[0].pose, P1 = plane_keys(scene.panels.back()).poses[0].pose;
  const Affine2 Q0 = plane_keys(scene.panels.front()).poses[1].pose, Q1 = plane_keys(scene.panels.back()).poses[1].pose;
  const auto distance = [](const Affine2& X, const Affine2& Y) { return (X.L - Y.L).norm() + (X.b - Y.b).norm(); };
  for (std::size_t j = 0; j < n; ++j) {
    const double tau = static_cast<double>(j) / static_cast<double>(n - 1);
    const Panel& panel = scene.panels[j];
    ASSERT_EQ(plane_keys(panel).poses.size(), 2u) << j;
    EXPECT_LT(distance(plane_keys(panel).poses[0].pose, steady_affine_morph(P0, P1, tau)), 1e-10) << "column " << j;
    EXPECT_LT(distance(plane_keys(panel).poses[1].pose, steady_affine_morph(Q0, Q1, tau)), 1e-10) << "column " << j;
    EXPECT_NO_THROW(SteadyAffineMorph(plane_keys(panel).poses[0].pose, plane_keys(panel).poses[1].pose))
        << "column " << j;
  }
}

}  // namespace
}  // namespace pita::scene
