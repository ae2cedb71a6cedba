// pita sweep from the outside: every variant equals the hand-edited scene run
// through pita render and pita eval; failed variants are rows; resume, --force,
// shards and --merge, an interrupted sweep resumed; bad usage (exit 2, nothing
// written); the HTML index sorted in a real browser.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

const std::string kFig13 = std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json";

// The first field of each data row of a manifest (no field here is quoted
// before the status).
std::vector<std::string> column(const std::string& manifest, std::size_t k) {
  std::vector<std::string> out;
  const std::vector<std::string> lines = lines_of(manifest);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::size_t start = 0;
    for (std::size_t j = 0; j < k; ++j) start = lines[i].find(',', start) + 1;
    out.push_back(lines[i].substr(start, lines[i].find(',', start) - start));
  }
  return out;
}

TEST(Sweep, EachVariantIsTheHandEditedScene) {
  ScratchDir dir;
  const RunResult r = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0.3:0.6:2", "--vary", "/method=P1,La-LP",
                                "-o", "out", "--format", "svg,csv,json", "-q"},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("4 variants: 4 written"), std::string::npos) << r.out;
  const Json base = Json::parse(read_file(kFig13));
  const std::vector<std::pair<double, std::string>> expected = {
      {0.3, "P1"}, {0.3, "La-LP"}, {0.6, "P1"}, {0.6, "La-LP"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    // The scene a user would write by hand, next to the base so that it reads alike.
    Json edited = base;
    edited["keyframes"][1]["t"] = expected[i].first;
    edited["method"] = expected[i].second;
    // Its title says what varies.
    edited["title"] = fmt::format("{} (/keyframes/1/t = {}, /method = {})", base["title"].get<std::string>(),
                                  expected[i].first, expected[i].second);
    const fs::path hand = dir.path() / fmt::format("hand-{}.json", i);
    std::ofstream(hand) << edited.dump(1);
    const RunResult svg = run_pita({"render", hand.string(), "-o", fmt::format("hand-{}.svg", i)}, dir.path());
    ASSERT_EQ(svg.exit_code, 0) << svg.err;
    EXPECT_EQ(read_file(dir.path() / fmt::format("out/fig13-knot-ratio-{}.svg", i)),
              read_file(dir.path() / fmt::format("hand-{}.svg", i)));
    for (const std::string format : {"csv", "json"}) {
      const RunResult frames = run_pita({"eval", hand.string(), "--format", format}, dir.path());
      ASSERT_EQ(frames.exit_code, 0) << frames.err;
      EXPECT_EQ(read_file(dir.path() / fmt::format("out/fig13-knot-ratio-{}.{}", i, format)), frames.out);
    }
    // The variant's own scene file is the same scene.
    EXPECT_EQ(Json::parse(read_file(dir.path() / fmt::format("out/fig13-knot-ratio-{}.scene.json", i))), edited);
  }
  const std::string manifest = read_file(dir.path() / "out/manifest.csv");
  EXPECT_EQ(lines_of(manifest).front().rfind("index,/keyframes/1/t,/method,status,outputs,hash,path_length_p", 0), 0u);
  EXPECT_EQ(column(manifest, 1), (std::vector<std::string>{"0.3", "0.3", "0.6", "0.6"}));
  EXPECT_EQ(column(manifest, 3), (std::vector<std::string>(4, "ok")));
  EXPECT_TRUE(fs::exists(dir.path() / "out/index.html"));
  EXPECT_TRUE(fs::exists(dir.path() / "out/contact.png"));
  EXPECT_TRUE(fs::exists(dir.path() / "out/contact.svg"));
}

