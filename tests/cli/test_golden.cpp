// `pita check` and `pita update-goldens` (src/cli/golden.cpp) through the real
// binary, on scenes and goldens made in a scratch directory.
#include <filesystem>
#include <functional>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;

std::string scene(const std::string& middle_x) {
  return R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [)" +
         middle_x + R"(, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
  "layers": [{"type": "pattern"}, {"type": "stroke"}, {"type": "discrepancy", "scale": 0.1}, {"type": "keyframes"}]})";
}

std::string fmt_name(int i) { return "s" + std::to_string(i) + ".json"; }

class Check : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("fig.json", scene("3"));
    const RunResult r = run({"update-goldens", "fig.json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("golden/fig/fig.png: new"), std::string::npos) << r.out;
  }
  RunResult run(const std::vector<std::string>& args) { return run_pita(args, dir.path()); }
  ScratchDir dir;
};

TEST_F(Check, UntouchedSceneMatches) {
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ok    fig.json"), std::string::npos) << r.out;
}

TEST_F(Check, PerturbedKeyframeFailsNamingLayerAndFrame) {
  dir.write("fig.json", scene("3.001"));
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("FAIL  fig.json"), std::string::npos) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("layer /layers/[0-9]+, frame [0-9]+"))) << r.err;
}

TEST_F(Check, ChangeBelowToleranceMatches) {
  dir.write("fig.json", scene("3.0000000000001"));
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(Check, MissingGoldenFails) {
  dir.write("other.json", scene("3"));
  const RunResult r = run({"check", "fig.json", "other.json"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("golden/other/other.data.json: no golden file"), std::string::npos) << r.err;
}

TEST_F(Check, ReportReferencesImagesThatExist) {
  dir.write("fig.json", scene("3.2"));
  const RunResult r = run({"check", "fig.json", "--report", "report"});
  EXPECT_EQ(r.exit_code, 1);
  const std::string html = read_file(dir.path() / "report/index.html");
  ASSERT_FALSE(html.empty());
  const std::regex image("<img src=\"([^\"]+)\"");
  int images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), image); it != std::sregex_iterator(); ++it) {
    EXPECT_TRUE(fs::exists(dir.path() / "report" / (*it)[1].str())) << (*it)[1].str();
    ++images;
  }
  EXPECT_EQ(images, 3);  // expected, actual, diff
  EXPECT_NE(html.find("DIFFERS"), std::string::npos);
}

