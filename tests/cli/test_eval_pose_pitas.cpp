// `pita eval` on pose scenes with the PITAs over affine poses P4, P5, P6, P9
// (docs/reference/pose-scenes.md, docs/paper-notes.md N73-N79): through the
// three poses in the plane and in space, the arrow PITA of the same name on
// similarity poses (two runs of the binary, one per kind of scene), an affine
// change of frame on the left, the name resolved by the scene's kind, the
// refusal at a time, and tracks past three poses.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;

const std::vector<std::string> kPosePitas = {"P4", "P5", "P6", "P9"};

// Sheared, stretched poses of the plane; neighbours turn by about 1 rad.
const Json kPlanePoses = Json::parse(R"([
  {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
  {"t": 0.7, "matrix": [[0.8, -0.9, 3], [0.7, 1.1, 1]]},
  {"t": 2, "matrix": [[-0.6, -1.2, 5], [1.3, -0.2, 3]]}])");

const Json kSpacePoses = Json::parse(R"([
  {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
  {"t": 1, "matrix": [[0.8, -0.6, 0.1, 2], [0.6, 0.8, 0, 1], [0, 0.2, 1.2, 0]]},
  {"t": 2.5, "matrix": [[0.2, -1.1, 0.3, 4], [1, 0.3, 0, 0], [0, 0.3, 1.4, 1]]}])");

// Arrows (p, m, w) whose neighbours turn by less than pi, and the same as
// similarity poses x -> p + m R(w) x.
const Json kArrows = Json::parse(R"([
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.3},
  {"t": 0.4, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])");

Json similarity_poses(const Json& arrows) {
  Json poses = Json::array();
  for (const Json& a : arrows) {
    const double m = a["m"], w = a["w"], x = a["p"][0], y = a["p"][1];
    poses.push_back(
        {{"t", a["t"]}, {"matrix", {{m * std::cos(w), -m * std::sin(w), x}, {m * std::sin(w), m * std::cos(w), y}}}});
  }
  return poses;
}

class EvalPosePitas : public ::testing::Test {
 protected:
  // The frames of `pita eval SCENE --t TIMES` for the scene `scene`.
  Json frames(const Json& scene, const std::string& times, const std::vector<std::string>& extra = {}) const {
    dir.write("scene.json", scene.dump());
    std::vector<std::string> args = {"eval", "scene.json", "--t", times};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult result = run_pita(args, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.exit_code == 0 ? Json::parse(result.out).at("frames") : Json::array();
  }
  ScratchDir dir;
};

double matrix_distance(const Json& x, const Json& y) {
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = 0; j < x[i].size(); ++j) {
      worst = std::max(worst, std::abs(x[i][j].get<double>() - y[i][j].get<double>()));
    }
  }
  return worst;
}

TEST_F(EvalPosePitas, PassThroughTheirThreePosesInThePlaneAndInSpace) {
  for (const std::string& method : kPosePitas) {
    const Json plane = frames({{"method", method}, {"poses", kPlanePoses}}, "0,0.7,2");
    const Json space = frames({{"dimension", 3}, {"method", method}, {"poses", kSpacePoses}}, "0,1,2.5");
    ASSERT_EQ(plane.size(), 3u);
    ASSERT_EQ(space.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(plane[i]["matrix"], kPlanePoses[i]["matrix"]) << method << " pose " << i;
      EXPECT_EQ(space[i]["matrix"], kSpacePoses[i]["matrix"]) << method << " pose " << i;
    }
  }
}

// The pose PITA on similarity poses is the arrow PITA of the same name: the
// arrow scene's frames (p, m, w) as matrices.
TEST_F(EvalPosePitas, AreTheArrowPitasOnSimilarityPoses) {
  const std::string times = "-0.3,0.1,0.25,0.4,0.55,0.8,1,1.4";
  for (const std::string& method : kPosePitas) {
    const Json arrows = frames({{"method", method}, {"keyframes", kArrows}}, times);
    const Json poses = frames({{"method", method}, {"poses", similarity_poses(kArrows)}}, times);
    ASSERT_EQ(arrows.size(), poses.size()) << method;
    for (std::size_t i = 0; i < arrows.size(); ++i) {
      const Json as_pose = similarity_poses(Json::array({arrows[i]}))[0]["matrix"];
      EXPECT_LT(matrix_distance(poses[i]["matrix"], as_pose), 1e-12) << method << " t " << arrows[i]["t"];
    }
  }
}