TEST(Sweep, PathLengthMetricIsTheEvaluatedPath) {
  // Independent of pita measure: the polyline through 2001 frames of pita eval.
  ScratchDir dir;
  dir.write("s.json", kFigureOneScene);
  const RunResult r =
      run_pita({"sweep", "s.json", "--vary", "/keyframes/2/m=1.2", "-o", "out", "--format", "csv", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const RunResult frames = run_pita({"eval", "s.json", "--samples", "2001", "--format", "csv"}, dir.path());
  double length = 0, x0 = 0, y0 = 0;
  const std::vector<std::string> lines = lines_of(frames.out);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    double t, x, y;
    ASSERT_EQ(std::sscanf(lines[i].c_str(), "%lf,%lf,%lf", &t, &x, &y), 3);
    if (i > 1) length += std::hypot(x - x0, y - y0);
    x0 = x;
    y0 = y;
  }
  const double metric = std::stod(column(read_file(dir.path() / "out/manifest.csv"), 5).at(0));
  EXPECT_NEAR(metric, length, 1e-4 * length);
}

// Each variant's title shows what varies: a "{/pointer}" of the title shows
// its value, the other varied values follow the title.
TEST(Sweep, VariantTitlesSayWhatVaries) {
  ScratchDir dir;
  Json scene = Json::parse(kFigureOneScene);
  scene["title"] = "A motion by {/method}";
  dir.write("s.json", scene.dump());
  const RunResult r = run_pita({"sweep", "s.json", "--vary", "/method=P2,P4", "--vary", "/keyframes/1/w=0.5,1", "-o",
                                "out", "--format", "svg", "-q"},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json variant = Json::parse(read_file(dir.path() / "out/s-3.scene.json"));
  EXPECT_EQ(variant["title"], "A motion by {/method} (/keyframes/1/w = 1)");
  // pita render shows the template's value: the variant's figure is the
  // scene titled by hand.
  Json hand = variant;
  hand["title"] = "A motion by P4 (/keyframes/1/w = 1)";
  dir.write("hand.json", hand.dump());
  ASSERT_EQ(run_pita({"render", "hand.json", "-o", "hand.svg"}, dir.path()).exit_code, 0);
  EXPECT_EQ(read_file(dir.path() / "out/s-3.svg"), read_file(dir.path() / "hand.svg"));
}

// A figure's panels that all set their own method draw none of the scene's:
// varying it is refused, unless the frames of the scene's own motion are asked for.
TEST(Sweep, VaryingAMethodThatNoPanelDrawsIsRefused) {
  ScratchDir dir;
  Json scene = Json::parse(kFigureOneScene);
  scene["panels"] = Json::array({"P2", Json{{"method", "P8"}}});
  dir.write("s.json", scene.dump());
  const RunResult r = run_pita({"sweep", "s.json", "--vary", "/method=P2,P4", "-o", "out"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("every panel sets its own method (/panels/0, /panels/1/method)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  const RunResult frames =
      run_pita({"sweep", "s.json", "--vary", "/method=P2,P4", "-o", "out", "--format", "csv", "-q"}, dir.path());
  EXPECT_EQ(frames.exit_code, 0) << frames.err;
  // A panel that draws the scene's method lets it vary.
  scene["panels"] = Json::array({"P2", Json{{"title", "the scene's"}}});
  dir.write("s.json", scene.dump());
  EXPECT_EQ(run_pita({"sweep", "s.json", "--vary", "/method=P2,P4", "-o", "out2", "-q"}, dir.path()).exit_code, 0);
}

// The metrics are of what the figure draws: its first panel's motion.
TEST(Sweep, MetricsMeasureTheFirstPanel) {
  ScratchDir dir;
  Json scene = Json::parse(kFigureOneScene);
  scene["panels"] = Json::array({"P1", "P6"});
  dir.write("s.json", scene.dump());
  ASSERT_EQ(run_pita({"sweep", "s.json", "--vary", "/keyframes/1/w=0.5", "-o", "out", "--format", "metrics", "-q"},
                     dir.path())
                .exit_code,
            0);
  const std::string metric = column(read_file(dir.path() / "out/manifest.csv"), 5).at(0);
  Json panel_scene = Json::parse(read_file(dir.path() / "s.json"));
  panel_scene["keyframes"][1]["w"] = 0.5;
  panel_scene.erase("panels");
  panel_scene["method"] = "P1";
  dir.write("p1.json", panel_scene.dump());
  const RunResult p1 = run_pita({"measure", "p1.json", "--format", "json"}, dir.path());
  ASSERT_EQ(p1.exit_code, 0) << p1.err;
  const double length = Json::parse(p1.out)["motions"][0]["path"]["p"]["length"].get<double>();
  EXPECT_NEAR(std::stod(metric), length, 1e-5 * length);
  // The scene's own method, P6, which no panel draws, gives another length.
  panel_scene["method"] = "P6";
  dir.write("p6.json", panel_scene.dump());
  const RunResult p6 = run_pita({"measure", "p6.json", "--format", "json"}, dir.path());
  const double own = Json::parse(p6.out)["motions"][0]["path"]["p"]["length"].get<double>();
  EXPECT_GT(std::abs(own - length), 1e-3 * length);
}

// An axis whose every value gives the same outputs as its first is named.
TEST(Sweep, SaysWhichAxisChangedNothing) {
  ScratchDir dir;
  dir.write("s.json", kFigureOneScene);
  const RunResult r = run_pita({"sweep", "s.json", "--vary", "/options/knots=increasing,as-given", "--vary",
                                "/keyframes/1/w=0.5,1", "-o", "out", "--format", "svg"},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("/options/knots changed nothing: every value of it gave the same figures (titles aside) and "
                       "metrics as its first value"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("/keyframes/1/w changed nothing"), std::string::npos) << r.err;
}

// A part that is not a regular file (a link to /dev/zero, a FIFO) is
// ignored with its reason, at once: never read without end or waited on.
TEST(Sweep, MergeRefusesPartsThatAreNotRegularFiles) {
  ScratchDir dir;
  dir.write("s.json", kFigureOneScene);
  for (const std::string shard : {"0/2", "1/2"}) {
    ASSERT_EQ(run_pita({"sweep", "s.json", "--vary", "/keyframes/1/w=1,2,3,4", "-o", "out", "--shard", shard, "-q"},
                       dir.path())
                  .exit_code,
              0);
  }
  fs::remove(dir.path() / "out/manifest.1-of-2.csv");
  fs::create_symlink("/dev/zero", dir.path() / "out/manifest.1-of-2.csv");
  const RunResult r = run_pita({"sweep", "--merge", "out"}, dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("manifest.1-of-2.csv: cannot read the manifest: it is a device, not a regular file"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("2 variants missing: 1, 3"), std::string::npos) << r.err;
}

// The folder's index/ is the sweep's own: a symbolic link to another folder
// is refused before anything runs, and nothing of that folder is removed.
TEST(Sweep, AnIndexFolderThatIsALinkIsRefused) {
  ScratchDir dir;
  dir.write("s.json", kFigureOneScene);
  ASSERT_EQ(run_pita({"sweep", "s.json", "--vary", "/keyframes/1/w=1,2", "-o", "out", "-q"}, dir.path()).exit_code, 0);
  fs::create_directories(dir.path() / "other");
  dir.write("other/rows-5.js", "theirs");
  fs::remove_all(dir.path() / "out/index");
  fs::create_directory_symlink("../other", dir.path() / "out/index");
  const RunResult r =
      run_pita({"sweep", "s.json", "--vary", "/keyframes/1/w=1,2", "-o", "out", "-q", "--force"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("out/index: cannot write: it is a symbolic link, not the sweep's own folder"), std::string::npos)
      << r.err;
  EXPECT_EQ(read_file(dir.path() / "other/rows-5.js"), "theirs");
}

TEST(Sweep, FailedVariantsAreRowsAndTheOthersAreWritten) {
  ScratchDir dir;
  const RunResult r = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/m=-1,0.8,abc", "-o", "out", "-q"}, dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("variant 0 (/keyframes/1/m = -1)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/keyframes/1/m"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("variant 2 (/keyframes/1/m = abc)"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / "out/fig13-knot-ratio-1.svg"));
  EXPECT_FALSE(fs::exists(dir.path() / "out/fig13-knot-ratio-0.svg"));
  const std::vector<std::string> status = column(read_file(dir.path() / "out/manifest.csv"), 2);
  ASSERT_EQ(status.size(), 3u);
  EXPECT_NE(status[0], "ok");
  EXPECT_EQ(status[1], "ok");
}

TEST(Sweep, NoSamIsAFailedRowAndPoseMetricsAreFilled) {
  ScratchDir dir;
  dir.write("poses.json", R"({"method": "SAM", "shapes": [{"outline": "F"}], "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 1], [0, 0.5, 1]]}]})");
  // (-2, -0.5) gives two distinct negative eigenvalues: no SAM (no real logarithm).
  const RunResult r = run_pita({"sweep", "poses.json", "--vary", "/poses/1/matrix/0/0=2,-2", "--vary",
                                "/poses/1/matrix/1/1=0.5,-0.5", "--zip", "-o", "out", "--format", "csv", "-q"},
                               dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("variant 1 (/poses/1/matrix/0/0 = -2, /poses/1/matrix/1/1 = -0.5): poses-1.scene.json: /poses: "
                       "no SAM exists"),
            std::string::npos)
      << r.err;
  const std::string manifest = read_file(dir.path() / "out/manifest.csv");
  EXPECT_EQ(column(manifest, 3).at(0), "ok");
  // Row 0 is a SAM: ARA (SAM paper Sec. 2.4) is 0 to rounding, and the area monotone.
  const std::vector<std::string> header = [&] {
    std::vector<std::string> h;
    std::string line = lines_of(manifest).front();
    for (std::size_t at = 0; at != std::string::npos;) {
      const std::size_t comma = line.find(',', at);
      h.push_back(line.substr(at, comma == std::string::npos ? comma : comma - at));
      at = comma == std::string::npos ? comma : comma + 1;
    }
    return h;
  }();
  const auto at = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  EXPECT_LT(std::abs(std::stod(column(manifest, at("ara")).at(0))), 1e-9);
  EXPECT_EQ(column(manifest, at("area_monotone")).at(0), "yes");
  EXPECT_TRUE(fs::exists(dir.path() / "out/poses-1.scene.json"));  // kept, to reproduce the error
  EXPECT_FALSE(fs::exists(dir.path() / "out/poses-1.csv"));
}

TEST(Sweep, ProgressBarOnATerminalLinesOffIt) {
  if (::access("/usr/bin/script", X_OK) != 0) GTEST_SKIP() << "script(1) is not installed (util-linux)";
  ScratchDir dir;
  // A terminal (script(1) gives pita one), CI unset: the bar, redrawn with \r.
  const std::string command =
      fmt::format("cd {} && env -u CI script -qec '{} sweep {} --vary /keyframes/1/t=0.1:0.9:20 -o tty' /dev/null 2>&1",
                  dir.path().string(), pita_binary(), kFig13);
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string shown;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) shown.append(buffer, n);
  EXPECT_EQ(::pclose(pipe), 0) << shown;
  EXPECT_NE(shown.find("\rpita sweep ["), std::string::npos) << shown;
  EXPECT_NE(shown.find("20/20 (100%)"), std::string::npos) << shown;
  // -q: no bar even there.
  const std::string quiet = fmt::format(
      "cd {} && env -u CI script -qec '{} sweep {} --vary /keyframes/1/t=0.1:0.9:20 -o tty2 -q' /dev/null 2>&1",
      dir.path().string(), pita_binary(), kFig13);
  pipe = ::popen(quiet.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  shown.clear();
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) shown.append(buffer, n);
  EXPECT_EQ(::pclose(pipe), 0) << shown;
  EXPECT_EQ(shown.find("pita sweep ["), std::string::npos) << shown;
}

TEST(Sweep, ResumesSkipsWhatIsDoneAndForceRedoesIt) {
  ScratchDir dir;
  const std::vector<std::string> args = {"sweep", kFig13, "--vary", "/keyframes/1/t=0.2:0.8:4", "-o", "out", "-q"};
  ASSERT_EQ(run_pita(args, dir.path()).exit_code, 0);
  const std::string first = read_file(dir.path() / "out/manifest.csv");
  RunResult again = run_pita(args, dir.path());
  EXPECT_NE(again.out.find("0 written, 4 resumed"), std::string::npos) << again.out;
  fs::remove(dir.path() / "out/fig13-knot-ratio-2.svg");
  again = run_pita(args, dir.path());
  EXPECT_NE(again.out.find("1 written, 3 resumed"), std::string::npos) << again.out;
  EXPECT_TRUE(fs::exists(dir.path() / "out/fig13-knot-ratio-2.svg"));
  EXPECT_EQ(read_file(dir.path() / "out/manifest.csv"), first);
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  again = run_pita(forced, dir.path());
  EXPECT_NE(again.out.find("4 written, 0 resumed"), std::string::npos) << again.out;
  // Other values at the same indices: new hashes, so every variant is redone.
  std::vector<std::string> changed = args;
  changed[3] = "/keyframes/1/t=0.3:0.7:4";
  again = run_pita(changed, dir.path());
  EXPECT_NE(again.out.find("4 written, 0 resumed"), std::string::npos) << again.out;
}

TEST(Sweep, ShardsMergeIntoTheUnshardedRun) {
  ScratchDir dir;
  const std::vector<std::string> base = {
      "sweep", kFig13, "--vary", "/keyframes/1/t=0.2:0.8:4", "--vary", "/method=P1,P6", "--format", "svg,csv", "-q"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return run_pita(a, dir.path());
  };
  ASSERT_EQ(with({"-o", "whole"}).exit_code, 0);
  ASSERT_EQ(with({"-o", "parts", "--shard", "0/3"}).exit_code, 0);
  ASSERT_EQ(with({"-o", "parts", "--shard", "2/3"}).exit_code, 0);
  EXPECT_FALSE(fs::exists(dir.path() / "parts/manifest.csv"));
  RunResult merged = run_pita({"sweep", "--merge", "parts"}, dir.path());
  EXPECT_EQ(merged.exit_code, 1);
  EXPECT_NE(merged.err.find("missing: 1, 4, 7"), std::string::npos) << merged.err;
  EXPECT_NE(merged.err.find("the shards with variants missing: shard 1/3 (3 of 3)"), std::string::npos) << merged.err;
  ASSERT_EQ(with({"-o", "parts", "--shard", "1/3"}).exit_code, 0);
  merged = run_pita({"sweep", "--merge", "parts"}, dir.path());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(read_file(dir.path() / "parts/manifest.csv"), read_file(dir.path() / "whole/manifest.csv"));
  EXPECT_EQ(read_file(dir.path() / "parts/contact.svg"), read_file(dir.path() / "whole/contact.svg"));
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(read_file(dir.path() / fmt::format("parts/fig13-knot-ratio-{}.csv", i)),
              read_file(dir.path() / fmt::format("whole/fig13-knot-ratio-{}.csv", i)));
  }
  EXPECT_EQ(run_pita({"sweep", "--merge", "whole"}, dir.path()).exit_code, 2);  // no parts there
}

// --merge reads its parts side by side, one open file each: it raises the
// soft limit of open files (ulimit -n) when the parts need it, and when even
// the hard limit is too few, it says so (exit 2) instead of leaving parts out.
// A part it cannot open is an error, never a shard silently missing.
TEST(Sweep, MergeOfManyPartsRaisesTheOpenFilesLimitOrSaysWhy) {
  ScratchDir dir;
  constexpr int kParts = 40;
  for (int k = 0; k < kParts; ++k) {
    const RunResult shard = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0.1:0.9:80", "--format", "metrics",
                                      "-o", "parts", "-q", "--shard", fmt::format("{}/{}", k, kParts)},
                                     dir.path());
    ASSERT_EQ(shard.exit_code, 0) << shard.err;
  }
  ASSERT_EQ(
      run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0.1:0.9:80", "--format", "metrics", "-o", "whole", "-q"},
               dir.path())
          .exit_code,
      0);
  const auto merge_with = [&](const std::string& limits) {
    const std::string command =
        fmt::format("cd '{}' && bash -c '{}; exec \"$0\" sweep --merge parts' '{}' >merge.out 2>merge.err",
                    dir.path().string(), limits, pita_binary());
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  // A soft limit of 60 (the parts and pita's others need 104), a hard one above: raised, merged.
  ASSERT_EQ(merge_with("ulimit -Sn 60"), 0) << read_file(dir.path() / "merge.err");
  EXPECT_EQ(read_file(dir.path() / "parts/manifest.csv"), read_file(dir.path() / "whole/manifest.csv"));
  // A hard limit of 60: refused, saying why; the manifest stays as it was.
  fs::remove(dir.path() / "parts/manifest.csv");
  EXPECT_EQ(merge_with("ulimit -n 60"), 2);
  const std::string err = read_file(dir.path() / "merge.err");
  EXPECT_NE(err.find("its 40 parts need 104 open files, more than this process may open (60"), std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(dir.path() / "parts/manifest.csv"));
}