// The report never replaces what the check read: not a golden (it is refused
// among them, exit 2), not an image a scene draws.
TEST_F(Check, TheReportNeverReplacesAnInput) {
  dir.write("fig.json", scene("3.2"));
  const std::string golden = read_file(dir.path() / "golden/fig/fig.png");
  for (const char* folder : {"golden/fig", "golden", "./golden/../golden/x"}) {
    const RunResult r = run({"check", "fig.json", "--report", folder});
    EXPECT_EQ(r.exit_code, 2) << folder;
    EXPECT_NE(r.err.find("among the goldens"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_file(dir.path() / "golden/fig/fig.png"), golden);
  EXPECT_FALSE(fs::exists(dir.path() / "golden/fig/index.html"));
  EXPECT_FALSE(fs::exists(dir.path() / "golden/x"));

  // A scene drawing the image the report would name its actual PNG.
  fs::copy_file(dir.path() / "golden/fig/fig.png", dir.path() / "pic.actual.png");
  std::string drawing = scene("3");
  drawing.insert(drawing.rfind('}'), R"(, "shapes": [{"image": "pic.actual.png", "box": [[0, 0], [1, 1]]}])");
  dir.write("pic.json", drawing);
  const RunResult r = run({"check", "pic.json", "--report", "."});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("would replace ./pic.actual.png, an input of this check"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(dir.path() / "pic.actual.png"), golden);
  EXPECT_FALSE(fs::exists(dir.path() / "index.html"));
}

// Claims (docs/reference/check.md "Claims"): measured on the motions drawn; one that does not
// hold fails `check` (exit 1) naming its pointer, words and values, while
// the goldens still match, and `render` only warns.
std::string with_claim(const std::string& claim) {
  std::string text = scene("3");
  text.insert(text.rfind('}'), R"(, "claims": [)" + claim + "]");
  return text;
}

TEST_F(Check, ClaimsThatHoldPass) {
  dir.write("fig.json", with_claim(R"({"says": "P6 has no pop", "measure": "pop", "is": false})"));
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ok    fig.json (1 claims hold)"), std::string::npos) << r.out;
}

TEST_F(Check, AClaimThatFailsIsAMismatchNamingIt) {
  dir.write("fig.json", with_claim(R"({"says": "the frames never turn", "measure": "turn-step", "below": 0.01})"));
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("FAIL  fig.json"), std::string::npos) << r.err;
  EXPECT_TRUE(std::regex_search(
      r.err,
      std::regex(
          R"(/claims/0: claim failed: "the frames never turn": turn-step of the scene \(P6[^)]*\) = [0-9.]+, not below 0\.01)")))
      << r.err;
  EXPECT_EQ(r.err.find("golden/fig/"), std::string::npos) << r.err;  // the goldens match

  const RunResult render = run({"render", "fig.json", "-o", "out"});
  EXPECT_EQ(render.exit_code, 0) << render.err;
  EXPECT_NE(render.err.find("pita: warning: fig.json: /claims/0: the claim \"the frames never turn\" does not hold"),
            std::string::npos)
      << render.err;
  EXPECT_TRUE(fs::exists(dir.path() / "out/fig.svg"));
}

TEST_F(Check, AClaimThePanelCannotMeasureIsBadInput) {
  dir.write("fig.json", with_claim(R"({"says": "x", "measure": "gain:D.q", "below": 1})"));
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("fig.json: /claims/0/measure: the scene (P6) has no \"gain:D.q\": no keyframe has that "
                       "parameter"),
            std::string::npos)
      << r.err;
}

// The paper figures' claims fail when the figure stops showing them: a
// method swapped (Fig. 20's P4 for P3) or a tweak removed (Fig. 19's B.q
// moved back), as a reviewer would try.
TEST_F(Check, PaperClaimsFailWhenTheFigureChanges) {
  const fs::path scenes = fs::path(PITA_SOURCE_DIR) / "scenes";
  std::string fig20 = read_file(scenes / "fig20-overreaction.json");
  const std::size_t p4 = fig20.find(R"("method": "P4")");
  ASSERT_NE(p4, std::string::npos);
  fig20.replace(p4, 14, R"("method": "P3")");
  dir.write("fig20-overreaction.json", fig20);
  std::string fig19 = read_file(scenes / "fig19-overreaction-p1.json");
  const std::size_t moved = fig19.find("2.85");
  ASSERT_NE(moved, std::string::npos);
  fig19.replace(moved, 4, "3.15");
  dir.write("fig19-overreaction-p1.json", fig19);
  const std::string golden = (fs::path(PITA_SOURCE_DIR) / "golden").string();
  const RunResult r = run({"check", "fig20-overreaction.json", "fig19-overreaction-p1.json", "--golden", golden});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("/claims/1: claim failed: \"P4 overreacts to B.q more than twice as much as P3\""),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("/claims/0: claim failed: \"moving B's tip left by 0.3 turns the short frame D(1/4) around"),
            std::string::npos)
      << r.err;
}

// The same for claims of the measures that compare with another method, a
// guess or a layer: Fig. 15's P8 swapped for P7, Fig. B.30's A.w moved back
// below pi (P10 no longer pops), Fig. 18's moved B.p put elsewhere.
TEST_F(Check, PaperClaimsOfComparisonsFailWhenTheFigureChanges) {
  const fs::path scenes = fs::path(PITA_SOURCE_DIR) / "scenes";
  const auto mutated = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string text = read_file(scenes / name);
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << name;
    text.replace(at, from.size(), to);
    dir.write(name, text);
  };
  mutated("fig15-velocities-p7-p8.json", R"("method": "P8")", R"("method": "P7")");
  mutated("appB-fig30-p3-p10.json", R"("w": 3.19)", R"("w": 3.09)");
  mutated("fig18-editing.json", "2.3920813529600684", "2.2");
  const std::string golden = (fs::path(PITA_SOURCE_DIR) / "golden").string();
  const RunResult r =
      run({"check", "fig15-velocities-p7-p8.json", "appB-fig30-p3-p10.json", "fig18-editing.json", "--golden", golden});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  for (const char* failed : {"/claims/0: claim failed: \"for P8 the shapes formed by D(t) and its two accelerations",
                             "/claims/1: claim failed: \"right, A.w = 3.19 past pi: P10 pops",
                             "/claims/2: claim failed: \"after the four moves d = 0.0304"}) {
    EXPECT_NE(r.err.find(failed), std::string::npos) << failed << "\n" << r.err;
  }
}

