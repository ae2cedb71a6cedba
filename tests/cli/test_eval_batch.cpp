// pita eval --batch, through the real binary (src/cli/eval_batch.cpp): each
// answer is what a separate `pita eval` prints, byte for byte; bad requests
// (tests/data/bad-batch/) are answered and the batch goes on; the limits.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const fs::path kBadBatch = fs::path(PITA_SOURCE_DIR) / "tests/data/bad-batch";

struct Answer {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// The answers of a batch's standard output, one per line.
std::vector<Answer> answers_of(const std::string& out) {
  std::vector<Answer> answers;
  for (const std::string& line : lines_of(out)) {
    const Json answer = Json::parse(line);
    EXPECT_EQ(answer.size(), 3u) << line;
    answers.push_back(
        {answer.at("exit").get<int>(), answer.at("stdout").get<std::string>(), answer.at("stderr").get<std::string>()});
  }
  return answers;
}

std::string request_line(const std::vector<std::string>& arguments) { return Json(arguments).dump() + "\n"; }

class EvalBatch : public ::testing::Test {
 protected:
  void SetUp() override { dir.write("scene.json", kFigureOneScene); }
  RunResult run(const std::vector<std::string>& args) const { return run_pita(args, dir.path()); }

  ScratchDir dir;
};

// Every scene of scenes/, in JSON or CSV, with --samples, --t, --method and
// --panel, and requests that fail: each answer is the exit code, stdout and
// stderr of the same arguments given to their own process.
TEST_F(EvalBatch, EachAnswerIsWhatItsOwnProcessPrints) {
  std::vector<std::vector<std::string>> requests;
  int k = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    std::vector<std::string> request{entry.path().string()};
    if (k % 3 == 1) request.insert(request.end(), {"--format", "csv", "--samples", "4"});
    if (k % 3 == 2) request.push_back("--t=-0.25,0.5,1.75");
    requests.push_back(request);
    ++k;
  }
  ASSERT_GE(requests.size(), 50u);
  const std::string fig13 = (fs::path(PITA_SOURCE_DIR) / "scenes/fig13-knot-ratio.json").string();
  requests.push_back({fig13, "--panel", "7", "--samples", "3"});
  requests.push_back({fig13, "--panel", "99"});
  requests.push_back({"scene.json", "--method", "P8", "--t", "0,0.5"});
  requests.push_back({"scene.json", "--method", "SAM"});
  requests.push_back({"absent.json"});
  requests.push_back({"scene.json", "--samples", "1"});
  requests.push_back({"scene.json", "--frobnicate"});

  std::string batch;
  for (const auto& request : requests) batch += request_line(request);
  dir.write("batch.jsonl", batch);
  const RunResult result = run({"eval", "--batch", "batch.jsonl"});
  EXPECT_EQ(result.exit_code, 2) << "the worst request's code";
  EXPECT_EQ(result.err, "");
  const std::vector<Answer> answers = answers_of(result.out);
  ASSERT_EQ(answers.size(), requests.size());
  int failed = 0;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    std::vector<std::string> args{"eval"};
    args.insert(args.end(), requests[i].begin(), requests[i].end());
    const RunResult alone = run(args);
    EXPECT_EQ(answers[i].exit_code, alone.exit_code) << requests[i][0];
    EXPECT_EQ(answers[i].out, alone.out) << requests[i][0];
    EXPECT_EQ(answers[i].err, alone.err) << requests[i][0];
    failed += alone.exit_code != 0;
  }
  EXPECT_EQ(failed, 5) << "the last five requests are refused, the others answered";
}

// Each bad line of tests/data/bad-batch/requests.jsonl is answered with exit
// 2, nothing on stdout and the message its line of requests.expect names;
// the good request after them is still answered.
TEST_F(EvalBatch, BadRequestsAreAnsweredAndTheBatchGoesOn) {
  const std::vector<std::string> expected = lines_of(read_file(kBadBatch / "requests.expect"));
  const std::string bad = read_file(kBadBatch / "requests.jsonl");
  ASSERT_EQ(lines_of(bad).size(), expected.size());
  dir.write("batch.jsonl", bad + request_line({"scene.json", "--t=0.5"}));
  const RunResult result = run({"eval", "--batch", "batch.jsonl"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "");
  const std::vector<Answer> answers = answers_of(result.out);
  ASSERT_EQ(answers.size(), expected.size() + 1);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(answers[i].exit_code, 2) << "line " << i + 1;
    EXPECT_EQ(answers[i].out, "") << "line " << i + 1;
    EXPECT_EQ(answers[i].err.rfind("pita: ", 0), 0u) << answers[i].err;
    EXPECT_NE(answers[i].err.find(expected[i]), std::string::npos)
        << "line " << i + 1 << ": " << answers[i].err << "does not say: " << expected[i];
  }
  EXPECT_EQ(answers.back().exit_code, 0) << answers.back().err;
  EXPECT_EQ(answers.back().out, run({"eval", "scene.json", "--t=0.5"}).out);
}