TEST(Sweep, MergeIgnoresTheRowsOfAnotherSweep) {
  // Shards of an earlier sweep left in the folder (other values, other N)
  // must not be merged into this one.
  ScratchDir dir;
  const auto run = [&](const std::string& spec, const std::vector<std::string>& extra) {
    std::vector<std::string> a = {"sweep", kFig13, "--vary", "/keyframes/1/m=" + spec, "--format", "csv", "-q"};
    a.insert(a.end(), extra.begin(), extra.end());
    return run_pita(a, dir.path());
  };
  ASSERT_EQ(run("0.5:1.5:5", {"-o", "d", "--shard", "0/2"}).exit_code, 0);
  ASSERT_EQ(run("0.5:1.5:5", {"-o", "d", "--shard", "1/2"}).exit_code, 0);
  for (const std::string k : {"0", "1", "2"})
    ASSERT_EQ(run("0.6,0.7,0.8,0.9,1", {"-o", "d", "--shard", k + "/3"}).exit_code, 0);
  ASSERT_EQ(run("0.6,0.7,0.8,0.9,1", {"-o", "whole"}).exit_code, 0);
  const RunResult merged = run_pita({"sweep", "--merge", "d"}, dir.path());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_NE(merged.err.find("belong to another sweep"), std::string::npos) << merged.err;
  EXPECT_EQ(read_file(dir.path() / "d/manifest.csv"), read_file(dir.path() / "whole/manifest.csv"));
}

