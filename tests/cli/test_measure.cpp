// pita measure, through the real binary (src/cli/measure.cpp): the three
// formats parse and agree, bad input exits 2 with nothing on stdout, a
// motion that does not exist is reported, and every scene of scenes/ is
// measured. Its timing is a benchmark (bench/bench_measure.cpp), not a test.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_pita.hpp"

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
  EXPECT_NE(p7["no_motion"].get<std::string>().find("panels.json: /panels/2"), std::string::npos)
      << p7["no_motion"];
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
    keys += (i ? ", " : "") + std::string(R"({"t": )") + std::to_string(i) + R"(, "p": [)" + std::to_string(i) +
            ", " + std::to_string(i % 3) + R"(], "m": 1, "w": 0})";
  }
  dir.write("long.json", R"({"method": "P6", "chain": "neville", "keyframes": [)" + keys + "]}");
  const RunResult result = run({"measure", "long.json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: long.json: /keyframes: measuring these motions costs about ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("above the limit of 1e+08"), std::string::npos) << result.err;
}

TEST_F(Measure, EverySceneOfScenesIsMeasured) {
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    const RunResult result = run({"measure", entry.path().string(), "--format", "json"});
    if (entry.path().stem().string().starts_with("sam-3d-")) {  // 3D scenes: refused, naming /dimension
      EXPECT_EQ(result.exit_code, 2) << entry.path();
      EXPECT_NE(result.err.find(": /dimension: pita measure works on scenes of the plane"), std::string::npos)
          << result.err;
      continue;
    }
    EXPECT_EQ(result.exit_code, 0) << entry.path() << ": " << result.err;
    Json document;
    ASSERT_NO_THROW(document = Json::parse(result.out)) << entry.path();
    EXPECT_GE(document["motions"].size(), 1u) << entry.path();
  }
}

}  // namespace
}  // namespace pita::test
