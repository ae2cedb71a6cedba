// `pita eval` with "timing" (docs/reference/scene-format.md "Timing"): frames keep the scene times
// asked for, a linear timing changes no byte, eased frames are the method's
// frames at the eased times, and the help lists every ease.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

const std::string kKeyframes = R"("method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
    {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2}, {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";

// The shortest text that reads back as x.
std::string fmt_double(double x) { return nlohmann::json(x).dump(); }

class EvalTiming : public ::testing::Test {
 protected:
  RunResult eval(const std::string& extra, const std::vector<std::string>& args) {
    dir.write("scene.json", "{" + kKeyframes + extra + "}");
    std::vector<std::string> all{"eval", "scene.json"};
    all.insert(all.end(), args.begin(), args.end());
    return run_pita(all, dir.path());
  }
  ScratchDir dir;
};

TEST_F(EvalTiming, LinearTimingChangesNoByte) {
  const RunResult plain = eval("", {"--samples", "33"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  for (const std::string timing :
       {R"(, "timing": {})", R"(, "timing": {"ease": "linear"})", R"(, "timing": {"ease": "linear", "per": "span"})",
        R"js(, "timing": {"ease": "cubic-bezier(0, 0, 1, 1)"})js"}) {
    const RunResult timed = eval(timing, {"--samples", "33"});
    ASSERT_EQ(timed.exit_code, 0) << timed.err;
    if (timing.find("cubic") == std::string::npos) {
      EXPECT_EQ(timed.out, plain.out) << timing;
    } else {  // the identity Bezier: equal to rounding
      const auto a = nlohmann::json::parse(plain.out)["frames"], b = nlohmann::json::parse(timed.out)["frames"];
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i]["p"][0].get<double>(), b[i]["p"][0].get<double>(), 1e-12);
      }
    }
  }
}

TEST_F(EvalTiming, EasedFramesAreTheMethodsFramesAtTheEasedTimes) {
  // sine: tau = (1 - cos(pi t)) / 2 on [0, 1]; the frame printed at t is P6's frame at tau.
  const RunResult eased = eval(R"(, "timing": {"ease": "sine"})", {"--t", "0.2,0.5,0.9,1.5"});
  ASSERT_EQ(eased.exit_code, 0) << eased.err;
  const auto frames = nlohmann::json::parse(eased.out)["frames"];
  ASSERT_EQ(frames.size(), 4u);
  std::string taus;
  for (const double t : {0.2, 0.5, 0.9}) taus += (taus.empty() ? "" : ",") + fmt_double((1 - std::cos(M_PI * t)) / 2);
  taus += ",1.5";  // outside the knots: not warped
  const RunResult plain = eval("", {"--t", taus});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto expected = nlohmann::json::parse(plain.out)["frames"];
  const double times[] = {0.2, 0.5, 0.9, 1.5};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(frames[i]["t"].get<double>(), times[i]);  // the scene time asked for
    for (const char* key : {"p", "q"}) {
      for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(frames[i][key][k].get<double>(), expected[i][key][k].get<double>(), 1e-13) << i << key;
      }
    }
  }
}

TEST_F(EvalTiming, CsvAndPoseScenesToo) {
  dir.write("poses.json", R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 2, "matrix": [[2, 0, 4], [0, 2, 0]]}], "timing": {"ease": "ease-in-out", "arc_length": "p"}})");
  const RunResult result = run_pita({"eval", "poses.json", "--samples", "5", "--format", "csv"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.rfind("t,a,b,tx,c,d,ty\n0,", 0), 0u) << result.out;
  EXPECT_NE(result.out.find("\n1,"), std::string::npos);  // t = 1 is printed as asked
}

TEST_F(EvalTiming, ZeroLengthArcLengthExitsTwoWithThePointer) {
  dir.write("still.json", R"({"method": "SMA", "keyframes": [{"t": 0, "p": [1, 1], "m": 1, "w": 0},
      {"t": 1, "p": [1, 1], "m": 2, "w": 1}], "panels": [{"title": "x", "timing": {"arc_length": "p"}}]})");
  const RunResult result = run_pita({"eval", "still.json"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err,
            "pita: still.json: /panels/0/timing/arc_length: cannot pace SMA by the arc length of p: "
            "the path has zero length: the point does not move\n");
}

TEST_F(EvalTiming, HelpListsEveryEase) {
  const RunResult help = run_pita({"eval", "--help"}, dir.path());
  ASSERT_EQ(help.exit_code, 0);
  for (const char* name :
       {"\"linear\"", "\"ease\"", "\"ease-in\"", "\"ease-out\"", "\"ease-in-out\"", "\"sine\"", "\"cubic\"",
        "cubic-bezier(x1, y1, x2, y2)", "{\"sine\": {\"k1\"", "{\"parabolic\": {\"t1\""}) {
    EXPECT_NE(help.out.find(name), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace pita::test