TEST(Sweep, AFolderOfAnotherSweepIsRefusedUnlessForced) {
  ScratchDir dir;
  ASSERT_EQ(run_pita({"sweep", kFig13, "--vary", "/keyframes/1/m=0.5:1.5:3", "-o", "d", "-q"}, dir.path()).exit_code,
            0);
  const std::string definition = read_file(dir.path() / "d/sweep.json");
  const RunResult other = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0.3,0.5", "-o", "d", "-q"}, dir.path());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("not the manifest of this sweep"), std::string::npos) << other.err;
  EXPECT_EQ(read_file(dir.path() / "d/sweep.json"), definition);  // nothing written
  const RunResult forced =
      run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0.3,0.5", "-o", "d", "-q", "--force"}, dir.path());
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
}

TEST(Sweep, TinyValuesListsOfStringsAndFileModes) {
  ScratchDir dir;
  const mode_t old = ::umask(022);
  // Subnormal values between the ends are numbers like any other.
  const RunResult tiny = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/w=0:1e-307:40", "-o", "tiny", "--format",
                                   "csv,json", "--jobs", "2", "-q"},
                                  dir.path());
  ::umask(old);
  EXPECT_EQ(tiny.exit_code, 0) << tiny.err;
  // Two threads write at once: every file gets the umask's mode, 0644 (index.html's data folder 0755).
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir.path() / "tiny")) {
    if (e.is_directory()) {
      EXPECT_EQ(e.status().permissions() & fs::perms::all, fs::perms::owner_all | fs::perms::group_read |
                                                               fs::perms::group_exec | fs::perms::others_read |
                                                               fs::perms::others_exec)
          << e.path();
      continue;
    }
    EXPECT_EQ(e.status().permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read)
        << e.path();
  }
  // JSON strings in a list: commas and quotes inside, a string that looks like a number.
  const RunResult titles =
      run_pita({"sweep", kFig13, "--vary", R"(/title="a, \"b\"",c,"1")", "-o", "t", "-q"}, dir.path());
  ASSERT_EQ(titles.exit_code, 0) << titles.err << titles.out;
  EXPECT_EQ(Json::parse(read_file(dir.path() / "t/fig13-knot-ratio-0.scene.json"))["title"], "a, \"b\"");
  EXPECT_EQ(Json::parse(read_file(dir.path() / "t/fig13-knot-ratio-2.scene.json"))["title"], "1");
}

