// pita measure, through the real binary (src/cli/measure.cpp): the three
// formats parse and agree, bad input exits 2 with nothing on stdout, a
// motion that does not exist is reported, and every scene of scenes/ is
// measured. Its timing is a benchmark (bench/bench_measure.cpp), not a test.
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"
#include "support/sanitizers.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;

class Measure : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("scene.json", kFigureOneScene);
    dir.write("panels.json", "{" + kFigureOneFields + R"(, "panels": ["P1", "P6", {"method": "P7",
        "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 3.141592653589793},
                      {"t": 0.5, "p": [2, 1], "m": 1, "w": 0},
                      {"t": 1, "p": [4, 0], "m": 1, "w": 3.141592653589793}]}]})");
  }
  RunResult run(const std::vector<std::string>& args) const { return run_pita(args, dir.path()); }

  ScratchDir dir;
};

std::vector<std::string> split(const std::string& line) {
  // The test scenes have no quoted fields with commas.
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

TEST_F(Measure, JsonHasOneObjectPerPanel) {
  const RunResult result = run({"measure", "panels.json", "--format", "json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  const Json document = Json::parse(result.out);
  EXPECT_EQ(document["scene"], "panels.json");
  ASSERT_EQ(document["motions"].size(), 3u);
  const Json& p1 = document["motions"][0];
  EXPECT_EQ(p1["pointer"], "/panels/0");
  EXPECT_EQ(p1["kind"], "arrows");
  for (const char* predictor : {"previous", "average", "pita"}) {
    EXPECT_TRUE(p1["discrepancy"][predictor]["max"].is_number()) << predictor;
  }
  EXPECT_GT(p1["path"]["p"]["length"].get<double>(), 6.0);  // at least the chord from (0,0) to (6,0)
  EXPECT_EQ(p1["overreaction"]["parameters"].size(), 21u);
  EXPECT_TRUE(p1["overreaction"]["most_sensitive"].is_string());
  EXPECT_FALSE(p1["pop"]["detected"].get<bool>());
  // P7 through these keyframes does not exist (docs/paper-notes.md N13): reported, not fatal.
  const Json& p7 = document["motions"][2];
  ASSERT_TRUE(p7.contains("no_motion"));
  EXPECT_NE(p7["no_motion"].get<std::string>().find("panels.json: /panels/2"), std::string::npos) << p7["no_motion"];
  EXPECT_FALSE(p7.contains("path"));
}

TEST_F(Measure, CsvRowsMatchTheHeaderAndTheJson) {
  const RunResult csv = run({"measure", "panels.json", "--format", "csv"});
  const RunResult json = run({"measure", "panels.json", "--format", "json"});
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  std::stringstream lines(csv.out);
  std::string header_line, line;
  std::getline(lines, header_line);
  const std::vector<std::string> header = split(header_line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(lines, line)) rows.push_back(split(line));
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) EXPECT_EQ(row.size(), header.size());
  const auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return std::size_t{0};
  };
  const Json document = Json::parse(json.out);
  EXPECT_EQ(std::stod(rows[1][column("p_length")]), document["motions"][1]["path"]["p"]["length"].get<double>());
  EXPECT_EQ(std::stod(rows[1][column("gain_B.q.x")]),
            document["motions"][1]["overreaction"]["parameters"][9]["gain"].get<double>());
  EXPECT_EQ(document["motions"][1]["overreaction"]["parameters"][9]["name"], "B.q.x");
  EXPECT_EQ(rows[2][column("p_length")], "");  // P7: no motion
  EXPECT_NE(rows[2][column("no_motion")], "");
}

TEST_F(Measure, MarkdownIsTheDefault) {
  const RunResult result = run({"measure", "scene.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("| panel | method |"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("| B.q.x |"), std::string::npos) << result.out;
}

TEST_F(Measure, PoseScenesGiveAraAndArea) {
  dir.write("poses.json", R"({"method": "linear", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[-0.99, -0.14, 2], [0.14, -0.99, 1]]}]})");
  const RunResult result = run({"measure", "poses.json", "--format", "json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Json motion = Json::parse(result.out)["motions"][0];
  EXPECT_GT(motion["ara"].get<double>(), 0.0);
  EXPECT_FALSE(motion["area"]["monotone"].get<bool>());  // det dips to ~0 half way
}

TEST_F(Measure, BadInputExitsTwoWithNothingOnStdout) {
  const RunResult missing = run({"measure", "missing.json"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.out, "");
  EXPECT_EQ(missing.err, "pita: missing.json: cannot open the scene file (No such file or directory)\n");

  dir.write("bad.json", R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": -1, "w": 0},
      {"t": 0.5, "p": [1, 0], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})");
  const RunResult bad = run({"measure", "bad.json"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.out, "");
  EXPECT_EQ(bad.err.rfind("pita: bad.json: /keyframes/0/m: ", 0), 0u) << bad.err;

  const RunResult format = run({"measure", "scene.json", "--format", "xml"});
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_EQ(format.out, "");
}

TEST_F(Measure, WorkBeyondTheLimitIsRefused) {
  // 64 keyframes through the neville chain: each frame blends ~2e3 frames
  // of P6, and measuring tweaks every keyframe: far above 1e8 frames.
  std::string keys;
  for (int i = 0; i < 64; ++i) {
    keys += (i ? ", " : "") + std::string(R"({"t": )") + std::to_string(i) + R"(, "p": [)" + std::to_string(i) + ", " +
            std::to_string(i % 3) + R"(], "m": 1, "w": 0})";
  }
  dir.write("long.json", R"({"method": "P6", "chain": "neville", "keyframes": [)" + keys + "]}");
  const RunResult result = run({"measure", "long.json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: long.json: /keyframes: measuring these motions costs about ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("above the limit of 1e+08"), std::string::npos) << result.err;
}

// Poses of space (SAM paper Sec. 2.4 and 6.1 in 3D): a SAM is steady (ARA 0)
// and its volume det L(t) = det(L)^t is monotone; the linear blend of the same
// two poses (a quarter turn about z, all scaled by 2) is not steady, and its
// volume ((1 - u)^2 + 4 u^2)(1 + u) first falls below 1, then rises to 8.
TEST_F(Measure, PosesOfSpaceHaveTheirAraAndVolume) {
  const std::string poses = R"("poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 2, "matrix": [[0, -2, 0, 1], [2, 0, 0, 2], [0, 0, 2, 3]]}])";
  dir.write("sam.json", R"({"dimension": 3, "method": "SAM", )" + poses + "}");
  dir.write("linear.json", R"({"dimension": 3, "method": "linear", )" + poses + "}");
  const RunResult sam = run({"measure", "sam.json", "--format", "json"});
  const RunResult linear = run({"measure", "linear.json", "--format", "json"});
  ASSERT_EQ(sam.exit_code, 0) << sam.err;
  ASSERT_EQ(linear.exit_code, 0) << linear.err;
  const Json steady = Json::parse(sam.out)["motions"][0];
  const Json blend = Json::parse(linear.out)["motions"][0];
  EXPECT_EQ(steady["kind"], "poses3d");
  EXPECT_LT(steady["ara"].get<double>(), 1e-6);
  EXPECT_EQ(steady["volume"]["monotone"], true);
  EXPECT_NEAR(steady["volume"]["first"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(steady["volume"]["last"].get<double>(), 8.0, 1e-9);
  EXPECT_GT(blend["ara"].get<double>(), 0.1);
  EXPECT_EQ(blend["volume"]["monotone"], false);
  // The Markdown report has the table of space, headed by the volume.
  const RunResult md = run({"measure", "sam.json", "--format", "md"});
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("| ARA | volume monotone |"), std::string::npos) << md.out;
}

// Panels of a 3D scene are measured one by one, each with its own method: the
// same poses, steady by SAM and not by linear interpolation; `pita eval
// --panel` prints the panel's own frames.
TEST_F(Measure, PanelsOfASpaceSceneEachHaveTheirMeasures) {
  dir.write("panels.json", R"({"dimension": 3, "method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 2, "matrix": [[0, -2, 0, 1], [2, 0, 0, 2], [0, 0, 2, 3]]}], "panels": ["SAM", "linear"]})");
  const RunResult measured = run({"measure", "panels.json", "--format", "json"});
  ASSERT_EQ(measured.exit_code, 0) << measured.err;
  const Json motions = Json::parse(measured.out)["motions"];
  ASSERT_EQ(motions.size(), 2u);
  EXPECT_EQ(motions[0]["pointer"], "/panels/0");
  EXPECT_EQ(motions[1]["method"], "linear");
  EXPECT_LT(motions[0]["ara"].get<double>(), 1e-6);
  EXPECT_GT(motions[1]["ara"].get<double>(), 0.1);
  // At t = 1 the linear panel's matrix is the mean of the two poses (an independent check).
  const RunResult linear = run({"eval", "panels.json", "--panel", "1", "--t", "1"});
  ASSERT_EQ(linear.exit_code, 0) << linear.err;
  const Json frame = Json::parse(linear.out)["frames"][0];
  EXPECT_EQ(frame["matrix"][0][1].get<double>(), -1.0);
  EXPECT_EQ(frame["matrix"][2][3].get<double>(), 1.5);
}

TEST_F(Measure, EverySceneOfScenesIsMeasured) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    if (!in_sample(i, 3)) continue;  // under the sanitizers a third of them (every one in Release)
    const std::filesystem::directory_entry entry(scenes[i]);
    const RunResult result = run({"measure", entry.path().string(), "--format", "json"});
    EXPECT_EQ(result.exit_code, 0) << entry.path() << ": " << result.err;
    Json document;
    ASSERT_NO_THROW(document = Json::parse(result.out)) << entry.path();
    EXPECT_GE(document["motions"].size(), 1u) << entry.path();
    if (entry.path().stem().string().starts_with("sam-3d-")) {  // poses of space: ARA and the volume
      for (const Json& motion : document["motions"]) {
        EXPECT_EQ(motion["kind"], "poses3d") << entry.path();
        EXPECT_TRUE(motion.contains("ara") && motion.contains("volume")) << motion.dump();
      }
    }
  }
}

}  // namespace
}  // namespace pita::test