// More of them, each a scene's panel given a neighbouring method (as a
// reviewer would swap P6 for P8): Fig. 22's knot-ratio-0.7 P6 panel, Fig.
// C.31's translated P5 panel, Fig. 4's WAM path, Fig. 28's P5 with B = M(A, C).
TEST_F(Check, PaperClaimsFailWhenAPanelsMethodChanges) {
  const fs::path scenes = fs::path(PITA_SOURCE_DIR) / "scenes";
  struct Swap {
    std::string scene;
    std::size_t panel;
    std::string field, value, failed;
  };
  const Swap swaps[] = {
      {"fig22-knot-recoil", 1, "method", "P8", "/claims/3: claim failed: \"P6 is knot-controlled (Sec. 4.8)"},
      {"appC-fig31-homogeneous-origin", 1, "method", "He-G",
       "/claims/0: claim failed: \"P5, keyframes translated by (6, 0): d < 1e-12"},
      {"fig04-mean-variants", 0, "path_mean", "geometric",
       "/claims/0: claim failed: \"the path mean changes the motion"},
      {"fig28-prediction", 13, "method", "P4", "/claims/13: claim failed: \"P5's d = 0.11"},
  };
  std::vector<std::string> args{"check"};
  for (const Swap& swap : swaps) {
    nlohmann::json scene = nlohmann::json::parse(read_file(scenes / (swap.scene + ".json")));
    nlohmann::json& panel = scene.at("panels").at(swap.panel);
    (swap.field == "method" ? panel["method"] : panel["options"][swap.field]) = swap.value;
    dir.write(swap.scene + ".json", scene.dump(1));
    args.push_back(swap.scene + ".json");
  }
  args.insert(args.end(), {"--golden", (fs::path(PITA_SOURCE_DIR) / "golden").string()});
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  for (const Swap& swap : swaps) EXPECT_NE(r.err.find(swap.failed), std::string::npos) << swap.scene << "\n" << r.err;
}

// A finding of the lint that the scene does not accept fails `check` like a
// claim (exit 1, the goldens matching); accepted with a reason, it passes.
TEST_F(Check, ALintFindingFailsUnlessTheSceneAcceptsIt) {
  std::string text = scene("3");
  text.insert(text.rfind(']'), R"(, {"type": "label", "text": "over the frames", "at": [2.6, 1.5], "size": 16})");
  dir.write("fig.json", text);
  ASSERT_EQ(run({"update-goldens", "fig.json"}).exit_code, 0);
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("lint: /layers/4: text-over-data: the label \"over the frames\" lies over the data of"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("golden/fig/"), std::string::npos) << r.err;  // the goldens match
  text.insert(text.rfind('}'), R"(, "lint": {"allow": [{"check": "text-over-data", "pointer": "/layers/4",
      "reason": "the label names what it lies on"}]})");
  dir.write("fig.json", text);
  const RunResult accepted = run({"check", "fig.json"});
  EXPECT_EQ(accepted.exit_code, 0) << accepted.err;
}

TEST_F(Check, CorruptedGoldenPngIsBadInput) {
  const fs::path png = dir.path() / "golden/fig/fig.png";
  const std::string bytes = read_file(png);
  dir.write("golden/fig/fig.png", bytes.substr(0, bytes.size() / 3));
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("golden/fig/fig.png: the expected PNG cannot be decoded"), std::string::npos) << r.err;
}