TEST(Sweep, InterruptedSweepLeavesCompleteFilesAndResumes) {
  ScratchDir dir;
  const std::vector<std::string> args = {
      "sweep", kFig13, "--vary", "/keyframes/1/t=0.05:0.95:150", "-o", "out", "--format", "svg", "--jobs", "2", "-q"};
  Started started = start_pita(args, dir.path());
  // Signalled once a row is journaled (a variant's file can be in place a
  // moment before its row is recorded: a run stopped then has no row yet,
  // and redoes that variant when resumed).
  const fs::path journal = dir.path() / "out/.manifest.csv.journal";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const auto journaled = [&] {
    if (!fs::exists(journal)) return false;
    const std::string text = read_file(journal);
    return std::count(text.begin(), text.end(), '\n') >= 1;
  };
  while (!journaled() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(started.pid, SIGTERM);
  const RunResult r = finish_pita(started);
  ASSERT_EQ(r.exit_code, 128 + SIGTERM) << "finished before the signal: " << r.out << r.err;
  const std::string partial = read_file(dir.path() / "out/manifest.csv");
  const std::size_t rows = lines_of(partial).size() - 1;
  EXPECT_GE(rows, 1u);
  EXPECT_LT(rows, 150u);
  for (const fs::directory_entry& e : fs::directory_iterator(dir.path() / "out")) {
    const std::string name = e.path().filename().string();
    if (name == ".pita-sweep" || name == ".manifest.csv.lock") continue;  // the folder's marker and lock
    EXPECT_NE(name.front(), '.') << "a temporary is left: " << e.path();
  }
  for (const std::string& index : column(partial, 0)) {
    EXPECT_TRUE(fs::exists(dir.path() / fmt::format("out/fig13-knot-ratio-{}.svg", index)));
  }
  const RunResult resumed = run_pita(args, dir.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(fmt::format("{} resumed", rows)), std::string::npos) << resumed.out;
  std::vector<std::string> fresh = args;
  fresh[5] = "fresh";
  ASSERT_EQ(run_pita(fresh, dir.path()).exit_code, 0);
  EXPECT_EQ(read_file(dir.path() / "out/manifest.csv"), read_file(dir.path() / "fresh/manifest.csv"));
}

TEST(Sweep, AKilledSweepResumesFromItsJournal) {
  // SIGKILL leaves no chance to write the manifest: the rows journaled so far
  // (a hidden file, in index order) are what the next run resumes from.
  ScratchDir dir;
  const std::vector<std::string> args = {
      "sweep", kFig13, "--vary", "/keyframes/1/t=0.05:0.95:150", "-o", "out", "--format", "csv", "--jobs", "1", "-q"};
  Started started = start_pita(args, dir.path());
  const fs::path journal = dir.path() / "out/.manifest.csv.journal";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const auto journaled = [&] {
    if (!fs::exists(journal)) return false;
    const std::string text = read_file(journal);
    return std::count(text.begin(), text.end(), '\n') >= 3;
  };
  while (!journaled() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(started.pid, SIGKILL);
  const RunResult r = finish_pita(started);
  ASSERT_EQ(r.exit_code, 128 + SIGKILL) << "finished before the signal";
  ASSERT_TRUE(fs::exists(journal));
  const std::string text = read_file(journal);
  const auto rows = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  const RunResult resumed = run_pita(args, dir.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(fmt::format("{} resumed", rows)), std::string::npos) << resumed.out;
  EXPECT_FALSE(fs::exists(journal));
  std::vector<std::string> fresh = args;
  fresh[5] = "fresh";
  ASSERT_EQ(run_pita(fresh, dir.path()).exit_code, 0);
  EXPECT_EQ(read_file(dir.path() / "out/manifest.csv"), read_file(dir.path() / "fresh/manifest.csv"));
}

// Issue 37: a sweep writes only into a folder that is new, empty or its own:
// a user's index.html or contact.svg in the folder, or a base scene named
// sweep.json, is never replaced (exit 3, nothing written).
TEST(Sweep, NeverOverwritesWhatASweepDidNotWrite) {
  ScratchDir dir;
  dir.write("mine/index.html", "my page");
  dir.write("mine/contact.svg", "<svg>mine</svg>");
  const RunResult r = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/m=0.5,1", "-o", "mine", "-q"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("-o mine: cannot write: the folder holds files that a sweep did not write"), std::string::npos)
      << r.err;
  EXPECT_EQ(read_file(dir.path() / "mine/index.html"), "my page");
  EXPECT_EQ(read_file(dir.path() / "mine/contact.svg"), "<svg>mine</svg>");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path() / "mine"), fs::directory_iterator()), 2);

  const std::string base = read_file(kFig13);
  dir.write("here/sweep.json", base);
  const RunResult self =
      run_pita({"sweep", "sweep.json", "--vary", "/keyframes/1/m=0.5,1", "-o", ".", "-q"}, dir.path() / "here");
  EXPECT_EQ(self.exit_code, 3) << self.err;
  EXPECT_NE(self.err.find("would replace the base scene"), std::string::npos) << self.err;
  EXPECT_EQ(read_file(dir.path() / "here/sweep.json"), base);

  // Its own folder, and an empty one, are fine.
  fs::create_directories(dir.path() / "empty");
  ASSERT_EQ(run_pita({"sweep", kFig13, "--vary", "/keyframes/1/m=0.5,1", "-o", "empty", "-q"}, dir.path()).exit_code,
            0);
  EXPECT_TRUE(fs::exists(dir.path() / "empty/.pita-sweep"));
  EXPECT_EQ(run_pita({"sweep", kFig13, "--vary", "/keyframes/1/m=0.5,1,2", "-o", "empty", "-q", "--force"}, dir.path())
                .exit_code,
            0);
}

