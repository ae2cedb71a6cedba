// Interruption through the real binary (src/io/interrupt.cpp): SIGINT,
// SIGTERM and SIGHUP remove the temporary files in flight and exit with
// 128 + signal, as a normal exit after a message; a signal ignored at start
// stays ignored; a closed stdout pipe is a write error, not a death by SIGPIPE.
//
// To catch pita with its temporaries written but not renamed, however fast the
// write, an LD_PRELOAD shim (preload/rename_hook.cpp) holds it at its first
// rename; a second test kills a real render at increasing delays.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kInterruptScene = R"({"method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}]})";

template <class Condition>
bool wait_for(Condition condition, std::chrono::milliseconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(2ms);
  }
  return true;
}

// Whether `pid` has a handler for `sig` (the SigCgt mask of /proc/PID/status),
// or has ended already (a zombie: nothing left to wait for).
bool catches_or_ended(pid_t pid, int sig) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("State:", 0) == 0 && line.find('Z') != std::string::npos) return true;
    if (line.rfind("SigCgt:", 0) != 0) continue;
    const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
    return (mask >> (sig - 1)) & 1u;
  }
  return false;
}

bool ends_with_svg_end(const std::string& text) {
  const std::size_t end = text.rfind("</svg>");
  return end != std::string::npos && text.find_first_not_of("\n", end + 6) == std::string::npos;
}

class Interrupt : public ::testing::TestWithParam<int> {};

// Held at the commit step with the temporaries of all three formats written:
// the signal removes every one of them, and the old files stay untouched.
TEST_P(Interrupt, RemovesEveryTemporaryInFlightAndExits128PlusSignal) {
  const int sig = GetParam();
  const ScratchDir dir;
  dir.write("x.json", kInterruptScene);
  fs::create_directories(dir.path() / "out");
  dir.write("out/x.png", "older");
  const fs::path marker = dir.path() / "renaming";
  Started started = start_pita({"render", "x.json", "-o", "out", "--format", "svg,png,pdf"}, dir.path(),
                               with_rename_hook({"PITA_TEST_PAUSE_BEFORE_RENAME=" + marker.string()}));
  ASSERT_TRUE(wait_for([&] { return fs::exists(marker); }, 60s)) << "pita never reached its first rename";

  // The scenario: a temporary per format, each written whole.
  const std::vector<std::string> temporaries = hidden_in(dir.path() / "out");
  ASSERT_EQ(temporaries.size(), 3u);
  for (const std::string& name : temporaries) {
    const fs::path temporary = dir.path() / "out" / name;
    EXPECT_GT(fs::file_size(temporary), 1000u) << temporary;
    if (temporary.filename().string().rfind(".x.svg.", 0) == 0) {
      EXPECT_TRUE(ends_with_svg_end(read_file(temporary))) << temporary;
    }
  }

  ASSERT_EQ(::kill(started.pid, sig), 0);
  int status = 0;
  const RunResult r = finish_pita(started, &status);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
  const std::string name = sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "SIGHUP";
  EXPECT_EQ(r.err, "pita: interrupted (" + name + "); removed unfinished outputs\n");
  EXPECT_TRUE(hidden_in(dir.path() / "out").empty());
  EXPECT_FALSE(fs::exists(dir.path() / "out/x.svg"));
  EXPECT_EQ(read_file(dir.path() / "out/x.png"), "older");
}

INSTANTIATE_TEST_SUITE_P(
    Signals, Interrupt, ::testing::Values(SIGINT, SIGTERM, SIGHUP), [](const ::testing::TestParamInfo<int>& signal) {
      return std::string(signal.param == SIGINT ? "SIGINT" : signal.param == SIGTERM ? "SIGTERM" : "SIGHUP");
    });

// Interrupted at the second scene: the first one's files, renamed into place
// before the signal, stay whole and are listed on stdout; the second one's
// temporaries are removed.
TEST(InterruptLater, ScenesWrittenBeforeTheSignalStay) {
  const ScratchDir dir;
  dir.write("a.json", kInterruptScene);
  dir.write("x.json", kInterruptScene);
  const fs::path marker = dir.path() / "renaming";
  Started started =
      start_pita({"render", "a.json", "x.json", "-o", "out", "--format", "svg,png"}, dir.path(),
                 with_rename_hook({"PITA_TEST_PAUSE_BEFORE_RENAME=" + marker.string(), "PITA_TEST_PAUSE_AT=x.svg"}));
  ASSERT_TRUE(wait_for([&] { return fs::exists(marker); }, 60s)) << "pita never reached the rename onto x.svg";
  EXPECT_EQ(hidden_in(dir.path() / "out").size(), 2u);
  ASSERT_EQ(::kill(started.pid, SIGINT), 0);
  int status = 0;
  const RunResult r = finish_pita(started, &status);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  EXPECT_EQ(r.out, "wrote out/a.svg\nwrote out/a.png\n");
  EXPECT_TRUE(ends_with_svg_end(read_file(dir.path() / "out/a.svg")));
  EXPECT_TRUE(hidden_in(dir.path() / "out").empty());
  EXPECT_FALSE(fs::exists(dir.path() / "out/x.svg"));
  EXPECT_FALSE(fs::exists(dir.path() / "out/x.png"));
}

