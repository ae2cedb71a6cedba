// pita audit poses from the outside: the formats, one dimension or both, the
// same output whatever --jobs, the table figure, and bad usage (exit 2,
// nothing written).
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

TEST(PoseAudit, JsonHasEveryCellOfBothDimensions) {
  ScratchDir dir;
  const RunResult r =
      run_pita({"audit", "poses", "--methods", "P5,P6,polySAM", "--configs", "12", "--format", "json"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress bar off a terminal
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["methods"], Json::array({"P5", "P6", "polySAM"}));
  EXPECT_EQ(j["dimensions"], Json::array({2, 3}));
  EXPECT_EQ(j["cells"].size(), 2 * 3 * j["properties"].size());
  int checked = 0;
  for (const Json& cell : j["cells"]) {
    const std::string method = cell["method"], property = cell["property"];
    if (property == "left-affine-invariant" && method != "P5") {
      EXPECT_TRUE(cell["holds"].get<bool>()) << method;
    }
    if (property == "left-affine-invariant" && method == "P5") {
      EXPECT_FALSE(cell["holds"].get<bool>());
      EXPECT_EQ(cell["configuration"]["poses"].size(), 3u);
      EXPECT_EQ(cell["configuration"]["poses"][0]["matrix"].size(), static_cast<std::size_t>(cell["dimension"]));
      ++checked;
    }
    if (property == "steady" && method == "polySAM") {
      EXPECT_TRUE(cell["holds"].get<bool>());
    }
    if (property == "exists") {
      EXPECT_TRUE(cell.contains("share_by_mix"));
    }
  }
  EXPECT_EQ(checked, 2);
}

TEST(PoseAudit, MarkdownAndCsvOfOneDimension) {
  ScratchDir dir;
  const RunResult md =
      run_pita({"audit", "poses", "--dimension", "3", "--methods", "P9", "--configs", "4"}, dir.path());
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("## 3D"), std::string::npos);
  EXPECT_EQ(md.out.find("## 2D"), std::string::npos);
  EXPECT_NE(md.out.find("| P9 |"), std::string::npos);
  const RunResult csv = run_pita(
      {"audit", "poses", "--dimension", "2", "--methods", "P9", "--configs", "4", "--format", "csv"}, dir.path());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("dimension,method,property,holds,value,measured,config,t\n", 0), 0u);
  EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 8);  // header + 7 properties
}

TEST(PoseAudit, SameSeedSameOutputWhateverTheJobs) {
  ScratchDir dir;
  const std::vector<std::string> args{"audit", "poses",  "--methods", "P4,four-point-SAM", "--configs",
                                      "8",     "--seed", "9",         "--format",          "json"};
  auto one = args, two = args;
  one.insert(one.end(), {"--jobs", "1"});
  two.insert(two.end(), {"--jobs", "2"});
  const RunResult a = run_pita(one, dir.path()), b = run_pita(two, dir.path());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
}

TEST(PoseAudit, DrawsTheTable) {
  ScratchDir dir;
  const RunResult r =
      run_pita({"audit", "poses", "--methods", "P6,biarc-SAM", "--configs", "3", "-o", "table.svg"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(dir.path() / "table.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
}

TEST(PoseAudit, BadUsageExitsTwoAndWritesNothing) {
  ScratchDir dir;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"audit", "poses", "--methods", "P66", "-o", "t.svg"}, "did you mean"},
      {{"audit", "poses", "--methods", "rARAP", "-o", "t.svg"}, "not measured"},
      {{"audit", "poses", "--methods", "SAM", "-o", "t.svg"}, "not measured"},
      {{"audit", "poses", "--methods", "P6,", "-o", "t.svg"}, "empty name"},
      {{"audit", "poses", "--dimension", "4", "-o", "t.svg"}, "--dimension"},
      {{"audit", "poses", "--configs", "0", "-o", "t.svg"}, "--configs"},
      {{"audit", "poses", "--seed", "x", "-o", "t.svg"}, "--seed"},
      {{"audit", "poses", "--configs", "2", "-o", "t.txt"}, ".svg, .png or .pdf"},
  };
  for (const auto& [args, message] : cases) {
    const RunResult r = run_pita(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << args[3];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_FALSE(fs::exists(dir.path() / "t.svg"));
  }
  const RunResult missing = run_pita({"audit", "poses", "--configs", "2", "-o", "no/such/t.svg"}, dir.path());
  EXPECT_EQ(missing.exit_code, 3) << missing.err;
}

}  // namespace
}  // namespace pita::test