TEST_F(EvalBatch, StandardInputAndAnEmptyBatch) {
  dir.write("in.jsonl", request_line({"scene.json", "--samples", "2", "--format", "csv"}) +
                            request_line({"scene.json", "--method", "P1", "--t=1"}));
  Started started = start_pita({"eval", "--batch", "-"}, dir.path(), {}, {}, 0, dir.path() / "in.jsonl");
  const RunResult result = finish_pita(started);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const std::vector<Answer> answers = answers_of(result.out);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(answers[0].out.rfind("t,px,py,m,w,qx,qy\n", 0), 0u) << answers[0].out;
  EXPECT_EQ(lines_of(answers[0].out).size(), 3u);
  EXPECT_EQ(Json::parse(answers[1].out).at("method"), "P1");

  dir.write("empty.jsonl", "");
  const RunResult empty = run({"eval", "--batch", "empty.jsonl"});
  EXPECT_EQ(empty.exit_code, 0) << empty.err;
  EXPECT_EQ(empty.out, "");
}

TEST_F(EvalBatch, UsageAndAMissingFileAreBadInput) {
  const RunResult missing = run({"eval", "--batch", "absent.jsonl"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.out, "");
  EXPECT_EQ(missing.err.rfind("pita: absent.jsonl: cannot open the batch file", 0), 0u) << missing.err;
  // A device (one endless line) or a directory is refused at once; a pipe is a batch.
  const RunResult device = run({"eval", "--batch", "/dev/zero"});
  EXPECT_EQ(device.exit_code, 2);
  EXPECT_EQ(device.err, "pita: /dev/zero: cannot read the batch file: it is a device, not a regular file\n");
  const RunResult folder = run({"eval", "--batch", "."});
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_EQ(folder.err, "pita: .: cannot read the batch file: it is a directory\n");

  dir.write("batch.jsonl", request_line({"scene.json"}));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"eval", "scene.json", "--batch", "batch.jsonl"},
        std::vector<std::string>{"eval", "--batch", "batch.jsonl", "--t", "0"},
        std::vector<std::string>{"eval", "--batch", "batch.jsonl", "--method", "P1"},
        std::vector<std::string>{"eval", "--batch", "batch.jsonl", "--format", "csv"}}) {
    const RunResult both = run(args);
    EXPECT_EQ(both.exit_code, 2) << args[1];
    EXPECT_EQ(both.out, "");
    EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
  }
}

// A request line over 32 MiB is refused without being kept, and the batch
// goes on; past 100 000 requests, each further line is refused.
TEST_F(EvalBatch, LongLinesAndTooManyRequestsAreRefused) {
  {
    std::ofstream out(dir.path() / "long.jsonl", std::ios::binary);
    out << "[\"scene.json\", \"--t=" << std::string(std::size_t{33} << 20, '0') << "\"]\n";
    out << request_line({"scene.json", "--t=1"});
  }
  const RunResult long_line = run({"eval", "--batch", "long.jsonl"});
  EXPECT_EQ(long_line.exit_code, 2);
  const std::vector<Answer> answers = answers_of(long_line.out);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(answers[0].err, "pita: long.jsonl:1: the request is longer than the limit of 32 MiB\n");
  EXPECT_EQ(answers[1].exit_code, 0) << answers[1].err;

  {
    std::ofstream out(dir.path() / "many.jsonl", std::ios::binary);
    for (int i = 0; i < 100'000; ++i) out << "0\n";  // each a bad request, answered quickly
    out << request_line({"scene.json"});
  }
  const RunResult many = run({"eval", "--batch", "many.jsonl"});
  EXPECT_EQ(many.exit_code, 2);
  const std::vector<std::string> lines = lines_of(many.out);
  ASSERT_EQ(lines.size(), 100'001u);
  EXPECT_EQ(Json::parse(lines.back()).at("stderr"),
            "pita: many.jsonl:100001: a batch holds at most 100000 requests: split it\n");
}

}  // namespace
}  // namespace pita::test