// A signal ignored when pita starts (nohup ignores SIGHUP) stays ignored: the
// hangup does not end the run; SIGTERM still cleans up.
TEST(InterruptIgnored, AnIgnoredSignalStaysIgnored) {
  const ScratchDir dir;
  dir.write("x.json", kInterruptScene);
  const fs::path marker = dir.path() / "renaming";
  Started started = start_pita({"render", "x.json", "-o", "out"}, dir.path(),
                               with_rename_hook({"PITA_TEST_PAUSE_BEFORE_RENAME=" + marker.string()}), {SIGHUP});
  ASSERT_TRUE(wait_for([&] { return fs::exists(marker); }, 60s)) << "pita never reached its first rename";
  ASSERT_EQ(::kill(started.pid, SIGHUP), 0);
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(hidden_in(dir.path() / "out").size(), 1u);  // still there: still running
  EXPECT_EQ(::waitpid(started.pid, nullptr, WNOHANG), 0);
  ASSERT_EQ(::kill(started.pid, SIGTERM), 0);
  int status = 0;
  const RunResult r = finish_pita(started, &status);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << r.err;
  EXPECT_TRUE(hidden_in(dir.path() / "out").empty());
}

// A real render, no shim: a figure large enough to take a while (about half a
// second of drawing, an 8 MB SVG), killed with SIGTERM once its handler is
// installed, after 0, 25, 50, 100, ... ms until a run ends by itself.
// Whenever the signal lands, pita exits normally with 143 (or 0 when it had
// finished), leaves no temporary, and any file present is whole.
TEST(InterruptTiming, ARenderKilledAtAnyMomentLeavesWholeFilesOnly) {
  const ScratchDir dir;
  std::ostringstream scene;
  scene << R"({"method": "P6", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}], "layers": [)";
  for (int i = 0; i < 4; ++i) scene << (i ? ", " : "") << R"({"type": "pattern", "samples": 10000})";
  scene << "]}";
  dir.write("big.json", scene.str());
  int interrupted = 0;
  bool finished = false;
  for (int delay_ms = 0; !finished && delay_ms <= 120000; delay_ms = delay_ms ? 2 * delay_ms : 25) {
    fs::remove_all(dir.path() / "out");
    Started started = start_pita({"render", "big.json", "-o", "out", "--format", "svg,pdf"}, dir.path());
    const bool ready = wait_for([&] { return catches_or_ended(started.pid, SIGTERM); }, 10s);
    if (!ready) ::kill(started.pid, SIGKILL);
    int status = 0;
    if (ready) {
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
      ::kill(started.pid, SIGTERM);
    }
    const RunResult r = finish_pita(started, &status);
    ASSERT_TRUE(ready) << "pita never installed its SIGTERM handler";
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << " after " << delay_ms << " ms";
    const int code = WEXITSTATUS(status);
    ASSERT_TRUE(code == 0 || code == 128 + SIGTERM) << code << ": " << r.err;
    finished = code == 0;
    if (!finished) ++interrupted;
    EXPECT_TRUE(hidden_in(dir.path() / "out").empty()) << delay_ms << " ms";
    if (fs::exists(dir.path() / "out/big.svg")) {
      EXPECT_TRUE(ends_with_svg_end(read_file(dir.path() / "out/big.svg"))) << delay_ms << " ms";
    }
    if (fs::exists(dir.path() / "out/big.pdf")) {
      const std::string pdf = read_file(dir.path() / "out/big.pdf");
      EXPECT_NE(pdf.find("%%EOF", pdf.size() > 16 ? pdf.size() - 16 : 0), std::string::npos) << delay_ms << " ms";
    }
  }
  EXPECT_TRUE(finished);
  EXPECT_GT(interrupted, 0) << "no run was interrupted: the figure renders too fast to test this";
}

// With SIGPIPE ignored, a closed stdout pipe is EPIPE, reported with exit 3,
// instead of a silent death by SIGPIPE (status 141).
TEST(ClosedPipe, IsAWriteErrorNotSigpipe) {
  const ScratchDir dir;
  dir.write("x.json", kInterruptScene);
  const std::string command = "cd '" + dir.path().string() + "' && ( '" + pita_binary() +
                              "' eval x.json --samples 200000 2>err; echo $? >status ) | head -c1 >/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(read_file(dir.path() / "status"), "3\n") << read_file(dir.path() / "err");
  EXPECT_FALSE(read_file(dir.path() / "err").empty());  // the reason, from eval
}

}  // namespace
}  // namespace pita::test
