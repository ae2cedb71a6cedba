// pita audit from the outside: formats, counterexamples that replay through
// pita eval, the table figure, and bad usage (exit 2, nothing written).
#include <cmath>
#include <complex>
#include <filesystem>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

TEST(Audit, JsonHasEveryCellAndThePapersTable) {
  ScratchDir dir;
  const RunResult r =
      run_pita({"audit", "--methods", "P1,P4,P5", "--configs", "20", "--format", "json", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["methods"], Json::array({"P1", "P4", "P5"}));
  EXPECT_EQ(j["cells"].size(), 3 * j["properties"].size());
  bool p5_similarity = false, p4_disagreement = false;
  for (const Json& cell : j["cells"]) {
    if (cell["method"] == "P5" && cell["property"] == "similarity-invariant") {
      p5_similarity = true;
      EXPECT_FALSE(cell["holds"].get<bool>());
      EXPECT_GT(cell["violation"].get<double>(), 1e-4);
    }
  }
  for (const Json& d : j["paper"]["disagreements"]) {
    if (d["method"] == "P4" && d["property"] == "winding-aware")
      p4_disagreement = !d["reason"].get<std::string>().empty();
  }
  EXPECT_TRUE(p5_similarity);
  EXPECT_TRUE(p4_disagreement);
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress bar off a terminal
}

TEST(Audit, MarkdownAndCsv) {
  ScratchDir dir;
  const RunResult md = run_pita({"audit", "--methods", "P8", "--configs", "5"}, dir.path());
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("| P8 |"), std::string::npos);
  EXPECT_NE(md.out.find("locally-perseverant"), std::string::npos);
  const RunResult csv = run_pita({"audit", "--methods", "P8", "--configs", "5", "--format", "csv"}, dir.path());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.rfind("method,property,holds,violation,measured,config,t,counterexample\n", 0), 0u);
  EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 14);  // header + 13 properties
}

TEST(Audit, SameSeedSameOutput) {
  ScratchDir dir;
  const std::vector<std::string> args{"audit",  "--methods", "P2,P6",    "--configs", "15",
                                      "--seed", "4",         "--format", "json"};
  auto one = args, two = args;
  one.insert(one.end(), {"--jobs", "1"});
  two.insert(two.end(), {"--jobs", "2"});
  const RunResult a = run_pita(one, dir.path()), b = run_pita(two, dir.path());
  ASSERT_EQ(a.exit_code, 0);
  EXPECT_EQ(a.out, b.out);
}

