// The defaults `pita eval --help` documents for the methods' options are the
// defaults the code uses (src/cli/eval.cpp, core/pitas/method_options.hpp):
// for every option and every method that reads it, a scene that sets the
// option to its documented default draws the same frames as one that does
// not set it, and another value draws other frames (so the check can fail).
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/pitas/method_options.hpp"
#include "core/pitas/registry.hpp"
#include "run_pita.hpp"

namespace pita::test {
namespace {

// The value the help text marks as the default of option `name`:
// `"geometric" (default)` after the name, or `(default false)`.
std::string documented_default(const std::string& help, const std::string& name) {
  const std::size_t at = help.find(name + " (");
  const std::size_t shared = help.find(name + ", ");  // "path_mean, magnitude_mean (...)"
  const std::size_t from = std::min(at, shared);
  if (from == std::string::npos) return "";
  const std::size_t mark = help.find("(default", from);
  if (mark == std::string::npos) return "";
  if (help.compare(mark, 9, "(default ") == 0) {  // "(default false)"
    return help.substr(mark + 9, help.find(')', mark) - mark - 9);
  }
  const std::size_t close = help.rfind('"', mark);
  const std::size_t open = help.rfind('"', close - 1);
  return help.substr(open + 1, close - open - 1);
}

std::string scene_json(const MethodInfo& method, const std::string& options) {
  const std::string keyframes =
      method.keyframe_count == 2
          ? R"({"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 1, "p": [6, 0], "m": 1.6, "w": 2.5})"
          : R"({"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.4, "p": [3, 1.5], "m": 0.6, "w": 2.0},
               {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5})";
  return fmt::format(R"({{"method": "{}", "keyframes": [{}]{}}})", method.id, keyframes,
                     options.empty() ? "" : ", \"options\": {" + options + "}");
}

std::string option_value(MethodOption option, std::string_view name) {
  return option == kSymmetrizeOption ? std::string(name) : fmt::format("\"{}\"", name);
}

TEST(EvalDefaults, EveryDocumentedDefaultIsTheBehaviourOfEveryMethodThatReadsIt) {
  ScratchDir dir;
  const RunResult help = run_pita({"eval", "--help"}, dir.path());
  ASSERT_EQ(help.exit_code, 0);
  // The frames printed; a value other than the default may refuse the
  // keyframes (P9's arithmetic magnitudes extrapolate below zero): "".
  const auto frames = [&](const std::string& json, bool must_succeed = true) {
    dir.write("s.json", json);
    const RunResult r = run_pita({"eval", "s.json", "--samples", "7"}, dir.path());
    if (must_succeed) {
      EXPECT_EQ(r.exit_code, 0) << json << "\n" << r.err;
    }
    return r.exit_code == 0 ? r.out : std::string();
  };
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    const std::string name(key.name);
    const OptionChoices choices = option_choices(key.option);
    const std::string documented = documented_default(help.out, name);
    ASSERT_EQ(documented, choices.default_name) << name << ": the help says \"" << documented << "\"";
    bool another_differs = false;
    int readers = 0;
    for (const MethodInfo& method : all_methods()) {
      if (!reads_option(method.method, key.option, false)) continue;
      ++readers;
      const std::string plain = frames(scene_json(method, ""));
      const std::string given =
          frames(scene_json(method, fmt::format("\"{}\": {}", name, option_value(key.option, documented))));
      EXPECT_EQ(plain, given) << method.id << " with " << name << " = " << documented;
      for (const std::string_view other : choices.names) {
        if (other == documented) continue;
        const std::string changed =
            frames(scene_json(method, fmt::format("\"{}\": {}", name, option_value(key.option, other))), false);
        another_differs = another_differs || (!changed.empty() && changed != plain);
      }
    }
    EXPECT_GT(readers, 0) << name;
    // "knots": "as-given" of increasing knots is the same motion; every other
    // option changes the frames of some method that reads it.
    if (key.option != kKnotsOption) {
      EXPECT_TRUE(another_differs) << name;
    }
  }
}

}  // namespace
}  // namespace pita::test
