// pita eval, through the real binary (src/cli/eval.cpp): exit codes, stdout
// and stderr. Bad input exits 2 with one message naming the file, the JSON
// Pointer and the reason, and prints nothing on stdout (the bad scenes of
// tests/data/bad/: test_bad_scenes_cli.cpp; bad options: here).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "run_pita.hpp"
#include "support/matrix_functions.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;

// Fig. 1's keyframes: three arrows with even knots.
const std::string kGoodScene = R"({
  "method": "P6",
  "keyframes": [
    {"t": 0,   "p": [0, 0],   "m": 1,   "w": 0.4},
    {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
    {"t": 1,   "p": [6, 0],   "m": 1.2, "w": 3.5}
  ]
})";

class Eval : public ::testing::Test {
 protected:
  void SetUp() override { dir.write("scene.json", kGoodScene); }
  RunResult run(const std::vector<std::string>& args) const { return run_pita(args, dir.path()); }

  ScratchDir dir;
};

std::vector<double> times_of(const Json& document) {
  std::vector<double> times;
  for (const Json& frame : document.at("frames")) times.push_back(frame.at("t").get<double>());
  return times;
}

// ------------------------------------------------------------ good input

TEST_F(Eval, GoodSceneGivesJsonFramesInKeyOrder) {
  const RunResult result = run({"eval", "scene.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  const Json document = Json::parse(result.out);
  std::vector<std::string> top_keys;
  for (const auto& [key, value] : document.items()) top_keys.push_back(key);
  EXPECT_EQ(top_keys, (std::vector<std::string>{"method", "frames"}));
  EXPECT_EQ(document.at("method"), "P6");
  ASSERT_EQ(document.at("frames").size(), 9u);  // the default
  for (const Json& frame : document.at("frames")) {
    std::vector<std::string> keys;
    for (const auto& [key, value] : frame.items()) keys.push_back(key);
    EXPECT_EQ(keys, (std::vector<std::string>{"t", "p", "m", "w", "q"}));
  }
  // One frame per line.
  EXPECT_EQ(lines_of(result.out).size(), 9u + 2u);
  // The motion starts at A and ends at C.
  const Json& first = document.at("frames").front();
  EXPECT_EQ(first.at("t").get<double>(), 0.0);
  EXPECT_NEAR(first.at("m").get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(first.at("w").get<double>(), 0.4, 1e-12);
  const Json& last = document.at("frames").back();
  EXPECT_EQ(last.at("t").get<double>(), 1.0);
  EXPECT_NEAR(last.at("p")[0].get<double>(), 6.0, 1e-12);
  EXPECT_NEAR(last.at("w").get<double>(), 3.5, 1e-12);
}

TEST_F(Eval, SamplesGivesEvenlySpacedTimes) {
  const RunResult result = run({"eval", "scene.json", "--samples", "5"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(times_of(Json::parse(result.out)), (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
}

TEST_F(Eval, SceneSamplesAreTheDefault) {
  dir.write("sampled.json", kGoodScene.substr(0, kGoodScene.rfind('}')) + R"(, "samples": 3})");
  const RunResult result = run({"eval", "sampled.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(times_of(Json::parse(result.out)), (std::vector<double>{0.0, 0.5, 1.0}));
  // --samples wins over the scene's.
  const RunResult overridden = run({"eval", "sampled.json", "--samples", "2"});
  ASSERT_EQ(overridden.exit_code, 0) << overridden.err;
  EXPECT_EQ(times_of(Json::parse(overridden.out)), (std::vector<double>{0.0, 1.0}));
}

TEST_F(Eval, TimesAreEvaluatedAsGivenAndMayExtrapolate) {
  const RunResult result = run({"eval", "scene.json", "--t", "1.5,-0.5, 0.25,+2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(times_of(Json::parse(result.out)), (std::vector<double>{1.5, -0.5, 0.25, 2.0}));
  const RunResult negative_first = run({"eval", "scene.json", "--t", "-1"});
  ASSERT_EQ(negative_first.exit_code, 0) << negative_first.err;
  EXPECT_EQ(times_of(Json::parse(negative_first.out)), (std::vector<double>{-1.0}));
}

TEST_F(Eval, CsvFormat) {
  const RunResult result = run({"eval", "scene.json", "--format", "csv", "--samples", "4"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<std::string> lines = lines_of(result.out);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "t,px,py,m,w,qx,qy");
  const std::vector<std::string> starts = {"0,", "0.33333333333333331,", "0.66666666666666663,", "1,"};
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i].rfind(starts[i - 1], 0), 0u) << lines[i];
    EXPECT_EQ(std::count(lines[i].begin(), lines[i].end(), ','), 6) << lines[i];
  }
}

TEST_F(Eval, MethodOverride) {
  const RunResult result = run({"eval", "scene.json", "--method", "P8", "--samples", "3"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(Json::parse(result.out).at("method"), "P8");
  const RunResult mnemonic = run({"eval", "scene.json", "--method", "la-lp"});
  ASSERT_EQ(mnemonic.exit_code, 0) << mnemonic.err;
  EXPECT_EQ(Json::parse(mnemonic.out).at("method"), "P6");
}

TEST_F(Eval, EveryStarterSceneEvaluates) {
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    const RunResult result = run({"eval", entry.path().string()});
    EXPECT_EQ(result.exit_code, 0) << entry.path() << ": " << result.err;
    EXPECT_NO_THROW({
      const Json document = Json::parse(result.out);
      EXPECT_TRUE(document.contains("frames")) << entry.path();
    }) << entry.path();
  }
}

// A figure whose layers need no motion (sam-fig06-existence-3d) has no frames:
// an empty, well-formed result in either format, exit 0, and a note on stderr
// that says why (docs/paper-notes.md N68).
TEST_F(Eval, SceneWithoutAMotionGivesNoFramesAndSaysSo) {
  const std::string scene = (std::filesystem::path(PITA_SOURCE_DIR) / "scenes/sam-fig06-existence-3d.json").string();
  const RunResult json = run({"eval", scene});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const Json parsed = Json::parse(json.out);
  EXPECT_EQ(parsed.at("method"), "SAM");
  EXPECT_EQ(parsed.at("frames"), Json::array());
  EXPECT_EQ(json.err, "pita: " + scene + ": /poses: the scene has no poses, so no motion: no frames\n");

  const RunResult csv = run({"eval", scene, "--format", "csv"});
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  const std::vector<std::string> lines = lines_of(csv.out);
  ASSERT_EQ(lines.size(), 1u) << csv.out;
  EXPECT_NE(lines[0].find("t,"), std::string::npos) << lines[0];  // the header of 3D pose frames, no row

  const RunResult panel = run({"eval", scene, "--panel", "0"});
  EXPECT_EQ(panel.exit_code, 2);
  EXPECT_EQ(panel.out, "");
  EXPECT_EQ(panel.err, "pita: --panel: " + scene + ": /poses: the scene has no poses, so no motion to evaluate\n");
}

// ------------------------------------------------------------ bad scenes
//
// Every bad scene of tests/data/bad/ is run through `pita eval` and `pita
// render` by test_bad_scenes_cli.cpp: exit code 2, nothing on stdout, and
// "pita: FILE: POINTER: REASON" on stderr.

// ------------------------------------------------------------ bad options

TEST_F(Eval, MissingFile) {
  const RunResult result = run({"eval", "missing.json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, "pita: missing.json: cannot open the scene file (No such file or directory)\n");
}

TEST_F(Eval, UnknownMethodOptionSuggests) {
  const RunResult result = run({"eval", "scene.json", "--method", "La-LQ"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, "pita: --method: unknown method \"La-LQ\"; did you mean P6 (La-LP), P3 (Pa-LP) or LS-LP?\n");
}

TEST_F(Eval, MethodOverrideMustFitTheKeyframeCount) {
  dir.write("two.json", R"({"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "p": [1, 0], "m": 1, "w": 0}]})");
  const RunResult result = run({"eval", "two.json", "--method", "P6"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err,
            "pita: two.json: /keyframes: method P6 (La-LP) takes at least 3 keyframes (got 2); more are chained "
            "(\"chain\")\n");
}

TEST_F(Eval, MethodOverrideOnThreeKeyframesWithSmaIsASpiralChain) {
  const RunResult result = run({"eval", "scene.json", "--method", "SMA", "--format", "json"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find(R"("method": "SMA", "chain": "spiral")"), std::string::npos) << result.out;
}

TEST_F(Eval, SamplesOutOfRange) {
  for (const std::string count : {"1", "0", "-3", "1000001", "2.5", "abc", ""}) {
    const RunResult result = run({"eval", "scene.json", "--samples", count});
    EXPECT_EQ(result.exit_code, 2) << count;
    EXPECT_EQ(result.out, "") << count;
    EXPECT_EQ(result.err, "pita: --samples: must be an integer between 2 and 1000000 (got \"" + count + "\")\n");
  }
  const RunResult smallest = run({"eval", "scene.json", "--samples", "2"});
  EXPECT_EQ(smallest.exit_code, 0) << smallest.err;
}

TEST_F(Eval, SamplesAndTimesExcludeEachOther) {
  const RunResult result = run({"eval", "scene.json", "--samples", "3", "--t", "0.5"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: --samples excludes --t\n", 0), 0u) << result.err;
}

TEST_F(Eval, TimesMustBeFiniteNumbers) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1e999", "pita: --t: \"1e999\" is out of the range of a double\n"},
      {"0,-1e999", "pita: --t: \"-1e999\" is out of the range of a double\n"},
      {"nan", "pita: --t: \"nan\" is not a finite number\n"},
      {"0.5,inf", "pita: --t: \"inf\" is not a finite number\n"},
      {"0.5,abc", "pita: --t: \"abc\" is not a number\n"},
      {"0.5x", "pita: --t: \"0.5x\" is not a number\n"},
      {"0,,1",
       "pita: --t: time number 2 is empty (give comma-separated numbers, for example --t "
       "0,0.5,1.5)\n"},
  };
  for (const auto& [times, error] : cases) {
    const RunResult result = run({"eval", "scene.json", "--t", times});
    EXPECT_EQ(result.exit_code, 2) << times;
    EXPECT_EQ(result.out, "") << times;
    EXPECT_EQ(result.err, error);
  }
}

TEST_F(Eval, UnknownFormat) {
  const RunResult result = run({"eval", "scene.json", "--format", "xml"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: --format: xml not in {json,csv}\n", 0), 0u) << result.err;
}

TEST_F(Eval, MissingSceneArgument) {
  const RunResult result = run({"eval"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: SCENE is required\n", 0), 0u) << result.err;
}

// ------------------------------------------------------------ motions that do not exist

// P7 and P8 have no motion when v_A + v_C = -2 v_B (docs/paper-notes.md N13).
TEST_F(Eval, SingularConfigurationExitsTwoWithoutNumbers) {
  dir.write("singular.json", R"({"method": "P7", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 0.5, "p": [1, 0], "m": 1, "w": 3.141592653589793},
    {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})");
  for (const std::string method : {"P7", "P8"}) {
    const RunResult result = run({"eval", "singular.json", "--method", method});
    EXPECT_EQ(result.exit_code, 2) << method;
    EXPECT_EQ(result.out, "") << method;
    const std::string prefix = "pita: singular.json: /keyframes: method " + method +
                               (method == "P7" ? " (Ra-Pe)" : " (Lo-Pe)") + " has no motion through these keyframes: ";
    EXPECT_EQ(result.err.rfind(prefix, 0), 0u) << result.err;
  }
}

TEST_F(Eval, NonFiniteFrameExitsTwoAndPrintsNothing) {
  // Extrapolating this far overflows: the frame is not finite.
  const RunResult result = run({"eval", "scene.json", "--t", "0,1e300"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err.rfind("pita: scene.json: /keyframes: method P6 (La-LP) has no finite frame at t = 1e+300: ", 0),
            0u)
      << result.err;
  EXPECT_EQ(result.err.find("nan"), std::string::npos) << result.err;
}

// ------------------------------------------------------------ resources (issue 11)

// `pita eval /dev/zero` read until memory ran out ("internal error:
// std::bad_alloc", exit 3), and a FIFO blocked in open(): a scene file must
// be a regular file, refused at once otherwise, and a regular file beyond the
// size limit is refused there.
TEST_F(Eval, EndlessFileIsRefusedAtTheSizeLimit) {
  const RunResult device = run({"eval", "/dev/zero"});
  EXPECT_EQ(device.exit_code, 2) << device.err;
  EXPECT_EQ(device.out, "");
  EXPECT_EQ(device.err, "pita: /dev/zero: cannot read the scene file: it is a device, not a regular file\n");
  ASSERT_EQ(::mkfifo((dir.path() / "fifo.json").c_str(), 0600), 0);
  const RunResult fifo = run({"eval", "fifo.json"});  // no writer: open() must not wait for one
  EXPECT_EQ(fifo.exit_code, 2) << fifo.err;
  EXPECT_EQ(fifo.err, "pita: fifo.json: cannot read the scene file: it is a named pipe (FIFO), not a regular file\n");
  {
    std::ofstream big(dir.path() / "big.json");
    big << std::string(33 * 1024 * 1024, ' ');
  }
  const RunResult large = run({"eval", "big.json"});
  EXPECT_EQ(large.exit_code, 2) << large.err;
  EXPECT_EQ(large.err, "pita: big.json: the scene file is larger than the limit of 32 MiB\n");
}

TEST_F(Eval, DeepNestingIsAnErrorNotACrash) {
  dir.write("deep.json",
            "{\"keyframes\": " + std::string(100'000, '[') + std::string(100'000, ']') + ", \"method\": \"P6\"}");
  const RunResult result = run({"eval", "deep.json"});
  EXPECT_FALSE(result.signaled) << result.err;
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err.rfind("pita: deep.json:1:", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("nest deeper than 256 levels"), std::string::npos) << result.err;
}

// Issue 37: control characters of a file name or a JSON value are escaped in
// messages (an ESC could recolour or clear the terminal, a BEL ring).
TEST_F(Eval, ControlCharactersInMessagesAreEscaped) {
  const std::string name = "bad\x1b[2Jname\x07.json";
  dir.write(name, R"({"method": "P6\u001b[31m", "keyframes": []})");
  const RunResult result = run({"eval", name});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err.find('\x1b'), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find('\x07'), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("bad\\x1b[2Jname\\x07.json"), std::string::npos) << result.err;
}

// Issue 38: the frames are streamed, so a million of them need no more
// memory than a few. Before, a million frames under this address-space limit
// ran out of memory (the whole text was built first); now they are written,
// to standard output and to a file. (Out of memory naming the input is
// tested with `pita render`, tests/cli/test_render_limits.cpp.)
TEST_F(Eval, AMillionFramesStreamUnderASmallMemoryLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "ulimit -v and AddressSanitizer do not mix";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "ulimit -v and AddressSanitizer do not mix";
#endif
#endif
  const std::size_t limit = std::size_t{120} << 20;
  const RunResult to_file = run_pita(
      {"eval", "scene.json", "--samples", "1000000", "--format", "csv", "-o", "frames.csv"}, dir.path(), limit);
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
  EXPECT_EQ(to_file.out, "");
  const std::string frames = read_file(dir.path() / "frames.csv");
  ASSERT_EQ(std::count(frames.begin(), frames.end(), '\n'), 1'000'001);
  EXPECT_EQ(frames.rfind("t,px,py,m,w,qx,qy\n0,", 0), 0u) << frames.substr(0, 100);
  // The last frame is the last keyframe's arrow (interpolation at the knots).
  const RunResult last = run({"eval", "scene.json", "--t", "1", "--format", "csv"});
  const std::string last_row = lines_of(last.out).at(1) + "\n";
  EXPECT_EQ(frames.substr(frames.size() - last_row.size()), last_row);
  const RunResult to_stdout = run_pita({"eval", "scene.json", "--samples", "1000000"}, dir.path(), limit);
  ASSERT_EQ(to_stdout.exit_code, 0) << to_stdout.err;
  // the head line, the frames, the closing line
  EXPECT_EQ(std::count(to_stdout.out.begin(), to_stdout.out.end(), '\n'), 1'000'002);
}

// -o FILE holds exactly what standard output shows, across many chunks.
TEST_F(Eval, OutputFileHoldsWhatStandardOutputShows) {
  for (const std::string format : {"json", "csv"}) {
    const RunResult shown = run({"eval", "scene.json", "--samples", "4000", "--format", format});
    ASSERT_EQ(shown.exit_code, 0) << shown.err;
    ASSERT_GT(shown.out.size(), std::size_t{200'000});  // several 64 KiB chunks
    const RunResult written = run({"eval", "scene.json", "--samples", "4000", "--format", format, "-o", "f." + format});
    ASSERT_EQ(written.exit_code, 0) << written.err;
    EXPECT_EQ(written.out, "");
    EXPECT_EQ(read_file(dir.path() / ("f." + format)), shown.out) << format;
  }
  EXPECT_TRUE(hidden_in(dir.path()).empty());
}

// -o's extension chooses the format, and must be one pita eval writes.
TEST_F(Eval, OutputExtensionChoosesTheFormatOrIsRefused) {
  const RunResult csv = run({"eval", "scene.json", "--format", "csv"});
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  ASSERT_EQ(run({"eval", "scene.json", "-o", "frames.csv"}).exit_code, 0);
  EXPECT_EQ(read_file(dir.path() / "frames.csv"), csv.out);
  const RunResult figure = run({"eval", "scene.json", "-o", "frames.png"});
  EXPECT_EQ(figure.exit_code, 2);
  EXPECT_NE(figure.err.find("-o frames.png: pita eval writes frames as .csv or .json files"), std::string::npos)
      << figure.err;
  const RunResult contradiction = run({"eval", "scene.json", "--format", "csv", "-o", "frames.json"});
  EXPECT_EQ(contradiction.exit_code, 2);
  EXPECT_NE(contradiction.err.find("--format csv contradicts the extension of -o frames.json"), std::string::npos)
      << contradiction.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames.png"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames.json"));
}

// The frames never replace the scene they come from, by its name or a link.
TEST_F(Eval, TheOutputIsNeverTheScene) {
  std::filesystem::create_symlink("scene.json", dir.path() / "link.json");
  for (const char* output : {"scene.json", "./scene.json", "link.json"}) {
    const RunResult r = run({"eval", "scene.json", "-o", output});
    EXPECT_EQ(r.exit_code, 2) << output;
    EXPECT_NE(r.err.find("the output is the scene file scene.json, which it would replace"), std::string::npos)
        << r.err;
    EXPECT_EQ(read_file(dir.path() / "scene.json"), kGoodScene);
  }
}

// All or nothing: a frame that is not finite, after many chunks' worth of
// good ones, leaves standard output empty and an existing -o file as it was.
TEST_F(Eval, ALateNonFiniteFrameWritesNothing) {
  std::string times = "0";
  for (int i = 1; i < 3000; ++i) times += "," + std::to_string(i / 3000.0);
  times += ",1e300";
  const RunResult shown = run({"eval", "scene.json", "--t", times, "--format", "csv"});
  EXPECT_EQ(shown.exit_code, 2);
  EXPECT_EQ(shown.out, "");
  EXPECT_NE(shown.err.find("no finite frame at t = 1e+300"), std::string::npos) << shown.err;
  dir.write("old.csv", "the old file\n");
  const RunResult written = run({"eval", "scene.json", "--t", times, "--format", "csv", "-o", "old.csv"});
  EXPECT_EQ(written.exit_code, 2);
  EXPECT_EQ(read_file(dir.path() / "old.csv"), "the old file\n");
  EXPECT_TRUE(hidden_in(dir.path()).empty());
}

// An output that cannot be written is exit 3; a bad scene is still exit 2
// first, and a scene without a motion writes its empty result.
TEST_F(Eval, OutputFileErrors) {
  const RunResult unwritable = run({"eval", "scene.json", "-o", "no/such/folder/f.json"});
  EXPECT_EQ(unwritable.exit_code, 3);
  EXPECT_NE(unwritable.err.find("no/such/folder/f.json"), std::string::npos) << unwritable.err;
  const RunResult bad = run({"eval", "missing.json", "-o", "no/such/folder/f.json"});
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  const std::string still = (std::filesystem::path(PITA_SOURCE_DIR) / "scenes/sam-fig06-existence-3d.json").string();
  const RunResult none = run({"eval", still, "-o", "none.json"});
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(read_file(dir.path() / "none.json"), "{\"method\": \"SAM\", \"frames\": []}\n");
  const RunResult batch = run({"eval", "--batch", "-", "-o", "f.json"});
  EXPECT_EQ(batch.exit_code, 2);
  EXPECT_NE(batch.err.find("-o"), std::string::npos) << batch.err;
}

// A reader that goes away (`pita eval ... | head -c1`) killed pita with
// SIGPIPE (status 141, no message); docs/reference/exit-codes-and-limits.md promises exit 3 and a message.
TEST_F(Eval, ClosedPipeIsExitThreeWithAMessage) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const ScratchDir capture;
  const std::string err_path = (capture.path() / "stderr").string();
  const std::string scene = (dir.path() / "scene.json").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err < 0 || ::dup2(fds[1], 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    ::close(fds[0]);
    ::execl(pita_binary(), pita_binary(), "eval", scene.c_str(), "--samples", "100000", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  char first = 0;
  EXPECT_EQ(::read(fds[0], &first, 1), 1);  // head -c1
  ::close(fds[0]);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 3);
  EXPECT_EQ(read_file(err_path).rfind("pita: cannot write the frames to standard output", 0), 0u)
      << read_file(err_path);
}

// 3D pose scenes through the binary: the CSV of `pita eval` against an
// independent fractional power, Eigen's Schur-Pade pow of the 4x4 homogeneous
// matrix C B^-1 in long double: A(t) = (C B^-1)^u B on each span.
using Matrix4L = Eigen::Matrix<long double, 4, 4>;

Matrix4L homogeneous_of(const std::vector<double>& rows) {  // a b c tx d e f ty g h i tz
  Matrix4L H = Matrix4L::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) H(r, c) = rows[static_cast<std::size_t>(4 * r + c)];
  }
  return H;
}

std::string matrix_json(const std::vector<double>& rows) {
  return fmt::format("[[{}, {}, {}, {}], [{}, {}, {}, {}], [{}, {}, {}, {}]]", rows[0], rows[1], rows[2], rows[3],
                     rows[4], rows[5], rows[6], rows[7], rows[8], rows[9], rows[10], rows[11]);
}

// A polySAM scene of these poses at these knots, with `timing` when not empty.
std::string space_scene(const std::vector<std::vector<double>>& poses, const std::vector<double>& knots,
                        const std::string& timing = "") {
  std::string scene =
      R"({"dimension": 3, "method": "polySAM", )" + (timing.empty() ? "" : timing + ", ") + R"("poses": [)";
  for (std::size_t i = 0; i < poses.size(); ++i) {
    scene += fmt::format(R"({}{{"t": {}, "matrix": {}}})", i == 0 ? "" : ", ", knots[i], matrix_json(poses[i]));
  }
  return scene + "]}";
}

// Each row of the CSV against (C B^-1)^u B, u = ease of the fraction of t's
// span (the knots' spans; t before the first or after the last extrapolates
// the first or last span). Returns the number of rows.
int expect_space_rows_match(const std::string& csv, const std::vector<std::vector<double>>& poses,
                            const std::vector<double>& knots, const std::function<long double(long double)>& ease) {
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "t,a,b,c,tx,d,e,f,ty,g,h,i,tz");
  int rows = 0;
  while (std::getline(lines, line)) {
    std::vector<double> values;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) values.push_back(std::stod(field));
    EXPECT_EQ(values.size(), 13u) << line;
    if (values.size() != 13u) continue;
    const double t = values[0];
    std::size_t span = 0;
    while (span + 2 < knots.size() && t >= knots[span + 1]) ++span;
    const long double u = ease((t - knots[span]) / (knots[span + 1] - knots[span]));
    const Matrix4L B = homogeneous_of(poses[span]), C = homogeneous_of(poses[span + 1]);
    const Matrix4L expected = oracle::pow(Matrix4L(C * B.inverse()), u) * B;
    const Matrix4L got = homogeneous_of(std::vector<double>(values.begin() + 1, values.end()));
    EXPECT_LE(static_cast<double>((got - expected).norm() / expected.norm()), 1e-12) << "t = " << t;
    ++rows;
  }
  return rows;
}

TEST_F(Eval, SpacePosesMatchAnIndependentMatrixPower) {
  // A stretch by 40 beside a turn, a shear, and a screw-like pose: three poses, two spans.
  const std::vector<std::vector<double>> poses = {
      {1.0, 0.2, 0.0, 0.5, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0},
      {0.3, -2.0, 0.4, 3.0, 1.5, 0.2, -0.3, 1.0, 0.1, 0.5, 40.0, -2.0},
      {-0.6, -0.8, 0.0, 1.0, 0.8, -0.6, 0.0, 4.0, 0.0, 0.0, 2.5, 7.0},
  };
  const std::vector<double> knots = {0.0, 0.7, 2.0};
  dir.write("space.json", space_scene(poses, knots));
  const RunResult result = run({"eval", "space.json", "--format", "csv", "--t", "-0.4,0,0.13,0.5,0.7,1.1,1.9,2,2.6"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(expect_space_rows_match(result.out, poses, knots, [](long double x) { return x; }), 9);
}

TEST_F(Eval, SpacePosesEasedPerSpanMatchAnIndependentMatrixPower) {
  // "timing" in space: the cubic ease 3x^2 - 2x^3 of each span (chapter Eq. 3.20,
  // written out here), then the SAM of the span at the eased u.
  const std::vector<std::vector<double>> poses = {
      {1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0},
      {0.0, -2.0, 0.0, 3.0, 2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.5, -2.0},
      {-0.6, -0.8, 0.3, 1.0, 0.8, -0.6, 0.0, 4.0, 0.0, 0.2, 2.5, 7.0},
  };
  const std::vector<double> knots = {0.0, 0.5, 2.0};
  dir.write("eased.json", space_scene(poses, knots, R"("timing": {"ease": "cubic", "per": "span"})"));
  const RunResult result = run({"eval", "eased.json", "--format", "csv", "--t", "0,0.1,0.25,0.4,0.5,0.8,1.25,1.9,2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto cubic = [](long double x) { return 3 * x * x - 2 * x * x * x; };
  EXPECT_EQ(expect_space_rows_match(result.out, poses, knots, cubic), 9);
}

TEST_F(Eval, SpaceSceneWithoutASamExitsTwo) {
  dir.write("space.json", R"({"dimension": 3, "method": "SAM", "poses": [
    {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
    {"t": 1, "matrix": [[-1, 0, 0, 0], [0, -3, 0, 0], [0, 0, 1, 0]]}]})");
  const RunResult result = run({"eval", "space.json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_NE(result.err.find("space.json: /poses: no SAM exists between these poses"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("-3"), std::string::npos) << result.err;  // the eigenvalues are named
  // pita render refuses it with the same message, and writes nothing.
  const RunResult render = run({"render", "space.json", "-o", "out"});
  EXPECT_EQ(render.exit_code, 2);
  EXPECT_NE(render.err.find("space.json: /poses: no SAM exists between these poses"), std::string::npos) << render.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "space.svg"));
}

}  // namespace
}  // namespace pita::test