std::vector<std::pair<double, std::complex<double>>> eval_p(const fs::path& dir, const std::string& scene, double t,
                                                            bool panel_one, std::complex<double>* q) {
  std::vector<std::string> args{"eval", scene, "--t", fmt::format("{:.17g}", t)};
  if (panel_one) args.insert(args.end(), {"--panel", "1"});
  const RunResult r = run_pita(args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const Json f = Json::parse(r.out)["frames"][0];
  const std::complex<double> p{f["p"][0].get<double>(), f["p"][1].get<double>()};
  *q = {f["q"][0].get<double>(), f["q"][1].get<double>()};
  return {{t, p}};
}

// The audit's unit of length for keyframes [A, B, C] as JSON: the largest
// distance of an arrow's end from B's origin, or a magnitude.
double extent_of(const Json& k) {
  const std::complex<double> b{k[1]["p"][0].get<double>(), k[1]["p"][1].get<double>()};
  double extent = 0;
  for (const Json& x : k) {
    const std::complex<double> p{x["p"][0].get<double>(), x["p"][1].get<double>()};
    const double m = x["m"], w = x["w"];
    extent = std::max({extent, std::abs(p - b), std::abs(p + std::polar(m, w) - b), m});
  }
  return extent;
}

TEST(Audit, SimilarityCounterexampleReplaysThroughEval) {
  // Independent of the audit's code: read S from the report, evaluate both
  // panels with pita eval, apply S by hand and measure the distance.
  ScratchDir dir;
  const RunResult r = run_pita(
      {"audit", "--methods", "P5", "--configs", "20", "--format", "json", "--counterexamples", "cx"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  for (const Json& cell : j["cells"]) {
    if (cell["property"] != "similarity-invariant") continue;
    const std::string file = cell["counterexample"];
    ASSERT_TRUE(fs::exists(dir.path() / file));
    ASSERT_TRUE(fs::exists((dir.path() / file).replace_extension(".svg")));
    const Json& c = cell["configuration"];
    const double t = c["t"], scale = c["parameters"]["scale"], rotation = c["parameters"]["rotation"];
    const std::complex<double> shift{c["parameters"]["translation.x"].get<double>(),
                                     c["parameters"]["translation.y"].get<double>()};
    const auto S = [&](std::complex<double> x) { return scale * std::polar(1.0, rotation) * x + shift; };
    std::complex<double> q0, q1;
    const auto p0 = eval_p(dir.path(), file, t, false, &q0)[0].second;
    const auto p1 = eval_p(dir.path(), file, t, true, &q1)[0].second;
    // The extent of the moved keyframes: the largest distance from B's origin.
    const double extent = extent_of(c["counterpart"]);
    const double measured = std::max(std::abs(S(p0) - p1), std::abs(S(q0) - q1)) / extent;
    EXPECT_NEAR(measured, cell["violation"].get<double>(), 1e-6 * cell["violation"].get<double>() + 1e-9);
    return;
  }
  FAIL() << "no similarity cell for P5";
}

TEST(Audit, OrderCounterexampleReplaysThroughEval) {
  // P2 is not order-independent: its counterpart panel keeps the swapped
  // keyframes in the order given ("knots": "as-given"). Replayed by pita eval,
  // the two panels differ by the reported violation (times a length no less
  // than the configuration's extent), and each still passes through its
  // keyframes, whatever their order.
  ScratchDir dir;
  const RunResult r = run_pita(
      {"audit", "--methods", "P2", "--configs", "20", "--format", "json", "--counterexamples", "cx"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  for (const Json& cell : j["cells"]) {
    if (cell["property"] != "order-independent") continue;
    ASSERT_FALSE(cell["holds"].get<bool>());
    const std::string file = cell["counterexample"];
    const Json scene = Json::parse(read_file(dir.path() / file));
    EXPECT_EQ(scene["panels"][1]["options"]["knots"], "as-given");
    const Json& c = cell["configuration"];
    const Json& k = c["keyframes"];
    const Json& swapped = c["counterpart"];
    EXPECT_EQ(swapped[0], k[1]);  // (b, B) first
    EXPECT_EQ(swapped[1], k[0]);  // (a, A) second
    const double t = c["t"];
    std::complex<double> q0, q1;
    const auto p0 = eval_p(dir.path(), file, t, false, &q0)[0].second;
    const auto p1 = eval_p(dir.path(), file, t, true, &q1)[0].second;
    const double extent = extent_of(k);
    const double distance = std::max(std::abs(p0 - p1), std::abs(q0 - q1));
    const double violation = cell["violation"];
    EXPECT_GT(distance / extent, 1e-3);
    EXPECT_GE(distance / violation, extent * (1 - 1e-9));
    // The counterpart passes through each of its keyframes at its own knot.
    for (const Json& x : swapped) {
      std::complex<double> q;
      const auto p = eval_p(dir.path(), file, x["t"].get<double>(), true, &q)[0].second;
      const std::complex<double> want{x["p"][0].get<double>(), x["p"][1].get<double>()};
      EXPECT_LT(std::abs(p - want), 1e-9 * extent) << x.dump();
      EXPECT_LT(std::abs(q - want - std::polar(x["m"].get<double>(), x["w"].get<double>())), 1e-9 * extent);
    }
    return;
  }
  FAIL() << "no order-independence cell for P2";
}

TEST(Audit, DrawsTheTable) {
  ScratchDir dir;
  const RunResult r = run_pita({"audit", "--methods", "P1,P2", "--configs", "5", "-o", "table.svg"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(dir.path() / "table.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir.path() / "table.svg"));
}

TEST(Audit, BadUsageExitsTwoAndWritesNothing) {
  ScratchDir dir;
  dir.write("file", "x");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"audit", "--methods", "P66", "-o", "t.svg"}, "did you mean"},
      {{"audit", "--methods", "SMA", "-o", "t.svg"}, "takes 2 keyframes"},
      {{"audit", "--methods", "SAM", "-o", "t.svg"}, "unknown method"},
      {{"audit", "--configs", "0", "-o", "t.svg"}, "--configs"},
      {{"audit", "--configs", "1000001", "-o", "t.svg"}, "--configs"},
      {{"audit", "--configs", "5", "-o", "t.txt"}, ".svg, .png or .pdf"},
      {{"audit", "--configs", "5", "--counterexamples", "file/cx", "-o", "t.svg"}, "cannot create the folder"},
      // Issue 37: refused before the work, not after it (exit 3, an empty folder).
      {{"audit", "--configs", "5", "-o", "t.svg", "--counterexamples", "t.svg"}, "name the same path"},
      {{"audit", "--configs", "5", "-o", "t.svg", "--counterexamples", "./t.svg"}, "name the same path"},
  };
  for (const auto& [args, message] : cases) {
    const RunResult r = run_pita(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << args[2];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_FALSE(fs::exists(dir.path() / "t.svg"));
  }
}

TEST(EvalPanel, OutOfRangeIsBadInputAndInRangeEvaluatesThatPanel) {
  ScratchDir dir;
  const RunResult r =
      run_pita({"eval", std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json", "--panel", "8"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--panel: "), std::string::npos) << r.err;
  const RunResult ok =
      run_pita({"eval", std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json", "--panel", "7", "--t", "0.4"},
               dir.path());
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("\"P6\""), std::string::npos);  // panel 7 is P6 at ratio 0.40
  // Panel 0 is P1: its frames are labelled P1, and equal those of --method P1.
  const RunResult first =
      run_pita({"eval", std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json", "--panel", "0", "--t", "0.3"},
               dir.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("\"method\": \"P1\""), std::string::npos) << first.out;
  const RunResult refused = run_pita(
      {"eval", std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json", "--panel", "0", "--method", "P8"},
      dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--panel and --method"), std::string::npos) << refused.err;
  EXPECT_TRUE(refused.out.empty());
}

TEST(Audit, SeedMustBeAnUnsignedInteger) {
  ScratchDir dir;
  for (const std::string seed : {"-5", "99999999999999999999999", "1e3", "x"}) {
    const RunResult r = run_pita({"audit", "--configs", "1", "--seed", seed}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << seed;
    EXPECT_NE(r.err.find("--seed"), std::string::npos) << r.err;
  }
  const RunResult r =
      run_pita({"audit", "--methods", "P1", "--configs", "1", "--seed", "18446744073709551615"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(Audit, TableFolderMissingIsExitThreeBeforeTheWork) {
  ScratchDir dir;
  const RunResult r =
      run_pita({"audit", "--configs", "1", "--counterexamples", "cx", "-o", "missing/t.svg"}, dir.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(dir.path() / "cx") || fs::is_empty(dir.path() / "cx"));  // nothing written
}

}  // namespace
}  // namespace pita::test
