// pita lint, through the real binary (src/cli/lint.cpp): a clean scene is
// ok, a finding is exit 1 naming the file, pointer and check, the JSON form
// parses, a bad scene is exit 2 while the others are still linted, and
// every scene of scenes/ lints clean (or accepts each finding with a reason).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;

const std::string kClean = "{" + kFigureOneFields + R"(, "layers": [{"type": "pattern"}, {"type": "keyframes"}]})";
const std::string kOver =
    "{" + kFigureOneFields +
    R"(, "layers": [{"type": "pattern"}, {"type": "label", "text": "on top", "at": [3, 1.5], "size": 20}]})";

class Lint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("clean.json", kClean);
    dir.write("over.json", kOver);
    dir.write("bad.json", R"({"method": "P6", "keyframes": []})");
  }
  RunResult run(const std::vector<std::string>& args) const { return run_pita(args, dir.path()); }
  ScratchDir dir;
};

TEST_F(Lint, ACleanSceneIsOk) {
  const RunResult r = run({"lint", "clean.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "clean.json: ok (0 findings accepted)\n");
  EXPECT_EQ(r.err, "");
}

TEST_F(Lint, AFindingIsExitOneNamingFilePointerAndCheck) {
  const RunResult r = run({"lint", "clean.json", "over.json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("clean.json: ok"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("over.json: /layers/1: text-over-data: the label \"on top\" lies over the data of /layers/0 "
                       "(pattern)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("over.json: 1 findings (0 accepted)"), std::string::npos) << r.out;
}

TEST_F(Lint, JsonListsEveryFinding) {
  const RunResult r = run({"lint", "over.json", "clean.json", "--format", "json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const nlohmann::json document = nlohmann::json::parse(r.out);
  ASSERT_EQ(document.size(), 2u);
  EXPECT_EQ(document[0]["scene"], "over.json");
  EXPECT_EQ(document[0]["clean"], false);
  ASSERT_EQ(document[0]["findings"].size(), 1u);
  EXPECT_EQ(document[0]["findings"][0]["check"], "text-over-data");
  EXPECT_EQ(document[0]["findings"][0]["pointer"], "/layers/1");
  EXPECT_EQ(document[1]["clean"], true);
  EXPECT_TRUE(document[1]["findings"].empty());
}

TEST_F(Lint, AnAcceptedFindingAndAStaleEntry) {
  std::string text = kOver;
  text.insert(text.rfind('}'), R"(, "lint": {"allow": [
      {"check": "text-over-data", "pointer": "/layers/1", "reason": "it names what it lies on"},
      {"check": "outside", "reason": "nothing is cut off any more"}]})");
  dir.write("accepted.json", text);
  const RunResult r = run({"lint", "accepted.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("accepted.json: /lint/allow/1: note: this accepted finding no longer occurs (remove it)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("accepted.json: ok (1 findings accepted)"), std::string::npos) << r.out;
}

TEST_F(Lint, ABadSceneIsExitTwoAndTheOthersAreLinted) {
  const RunResult r = run({"lint", "bad.json", "clean.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pita: bad.json: /keyframes:"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("clean.json: ok"), std::string::npos) << r.out;
  EXPECT_EQ(run({"lint", "clean.json", "--format", "yaml"}).exit_code, 2);
  EXPECT_EQ(run({"lint"}).exit_code, 2);
}

// The issue's acceptance test: `pita lint scenes/*.json` exits 0.
TEST_F(Lint, EverySceneOfTheRepositoryLintsClean) {
  std::vector<std::string> args = {"lint"};
  for (const auto& entry : fs::directory_iterator(fs::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".json") args.push_back(entry.path().string());
  }
  ASSERT_GT(args.size(), 50u);
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace pita::test
