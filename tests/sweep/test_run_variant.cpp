// One variant of a sweep run (src/sweep/run_variant.cpp): a good variant
// writes its scene, figure and frames and records its metrics; a variant the
// scene reader refuses keeps only its scene, removes what an earlier run
// wrote for it, and names its own file in the status.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "sweep/run_variant.hpp"

namespace pita::sweep {
namespace {

namespace fs = std::filesystem;

const std::string kBaseScene = std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json";

std::string file_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class RunVariant : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pita-run-variant-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(RunVariant, GoodVariantWritesItsFilesAndMetrics) {
  const Grid grid({parse_axis("/keyframes/1/t=0.3,0.5")}, false);
  const BaseScene base = load_base(kBaseScene, grid);
  SweepOptions options;
  options.formats = {OutputKind::svg, OutputKind::csv};
  const VariantJob job{options, grid, base, dir_, "knots", "salt"};
  VariantOutcome outcome;
  const Row row = run_variant(job, 1, outcome);
  EXPECT_FALSE(outcome.write_failed);
  EXPECT_EQ(row.status, "ok");
  ASSERT_EQ(row.outputs.size(), 3u);  // scene, svg, csv
  for (const std::string& file : row.outputs) EXPECT_TRUE(fs::is_regular_file(dir_ / file)) << file;
  // The scene written is the variant: read back, its second knot is 0.5.
  const scene::Scene scene = scene::load_scene(dir_ / row.outputs[0]);
  EXPECT_EQ(std::get<scene::KeyframeKeys>(scene.keys).keyframes[1].t, 0.5);
  EXPECT_NE(file_text(dir_ / row.outputs[1]).find("<svg"), std::string::npos);
  EXPECT_FALSE(row.metrics[0].empty());  // the path length of p
  EXPECT_EQ(row.values, (std::vector<std::string>{"0.5"}));
}

TEST_F(RunVariant, RefusedVariantKeepsOnlyItsScene) {
  const Grid grid({parse_axis("/keyframes/1/m=1,-1")}, false);
  const BaseScene base = load_base(kBaseScene, grid);
  SweepOptions options;
  options.formats = {OutputKind::svg};
  const VariantJob job{options, grid, base, dir_, "knots", "salt"};
  VariantOutcome outcome;
  // An earlier run's figure for variant 1, now stale.
  const fs::path stale = dir_ / variant_file("knots", 1, grid.size(), "svg");
  std::ofstream(stale) << "<svg/>";
  const Row row = run_variant(job, 1, outcome);
  EXPECT_FALSE(outcome.write_failed);
  EXPECT_NE(row.status.find(variant_file("knots", 1, grid.size(), "scene.json") + ": /keyframes/1/m"),
            std::string::npos)
      << row.status;
  ASSERT_EQ(row.outputs.size(), 1u);
  EXPECT_TRUE(fs::is_regular_file(dir_ / row.outputs[0]));
  EXPECT_FALSE(fs::exists(stale));
  for (const std::string& metric : row.metrics) EXPECT_TRUE(metric.empty());
}

}  // namespace
}  // namespace pita::sweep
