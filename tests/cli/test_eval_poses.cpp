// `pita eval` on pose scenes (SAM paper): frames as 2x3 matrices, the method
// override, and the clear refusal when no SAM exists (exit 2).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;

// B = identity, C = rotation by 90 degrees scaled by 2, moved to (3, 1):
// A = C B^-1 = C, whose square root is the rotation by 45 degrees scaled by
// sqrt 2 about A's fixed point q = (I - L)^-1 b.
constexpr const char* kSamScene = R"({
  "method": "SAM",
  "poses": [
    {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
    {"t": 1, "matrix": [[0, -2, 3], [2, 0, 1]]}
  ],
  "samples": 3
})";

constexpr const char* kNoSamScene = R"({
  "method": "SAM",
  "poses": [
    {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
    {"t": 1, "matrix": [[-2, 0, 3], [0, -0.5, 1]]}
  ]
})";

class EvalPoses : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("sam.json", kSamScene);
    dir.write("nosam.json", kNoSamScene);
  }
  RunResult run(const std::vector<std::string>& args) const { return run_pita(args, dir.path()); }
  ScratchDir dir;
};

TEST_F(EvalPoses, FramesAreMatrices) {
  const RunResult result = run({"eval", "sam.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Json document = Json::parse(result.out);
  EXPECT_EQ(document.at("method"), "SAM");
  ASSERT_EQ(document.at("frames").size(), 3u);
  for (const Json& frame : document.at("frames")) {
    std::vector<std::string> keys;
    for (const auto& [key, value] : frame.items()) keys.push_back(key);
    EXPECT_EQ(keys, (std::vector<std::string>{"t", "matrix"}));
  }
  EXPECT_EQ(document["frames"][0]["matrix"], Json::parse("[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]"));
  EXPECT_EQ(document["frames"][2]["matrix"], Json::parse("[[0.0, -2.0, 3.0], [2.0, 0.0, 1.0]]"));
  // The middle frame: sqrt(2) R(45 deg) = [[1, -1], [1, 1]] about q, with
  // (I - L) q = b: [[1, 2], [-2, 1]] q = (3, 1), q = (1/5, 7/5); b_half = q - L_half q.
  const Json& half = document["frames"][1]["matrix"];
  const double qx = 0.2, qy = 1.4;
  const double expected[2][3] = {{1.0, -1.0, qx - (qx - qy)}, {1.0, 1.0, qy - (qx + qy)}};
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 3; ++column) {
      EXPECT_NEAR(half[row][column].get<double>(), expected[row][column], 1e-14) << row << ", " << column;
    }
  }
}

TEST_F(EvalPoses, CsvAndTimes) {
  const RunResult result = run({"eval", "sam.json", "--format", "csv", "--t", "0.5,2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.substr(0, result.out.find('\n')), "t,a,b,tx,c,d,ty");
  // t = 2 extrapolates: A^2 = [L^2 | (I + L) b] = [-4 I | (1, 7)].
  const std::string last = result.out.substr(result.out.rfind('\n', result.out.size() - 2) + 1);
  std::vector<double> values;
  std::size_t start = 0;
  while (start < last.size()) {
    const std::size_t comma = last.find(',', start);
    values.push_back(std::stod(last.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const std::vector<double> expected = {2.0, -4.0, 0.0, 1.0, 0.0, -4.0, 7.0};
  ASSERT_EQ(values.size(), expected.size()) << last;
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_NEAR(values[i], expected[i], 1e-13) << i;
}

TEST_F(EvalPoses, MethodOverride) {
  const RunResult linear = run({"eval", "sam.json", "--method", "linear", "--t", "0.5"});
  ASSERT_EQ(linear.exit_code, 0) << linear.err;
  EXPECT_EQ(Json::parse(linear.out)["frames"][0]["matrix"], Json::parse("[[0.5, -1.0, 1.5], [1.0, 0.5, 0.5]]"));
  const RunResult pita = run({"eval", "sam.json", "--method", "P8"});  // P4, P5, P6, P9 are pose methods too
  EXPECT_EQ(pita.exit_code, 2);
  EXPECT_EQ(pita.out, "");
  EXPECT_NE(pita.err.find("this is a pose scene"), std::string::npos) << pita.err;
}

TEST_F(EvalPoses, NoSamExitsTwoWithTheReason) {
  const RunResult result = run({"eval", "nosam.json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: nosam.json: /poses: no SAM exists between these poses: ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("-0.5 and -2"), std::string::npos) << result.err;  // the eigenvalues
  EXPECT_NE(result.err.find("polySAM or a SAM bi-arc"), std::string::npos) << result.err;
  // render refuses it the same way, and writes nothing.
  const RunResult render = run({"render", "nosam.json", "-o", "out.png"});
  EXPECT_EQ(render.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
}

}  // namespace
}  // namespace pita::test
