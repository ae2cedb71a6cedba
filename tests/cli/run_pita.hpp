// Runs the real pita binary (PITA_BINARY) in a scratch directory and captures
// its exit code, stdout and stderr; or starts it (start_pita), to signal it
// while it runs, and waits for it (finish_pita).
#pragma once

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support/scratch_dir.hpp"

namespace pita::test {

// Fig. 1's keyframes as scene fields (method P6), and as a whole scene: the
// good scene of the CLI tests.
inline const std::string kFigureOneFields = R"("method": "P6", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4},
  {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
  {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";
inline const std::string kFigureOneScene = "{" + kFigureOneFields + "}";

// The pita under test: build/pita (PITA_BINARY), or the binary the environment
// variable PITA_TEST_BINARY names: ctest packaging.cli_installed runs these
// tests against the installed pita (tests/packaging/check_cli_installed.sh).
inline const char* pita_binary() {
  const char* chosen = std::getenv("PITA_TEST_BINARY");
  return chosen != nullptr && *chosen != '\0' ? chosen : PITA_BINARY;
}

struct RunResult {
  int exit_code = -1;     // 128 + signal number when killed by a signal
  bool signaled = false;  // killed by a signal (not an exit with a status)
  std::string out;
  std::string err;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The lines of `text`, without their '\n' (no empty last line).
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

// A pita process started by start_pita and not yet waited for.
struct Started {
  pid_t pid = -1;
  std::unique_ptr<ScratchDir> capture;  // its stdout and stderr

  Started() = default;
  Started(Started&& other) noexcept : pid(std::exchange(other.pid, -1)), capture(std::move(other.capture)) {}
  Started& operator=(Started&&) = delete;
  // A test that stops before finish_pita (a failed ASSERT) must not leave pita
  // running: a shim may hold it forever.
  ~Started() {
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
};

// Starts `pita args...` with `directory` as working directory, `environment`
// ("NAME=value") set over the test's own and `ignored_signals` ignored (as
// nohup does), with at most `address_space` bytes of virtual memory when
// given (ulimit -v), and the file `input` as standard input when given,
// without waiting for it.
inline Started start_pita(const std::vector<std::string>& args, const std::filesystem::path& directory,
                          const std::vector<std::string>& environment = {},
                          const std::vector<int>& ignored_signals = {}, std::size_t address_space = 0,
                          const std::filesystem::path& input = {}) {
  // The captured streams go to a directory of their own, so that they never
  // collide with the files of the test.
  Started started;
  started.capture = std::make_unique<ScratchDir>();
  const std::string out_path = (started.capture->path() / "stdout").string();
  const std::string err_path = (started.capture->path() / "stderr").string();
  const std::string binary = pita_binary();
  const std::string cwd = directory.string();
  const std::string in_path = input.string();

  std::vector<std::string> argv_strings;
  argv_strings.push_back(binary);
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_strings) argv.push_back(arg.data());
  argv.push_back(nullptr);
  // The test's environment, less the variables that `environment` sets anew.
  const auto name_of = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
  std::vector<std::string> env_strings;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string inherited = *entry;
    bool replaced = false;
    for (const std::string& set : environment) replaced = replaced || name_of(set) == name_of(inherited);
    if (!replaced) env_strings.push_back(inherited);
  }
  env_strings.insert(env_strings.end(), environment.begin(), environment.end());
  std::vector<char*> envp;
  for (std::string& entry : env_strings) envp.push_back(entry.data());
  envp.push_back(nullptr);

  // vfork, not fork: the child borrows this process's memory until execve
  // instead of copying its page tables. A sanitized test process maps
  // terabytes of shadow memory, and fork cost each start of pita about 40 ms
  // more there (docs/explanation/build-time.md "Build time").
  started.pid = ::vfork();
  if (started.pid < 0) throw std::runtime_error("vfork failed");
  if (started.pid == 0) {
    // Child, sharing the parent's memory: only system calls (no allocation,
    // no write to a variable) until execve or _exit.
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::chdir(cwd.c_str()) != 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) {
      ::_exit(126);
    }
    if (!in_path.empty()) {
      const int in = ::open(in_path.c_str(), O_RDONLY);
      if (in < 0 || ::dup2(in, 0) < 0) ::_exit(126);
    }
    for (const int sig : ignored_signals) ::signal(sig, SIG_IGN);
    if (address_space > 0) {
      const rlimit limit{address_space, address_space};
      if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(126);
    }
    ::execve(binary.c_str(), argv.data(), envp.data());
    ::_exit(127);
  }
  return started;
}

// Waits for a started pita. `status`, when given, receives the raw wait status
// (WIFEXITED tells an exit from a death by signal, which exit_code merges).
inline RunResult finish_pita(Started& started, int* status = nullptr) {
  int raw = 0;
  while (::waitpid(started.pid, &raw, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed");
  }
  started.pid = -1;
  if (status != nullptr) *status = raw;
  RunResult result;
  result.exit_code = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  result.signaled = WIFSIGNALED(raw);
  result.out = read_file(started.capture->path() / "stdout");
  result.err = read_file(started.capture->path() / "stderr");
  started.capture.reset();
  return result;
}

// `environment` and what start_pita needs to load the rename shim
// (tests/cli/preload/rename_hook.cpp, PITA_RENAME_HOOK): it holds pita before
// a rename, or fails one, as its variables in `environment` say.
inline std::vector<std::string> with_rename_hook(std::vector<std::string> environment) {
  environment.push_back(std::string("LD_PRELOAD=") + PITA_RENAME_HOOK);
  // A sanitizer build wants its runtime first among the libraries; the shim does not mind.
  const char* asan = std::getenv("ASAN_OPTIONS");
  const std::string options = asan != nullptr && *asan != '\0' ? std::string(asan) + ":" : "";
  environment.push_back("ASAN_OPTIONS=" + options + "verify_asan_link_order=0");
  return environment;
}

// Runs `pita args...` with `directory` as working directory, and with at
// most `address_space` bytes of virtual memory when given (ulimit -v).
inline RunResult run_pita(const std::vector<std::string>& args, const std::filesystem::path& directory,
                          std::size_t address_space = 0) {
  Started started = start_pita(args, directory, {}, {}, address_space);
  return finish_pita(started);
}

// The hidden entries of `dir` (pita's temporaries are .NAME.XXXXXX), by
// name; none when `dir` does not exist.
inline std::vector<std::string> hidden_in(const std::filesystem::path& dir) {
  std::vector<std::string> hidden;
  if (!std::filesystem::exists(dir)) return hidden;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.front() == '.') hidden.push_back(name);
  }
  return hidden;
}

}  // namespace pita::test