// One run at a time writes a manifest: a second is refused naming the
// holder's PID (exit 2), or waits with --wait.
TEST(Sweep, ASecondRunIntoTheFolderIsRefusedOrWaits) {
  ScratchDir dir;
  const std::vector<std::string> args = {"sweep", kFig13, "--vary", "/keyframes/1/m=0.5,1", "-o", "out", "-q"};
  ASSERT_EQ(run_pita(args, dir.path()).exit_code, 0);
  const std::string manifest = read_file(dir.path() / "out/manifest.csv");
  // This test holds the lock, as a running sweep would.
  const int fd = ::open((dir.path() / "out/.manifest.csv.lock").c_str(), O_RDWR | O_CLOEXEC);  // not inherited by pita
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX), 0);
  const std::string pid = std::to_string(::getpid()) + "\n";
  ASSERT_EQ(::pwrite(fd, pid.data(), pid.size(), 0), static_cast<ssize_t>(pid.size()));
  std::vector<std::string> forced = args;
  forced.push_back("--force");
  const RunResult refused = run_pita(forced, dir.path());
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find(fmt::format("another pita sweep (PID {}) is writing manifest.csv", ::getpid())),
            std::string::npos)
      << refused.err;
  forced.push_back("--wait");
  Started waiting = start_pita(forced, dir.path());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  int status = 0;
  EXPECT_EQ(::waitpid(waiting.pid, &status, WNOHANG), 0) << "did not wait for the lock";
  ::close(fd);  // releases it
  const RunResult waited = finish_pita(waiting);
  EXPECT_EQ(waited.exit_code, 0) << waited.err;
  EXPECT_EQ(read_file(dir.path() / "out/manifest.csv"), manifest);
}

// What a SIGKILLed run left half-written (hidden temporaries of its own
// outputs) is removed by the next run; other hidden files stay.
TEST(Sweep, AResumedRunRemovesTheTemporariesOfAKilledOne) {
  ScratchDir dir;
  const std::vector<std::string> args = {"sweep", kFig13, "--vary", "/keyframes/1/m=0.5,1", "-o", "out", "-q"};
  ASSERT_EQ(run_pita(args, dir.path()).exit_code, 0);
  dir.write("out/.fig13-knot-ratio-1.svg.Ab12Cd", "<svg");
  dir.write("out/.manifest.csv.x9Y8z7", "index");
  dir.write("out/.my-notes.txt.Ab12Cd", "keep");
  const RunResult r = run_pita(args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out/.fig13-knot-ratio-1.svg.Ab12Cd"));
  EXPECT_FALSE(fs::exists(dir.path() / "out/.manifest.csv.x9Y8z7"));
  EXPECT_TRUE(fs::exists(dir.path() / "out/.my-notes.txt.Ab12Cd"));
}

// More threads than slots for temporaries (--jobs on a 256-core node): every
// variant is written.
TEST(Sweep, ManyJobsWriteEveryVariant) {
  ScratchDir dir;
  const RunResult r = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/m=0.5:1.5:300", "-o", "out", "--jobs", "256",
                                "--format", "svg,csv", "-q"},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("300 variants: 300 written"), std::string::npos) << r.out;
  EXPECT_EQ(lines_of(read_file(dir.path() / "out/manifest.csv")).size(), 301u);
}