// D(G o A, G o B, G o C) = G o D(A, B, C) for P4, P6, P9 (N73); P5 only for
// translations G (N78).
TEST_F(EvalPosePitas, CommuteWithAnAffinityOnTheLeft) {
  const double G[2][3] = {{1.3, 0.4, -2}, {-0.2, 0.9, 1}};
  const auto moved = [&](const Json& matrix) {
    Json out = Json::array();
    for (int i = 0; i < 2; ++i) {
      Json row = Json::array();
      for (int j = 0; j < 3; ++j) {
        double v = j == 2 ? G[i][2] : 0.0;
        for (int k = 0; k < 2; ++k) v += G[i][k] * matrix[k][j].get<double>();
        row.push_back(v);
      }
      out.push_back(row);
    }
    return out;
  };
  Json poses = kPlanePoses;
  for (Json& pose : poses) pose["matrix"] = moved(pose["matrix"]);
  for (const std::string& method : kPosePitas) {
    const Json original = frames({{"method", method}, {"poses", kPlanePoses}}, "0.3,1.1,1.7");
    const Json transformed = frames({{"method", method}, {"poses", poses}}, "0.3,1.1,1.7");
    double worst = 0.0;
    for (std::size_t i = 0; i < original.size(); ++i) {
      worst = std::max(worst, matrix_distance(transformed[i]["matrix"], moved(original[i]["matrix"])));
    }
    if (method == "P5") {
      EXPECT_GT(worst, 1e-3) << method;  // not invariant to a general affinity
    } else {
      EXPECT_LT(worst, 1e-10) << method;
    }
  }
}

TEST_F(EvalPosePitas, TheMethodOptionTakesThePoseMethodInAPoseScene) {
  const Json poly = frames({{"method", "polySAM"}, {"poses", kPlanePoses}}, "1.1");
  const Json p6 = frames({{"method", "P6"}, {"poses", kPlanePoses}}, "1.1");
  for (const char* name : {"P6", "6", "la-lp", "P6:La-LP"}) {
    const Json chosen = frames({{"method", "polySAM"}, {"poses", kPlanePoses}}, "1.1", {"--method", name});
    ASSERT_EQ(chosen.size(), 1u) << name;
    EXPECT_EQ(chosen[0]["matrix"], p6[0]["matrix"]) << name;
  }
  EXPECT_GT(matrix_distance(poly[0]["matrix"], p6[0]["matrix"]), 1e-3);
  // In an arrow scene the same name is the arrow PITA; a pose-only name is refused.
  const Json arrow = frames({{"method", "P1"}, {"keyframes", kArrows}}, "0.5", {"--method", "P6"});
  ASSERT_EQ(arrow.size(), 1u);
  EXPECT_TRUE(arrow[0].contains("w"));
  dir.write("arrows.json", Json({{"method", "P6"}, {"keyframes", kArrows}}).dump());
  const RunResult refused = run_pita({"eval", "arrows.json", "--method", "polySAM"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("method polySAM interpolates poses"), std::string::npos) << refused.err;
}

// A power the construction forms at a time has no real value there: exit 2,
// nothing on stdout, the method, the poses it formed and the time named.
TEST_F(EvalPosePitas, RefusesAtTheTimeAPowerIsMissing) {
  dir.write("wild.json", R"({"method": "P9", "poses": [
    {"t": 0, "matrix": [[1.321, -1.225, 2], [1.01, 0.156, 1]]},
    {"t": 1, "matrix": [[-1.826, -1.237, -3], [0.576, -1.048, -2]]},
    {"t": 2, "matrix": [[0.455, -0.045, -1], [0.934, 1.172, -2]]}]})");
  const RunResult result = run_pita({"eval", "wild.json", "--t", "0.05"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_NE(result.err.find("wild.json: /poses: method P9 (Ne-LP) is undefined at t = 0.05: no SAM exists between "
                            "the poses the construction forms"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("(between M(A, B, q) and M(B, C, r), which P9 morphs at t = 0.05)"), std::string::npos)
      << result.err;
  // Where every power is real the same scene has frames.
  const RunResult later = run_pita({"eval", "wild.json", "--t", "1,2"}, dir.path());
  EXPECT_EQ(later.exit_code, 0) << later.err;
}

// Five poses make a track (the blend chain, N79) through every one.
TEST_F(EvalPosePitas, MoreThanThreePosesMakeATrackThroughEveryPose) {
  Json poses = kPlanePoses;
  poses.push_back(Json::parse(R"({"t": 3, "matrix": [[-1.1, 0.2, 6], [-0.1, -0.9, 5]]})"));
  poses.push_back(Json::parse(R"({"t": 4.5, "matrix": [[-0.5, 1.1, 8], [-1.2, -0.4, 4]]})"));
  for (const std::string& method : kPosePitas) {
    const Json at_knots = frames({{"method", method}, {"poses", poses}}, "0,0.7,2,3,4.5");
    ASSERT_EQ(at_knots.size(), 5u) << method;
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(at_knots[i]["matrix"], poses[i]["matrix"]) << method << " " << i;
  }
}

}  // namespace
}  // namespace pita::test