// Golden files as hostile input (tests/data/bad-goldens/README.md): each case
// replaces one golden of a fresh set; `check` must refuse it with exit 2,
// naming the golden file and what is wrong, and never crash.
TEST_F(Check, HostileGoldensAreBadInputNamingTheFile) {
  const fs::path cases = fs::path(PITA_SOURCE_DIR) / "tests/data/bad-goldens";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(cases)) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".expect") continue;
    const std::string name = entry.path().stem().string();
    std::string replaced;
    for (const char* kind : {".data.json", ".png", ".svg"}) {
      if (fs::exists(cases / (name + kind))) replaced = std::string("fig") + kind;
    }
    SCOPED_TRACE(file);
    ASSERT_FALSE(replaced.empty()) << "no golden file for " << file;
    std::string expect = read_file(entry.path());
    ASSERT_EQ(expect.rfind("error: ", 0), 0u) << expect;
    expect = expect.substr(7, expect.find('\n') - 7);
    const fs::path target = dir.path() / "golden/fig" / replaced;
    const std::string original = read_file(target);
    fs::copy_file(cases / (name + fs::path(replaced).string().substr(3)), target, fs::copy_options::overwrite_existing);
    const RunResult r = run({"check", "fig.json"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("golden/fig/" + replaced), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    dir.write("golden/fig/" + replaced, original);
    ++count;
  }
  EXPECT_GE(count, 20);
}