// Issue 37: a variant's frames obey pita eval's work limit (a failed row at
// once, naming /chain), where they used to run for minutes.
TEST(Sweep, FramesOfAVariantObeyEvalsWorkLimit) {
  ScratchDir dir;
  std::string keyframes;
  for (int i = 0; i < 64; ++i) {
    keyframes +=
        fmt::format("{}{{\"t\": {}, \"p\": [{}, {}], \"m\": 1, \"w\": 0.1}}", i == 0 ? "" : ", ", i, i, (i % 2) * 0.5);
  }
  dir.write("n64.json", R"({"method": "P6", "chain": "neville", "keyframes": [)" + keyframes + "]}");
  const auto start = std::chrono::steady_clock::now();
  const RunResult r =
      run_pita({"sweep", "n64.json", "--vary", "/samples=1000000", "--format", "csv", "-o", "out", "-q"}, dir.path());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));  // generous: refused up front
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("/chain: 1000000 frames of the"), std::string::npos) << r.err;
  EXPECT_NE(read_file(dir.path() / "out/manifest.csv").find("above the limit"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir.path() / "out/n64-0.csv"));
}

// A swept bare string with a control character is refused (exit 2).
TEST(Sweep, ControlCharactersInSweptStringsAreRefused) {
  ScratchDir dir;
  const RunResult r = run_pita({"sweep", kFig13, "--vary", "/title=plain,\x1b[31mred", "-o", "out", "-q"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("\\x1b[31mred contains the control character U+001B"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

// --merge takes the parts' rows in any order, refuses a variant twice in a
// part or two different rows of one variant, naming part and line.
TEST(Sweep, MergeSortsAndRefusesDuplicatesAndConflicts) {
  ScratchDir dir;
  const std::vector<std::string> base = {"sweep",    kFig13, "--vary", "/keyframes/1/t=0.1:0.9:9",
                                         "--format", "csv",  "-q"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return run_pita(a, dir.path());
  };
  ASSERT_EQ(with({"-o", "whole"}).exit_code, 0);
  ASSERT_EQ(with({"-o", "parts", "--shard", "0/2"}).exit_code, 0);
  ASSERT_EQ(with({"-o", "parts", "--shard", "1/2"}).exit_code, 0);
  const fs::path part0 = dir.path() / "parts/manifest.0-of-2.csv", part1 = dir.path() / "parts/manifest.1-of-2.csv";
  const std::vector<std::string> rows0 = lines_of(read_file(part0)), rows1 = lines_of(read_file(part1));
  const auto write_rows = [](const fs::path& path, const std::vector<std::string>& rows) {
    std::ofstream out(path, std::ios::binary);
    for (const std::string& row : rows) out << row << '\n';
  };
  // Reversed rows.
  std::vector<std::string> reversed = {rows0[0]};
  reversed.insert(reversed.end(), rows0.rbegin(), rows0.rend() - 1);
  write_rows(part0, reversed);
  RunResult merged = run_pita({"sweep", "--merge", "parts"}, dir.path());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(merged.err.find("missing"), std::string::npos) << merged.err;
  EXPECT_EQ(read_file(dir.path() / "parts/manifest.csv"), read_file(dir.path() / "whole/manifest.csv"));
  // A row twice in one part.
  std::vector<std::string> twice = rows1;
  twice.push_back(rows1[1]);
  write_rows(part1, twice);
  merged = run_pita({"sweep", "--merge", "parts"}, dir.path());
  EXPECT_EQ(merged.exit_code, 2) << merged.err;
  EXPECT_NE(merged.err.find("manifest.1-of-2.csv: variant 1 appears twice, on lines 2 and 6"), std::string::npos)
      << merged.err;
  // One variant in two parts with different rows.
  std::vector<std::string> conflicting = rows1;
  std::string changed = rows0[1];  // variant 0
  changed.replace(changed.find(",ok,"), 4, ",err,");
  conflicting.insert(conflicting.begin() + 1, changed);
  write_rows(part1, conflicting);
  merged = run_pita({"sweep", "--merge", "parts"}, dir.path());
  EXPECT_EQ(merged.exit_code, 2) << merged.err;
  EXPECT_NE(merged.err.find("variant 0 has two different rows"), std::string::npos) << merged.err;
  EXPECT_NE(merged.err.find("manifest.1-of-2.csv:2"), std::string::npos) << merged.err;
}

TEST(Sweep, BadUsageExitsTwoAndWritesNothing) {
  ScratchDir dir;
  dir.write("file", "x");
  dir.write("bad.json", "{\"method\": \"P6\"}");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--vary", "/keyframes/7/t=0:1:3"}, "nearest pointer that exists is /keyframes/2/t"},
      {{"--vary", "/keyframs/1/t=0:1:3"}, "nearest pointer that exists is /keyframes/1/t"},
      {{"--vary", "/keyframes/1/tt=0:1:3"}, "did you mean \"t\""},
      {{"--vary", "/keyframes/1/w=-1e308:1e308:5"}, "not all finite"},
      {{"--vary", "/keyframes/1/t=0:1:3", "--vary", "/keyframes/1/t=2,3"}, "varied twice"},
      {{"--vary", "/keyframes/1/t=0:1"}, "SPEC must be"},
      {{"--vary", "/keyframes/1/t=0:1:0"}, "must be >= 1"},
      {{"--vary", "/keyframes/1/t=0:1:5000", "--vary", "/keyframes/1/m=1:2:5000"}, "more than the limit"},
      {{"--vary", "/keyframes/1/t=0:1:3", "--vary", "/method=P1,P2", "--zip"}, "--zip"},
      {{"--vary", "/keyframes/1/t=0:1:3", "--shard", "3/3"}, "--shard"},
      {{"--vary", "/keyframes/1/t=0:1:3", "--format", "gif"}, "--format"},
      {{"--vary", "/keyframes/1/t=0:1:3", "--jobs", "0"}, "--jobs"},
      {{}, "--vary"},
      // Axes that run no variant: every value refused at the axis's pointer.
      {{"--vary", "/keyframes/1/m=-1,-2"}, "every value is refused, so no variant would run: /keyframes/1/m:"},
  };
  for (const auto& [extra, message] : cases) {
    std::vector<std::string> args = {"sweep", kFig13, "-o", "out"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_pita(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << fmt::format("{}", fmt::join(extra, " "));
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out")) << fmt::format("{}", fmt::join(extra, " "));
  }
  const RunResult folder = run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0:1:3", "-o", "file/out"}, dir.path());
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_NE(folder.err.find("cannot create the output folder"), std::string::npos) << folder.err;
  // A file's name is not a folder to create.
  const RunResult file_name =
      run_pita({"sweep", kFig13, "--vary", "/keyframes/1/t=0:1:3", "-o", "out.png"}, dir.path());
  EXPECT_EQ(file_name.exit_code, 2);
  EXPECT_NE(file_name.err.find("-o out.png: a sweep writes into a folder, and \".png\" is the extension of a file"),
            std::string::npos)
      << file_name.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
  // An option the method does not read: every value is refused.
  dir.write("p6.json", kFigureOneScene);
  const RunResult anchor = run_pita({"sweep", "p6.json", "--vary", "/keyframes/1/t=0.2:0.8:3", "--vary",
                                     "/options/anchor=start,midpoint", "-o", "out"},
                                    dir.path());
  EXPECT_EQ(anchor.exit_code, 2);
  EXPECT_NE(anchor.err.find("/options/anchor=start,midpoint: every value is refused, so no variant would run: "
                            "/options/anchor: P6 La-LP does not read \"anchor\""),
            std::string::npos)
      << anchor.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  const RunResult scene = run_pita({"sweep", "bad.json", "--vary", "/method=P1", "-o", "out"}, dir.path());
  EXPECT_EQ(scene.exit_code, 2);
  EXPECT_NE(scene.err.find("bad.json: /keyframes"), std::string::npos) << scene.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(SweepChromium, IndexSortsByAMetricColumn) {
  const std::string chromium = fs::exists("/usr/bin/chromium") ? "/usr/bin/chromium" : "";
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (Debian package chromium)";
  ScratchDir dir;
  // The knot of the first panel's B, whose motion the metrics measure.
  const RunResult r =
      run_pita({"sweep", kFig13, "--vary", "/panels/0/keyframes/1/t=0.1:0.9:6", "-o", "out", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The expected order: the manifest's rows by discrepancy_max, largest first.
  const std::string manifest = read_file(dir.path() / "out/manifest.csv");
  const std::vector<std::string> index = column(manifest, 0), e = column(manifest, 11);  // discrepancy_max
  std::vector<std::size_t> order(index.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return std::stod(e[a]) > std::stod(e[b]); });
  std::vector<std::string> want;
  for (const std::size_t i : order) want.push_back(index[i]);
  ASSERT_NE(want.front(), "0");  // the sort moves something
  const std::string command = fmt::format(
      "timeout 120 {} --headless --no-sandbox --disable-gpu --user-data-dir={} --virtual-time-budget=10000 --dump-dom "
      "'file://{}#sort=discrepancy_max&order=desc' 2>/dev/null",
      chromium, (dir.path() / "profile").string(), (dir.path() / "out/index.html").string());
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string dom;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) dom.append(buffer, n);
  EXPECT_EQ(::pclose(pipe), 0);
  std::vector<std::string> shown;
  const std::regex cell("<tr class=\"[a-z]+\" data-index=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(dom.begin(), dom.end(), cell); it != std::sregex_iterator(); ++it) {
    shown.push_back((*it)[1]);
  }
  EXPECT_EQ(shown, want) << dom.substr(0, 2000);
}

// 3D pose scenes sweep as the plane's do: here over an entry of a pose of
// space (the second pose's x translation), each variant with its figure, its
// frames (3x4 rows, the swept entry in place) and its metrics (the ARA of a
// polySAM, steady within each span: about 0).
TEST(Sweep, SweepsAnEntryOfAPoseOfSpace) {
  const ScratchDir dir;
  const RunResult result = run_pita({"sweep", std::string(PITA_SOURCE_DIR) + "/scenes/sam-3d-fig13-polysam.json",
                                     "--vary", "/poses/1/matrix/0/3=2:4:3", "-o", "out", "--format", "png,json", "-q"},
                                    dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string manifest = read_file(dir.path() / "out" / "manifest.csv");
  EXPECT_EQ(std::count(manifest.begin(), manifest.end(), '\n'), 4) << manifest;  // the header and 3 variants
  for (const double x : {2.0, 3.0, 4.0}) {
    EXPECT_NE(manifest.find(fmt::format(",{},", x)), std::string::npos) << x << "\n" << manifest;
  }
  int frames_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "out")) {
    const std::string name = entry.path().filename().string();
    if (!name.ends_with(".json") || name.ends_with("scene.json") || name == "sweep.json") continue;
    const nlohmann::json frames = nlohmann::json::parse(read_file(entry.path()));
    if (!frames.contains("frames")) continue;
    ++frames_files;
    ASSERT_FALSE(frames["frames"].empty()) << name;
    EXPECT_EQ(frames["frames"][0]["matrix"].size(), 3u) << name;
    EXPECT_EQ(frames["frames"][0]["matrix"][0].size(), 4u) << name;
  }
  EXPECT_EQ(frames_files, 3);
}

}  // namespace
}  // namespace pita::test
