// The reports of `pita measure` (src/analysis/measure_report.cpp): the JSON
// reads back with every panel and its numbers, a panel without a motion says
// so, and the CSV has a row per panel and a gain column per parameter.
#include <algorithm>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "analysis/measure.hpp"
#include "analysis/measure_report.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

const std::string kReportKeyframes = R"("keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";

TEST(MeasureReport, JsonReadsBackWithEveryPanel) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", )" + kReportKeyframes + R"(, "panels": [{"title": "a"}, {"method": "P8"}]})", "r.json");
  const std::vector<MotionMeasures> all = measure_scene(scene);
  const nlohmann::json report = nlohmann::json::parse(measures_json(scene.path, all));
  EXPECT_EQ(report["scene"], "r.json");
  ASSERT_EQ(report["motions"].size(), 2u);
  EXPECT_EQ(report["motions"][0]["title"], "a");
  EXPECT_EQ(report["motions"][1]["method"], all[1].method);
  EXPECT_DOUBLE_EQ(report["motions"][0]["path"]["p"]["length"].get<double>(),
                   std::get<ArrowMeasures>(all[0].measured).path_p.length);
  EXPECT_EQ(report["motions"][0]["overreaction"]["parameters"].size(), parameters_of(all[0]).size());
}

TEST(MeasureReport, CsvHasARowPerPanelAndAGainColumnPerParameter) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P6", )" + kReportKeyframes + "}", "r.json");
  const std::vector<MotionMeasures> all = measure_scene(scene);
  std::istringstream csv(measures_csv(all));
  std::string header, row, extra;
  ASSERT_TRUE(std::getline(csv, header));
  ASSERT_TRUE(std::getline(csv, row));
  EXPECT_FALSE(std::getline(csv, extra));
  EXPECT_NE(header.find(",gain_" + parameters_of(all[0]).front().name), std::string::npos);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), std::count(row.begin(), row.end(), ','));
}

TEST(MeasureReport, MarkdownNamesTheScene) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P6", )" + kReportKeyframes + "}", "r.json");
  EXPECT_EQ(measures_markdown(scene.path, measure_scene(scene)).rfind("# pita measure r.json", 0), 0u);
}

TEST(MeasureReport, TheWorkLimitNamesThePanels) {
  // A track of 1000 keyframes in three panels: its tweaks cost about 6e7 frames a panel.
  std::string keyframes;
  for (int i = 0; i < 1000; ++i) {
    keyframes += (i ? ", " : "") + std::string(R"({"t": )") + std::to_string(i) + R"(, "p": [)" + std::to_string(i) +
                 R"(, 0], "m": 1, "w": 0.1})";
  }
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "keyframes": [)" + keyframes + R"(], "panels": [{}, {"method": "P8"}, {"method": "P1"}]})",
      "r.json");
  try {
    check_measure_work(scene);
    ADD_FAILURE() << "measuring 3 x 1000 keyframes was accepted";
  } catch (const scene::SceneError& error) {
    EXPECT_EQ(error.pointer(), "/panels");
    EXPECT_NE(error.reason().find("above the limit"), std::string::npos);
  }
  const scene::Scene small = scene::parse_scene(R"({"method": "P6", )" + kReportKeyframes + "}", "r.json");
  EXPECT_NO_THROW(check_measure_work(small));
}

}  // namespace
}  // namespace pita::analysis