// Issue 37: a golden that is a link (to a secret outside the tree), a FIFO
// or a device is refused with its path (exit 2): never read into the report,
// never waited on, never written through by update-goldens.
TEST_F(Check, GoldensThatAreLinksFifosOrDevicesAreRefused) {
  dir.write("secret.txt", "TOKEN=hunter2");
  const fs::path svg = dir.path() / "golden/fig/fig.svg";
  struct Case {
    std::string what;
    std::function<void()> make;
  };
  const std::vector<Case> cases = {
      {"symbolic link", [&] { fs::create_symlink(dir.path() / "secret.txt", svg); }},
      {"symbolic link", [&] { fs::create_symlink("/dev/stdin", svg); }},
      {"FIFO", [&] { ASSERT_EQ(::mkfifo(svg.c_str(), 0600), 0); }},
      {"symbolic link to a device", [&] { fs::create_symlink("/dev/zero", svg); }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    fs::remove(svg);
    c.make();
    for (const std::string command : {"check", "update-goldens"}) {
      const RunResult r =
          command == "check" ? run({"check", "fig.json", "--report", "rep"}) : run({"update-goldens", "fig.json"});
      EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
      EXPECT_NE(r.err.find("golden/fig/fig.svg"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("a golden must be a plain file"), std::string::npos) << r.err;
    }
    EXPECT_EQ(read_file(dir.path() / "secret.txt"), "TOKEN=hunter2");
    if (fs::exists(dir.path() / "rep")) {
      for (const auto& entry : fs::recursive_directory_iterator(dir.path() / "rep")) {
        EXPECT_EQ(read_file(entry.path()).find("hunter2"), std::string::npos) << entry.path();
      }
    }
  }
}

// A golden folder golden/<name> that is a link out of --golden is neither
// read nor written through.
TEST_F(Check, ALinkedGoldenFolderIsRefused) {
  fs::create_directories(dir.path() / "elsewhere");
  fs::rename(dir.path() / "golden/fig", dir.path() / "elsewhere/fig");
  fs::create_directory_symlink(dir.path() / "elsewhere/fig", dir.path() / "golden/fig");
  const std::string before = read_file(dir.path() / "elsewhere/fig/fig.svg");
  dir.write("fig.json", scene("3.5"));
  for (const std::string command : {"check", "update-goldens"}) {
    const RunResult r = run({command, "fig.json"});
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("golden/fig: it is a symbolic link"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_file(dir.path() / "elsewhere/fig/fig.svg"), before);
}

// Issue 11: 85 000 nested arrays in a golden data file crashed `check`
// (stack overflow in the JSON DOM); now refused before the DOM is built.
TEST_F(Check, DeeplyNestedGoldenDataIsRefusedNotACrash) {
  dir.write("golden/fig/fig.data.json",
            "{\"panels\": " + std::string(100'000, '[') + std::string(100'000, ']') + ", \"x\": 1}");
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("golden/fig/fig.data.json:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nest deeper than 256 levels"), std::string::npos) << r.err;
}

TEST_F(Check, BadSceneIsBadInput) {
  dir.write("fig.json", R"({"method": "P6", "keyframes": []})");
  const RunResult r = run({"check", "fig.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("fig.json: /keyframes"), std::string::npos) << r.err;
}

TEST_F(Check, UpdateGoldensSaysWhatChangedAndByHowMuch) {
  RunResult r = run({"update-goldens", "fig.json"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("golden/fig/fig.data.json: unchanged"), std::string::npos) << r.out;
  dir.write("fig.json", scene("3.2"));
  r = run({"update-goldens", "fig.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("fig.data.json: changed: [0-9]+ of [0-9]+ numbers differ"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("fig.png: changed: [0-9]+ pixels"))) << r.out;
  EXPECT_EQ(run({"check", "fig.json"}).exit_code, 0);
}

}  // namespace
}  // namespace pita::test

namespace pita::test {
namespace {

// Issue 38: scenes are checked and updated on several threads (--jobs), and
// what is printed keeps the order of the scenes given, good, failing and bad
// scenes mixed, whatever the number of jobs.
TEST_F(Check, JobsKeepTheOrderOfTheScenes) {
  std::vector<std::string> names;
  for (int i = 0; i < 8; ++i) {
    names.push_back(fmt_name(i));
    dir.write(names.back(), i == 5 ? R"({"method": "P6", "keyframes": []})" : scene("3." + std::to_string(i + 1)));
  }
  std::vector<std::string> update{"update-goldens", "-j", "1"};
  update.insert(update.end(), names.begin(), names.end());
  const RunResult serial_update = run(update);
  update[2] = "3";
  fs::remove_all(dir.path() / "golden");
  const RunResult parallel_update = run(update);
  EXPECT_EQ(parallel_update.exit_code, 2) << parallel_update.err;  // scene 5 is bad
  EXPECT_EQ(parallel_update.out, serial_update.out);
  EXPECT_EQ(parallel_update.err, serial_update.err);
  EXPECT_EQ(lines_of(parallel_update.out).size(), 7u * 3u);  // three goldens of each good scene
  EXPECT_FALSE(fs::exists(dir.path() / "golden" / "s5"));

  dir.write(names[2], scene("3.35"));  // now differs from its golden
  std::vector<std::string> check{"check", "--jobs", "1"};
  check.insert(check.end(), names.begin(), names.end());
  const RunResult serial = run(check);
  check[2] = "3";
  const RunResult parallel = run(check);
  EXPECT_EQ(parallel.exit_code, 2);
  EXPECT_EQ(parallel.out, serial.out);
  EXPECT_EQ(parallel.err, serial.err);
  const std::vector<std::string> ok = lines_of(parallel.out);
  ASSERT_EQ(ok.size(), 6u) << parallel.out;
  EXPECT_EQ(ok.front(), "ok    s0.json");
  EXPECT_EQ(ok.back(), "ok    s7.json");
  EXPECT_LT(parallel.err.find("FAIL  s2.json"), parallel.err.find("s5.json: /keyframes")) << parallel.err;
}

TEST(CheckTolerances, SceneToleranceAppliesAndCommandLineOverridesIt) {
  const ScratchDir dir;
  const auto write = [&](const std::string& x) {
    dir.write("fig.json", R"({"method": "P3", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [)" +
                              x + R"(, 1.5], "m": 0.6, "w": 2.0},
      {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}],
      "golden": {"number_tolerance": 0.01, "svg_tolerance": 1000, "pixel_tolerance": 255, "max_differing": 1}})");
  };
  write("3");
  ASSERT_EQ(run_pita({"update-goldens", "fig.json"}, dir.path()).exit_code, 0);
  write("3.0001");  // moves frames by ~1e-5 of the extent: within the scene's 0.01
  EXPECT_EQ(run_pita({"check", "fig.json"}, dir.path()).exit_code, 0);
  const RunResult strict = run_pita({"check", "fig.json", "--number-tolerance", "1e-9"}, dir.path());
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_NE(strict.err.find("tolerance 1e-09"), std::string::npos) << strict.err;
}

}  // namespace
}  // namespace pita::test
