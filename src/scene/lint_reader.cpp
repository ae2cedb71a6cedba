// "lint": the legibility lint's thresholds and the findings a scene accepts
// (scene/lint_settings.hpp; docs/reference/lint.md "Lint").
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/scene_readers.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 6> kLintFields = {"min_content_share",  "min_motion_share", "min_frame_pixels",
                                                         "min_feature_pixels", "max_hidden_share", "allow"};
constexpr std::array<std::string_view, 3> kAllowFields = {"check", "pointer", "reason"};
constexpr std::size_t kMaxAllowed = 64;
constexpr std::size_t kMaxReason = 400;

LintAllow read_allow(const JsonReader& reader, const Json& value, const std::string& pointer) {
  reader.object(value, pointer, "an accepted finding");
  reader.check_fields(value, pointer, kAllowFields);
  LintAllow allow;
  allow.at = pointer;
  const Json* check = JsonReader::member(value, "check");
  if (check == nullptr) reader.fail(pointer, "an accepted finding names its check: \"check\"");
  allow.check = reader.text(*check, pointer + "/check", 100);
  std::vector<std::string_view> names;
  for (const LintCheckInfo& info : kLintChecks) names.push_back(info.name);
  if (std::find(names.begin(), names.end(), allow.check) == names.end()) {
    reader.fail(pointer + "/check",
                fmt::format("unknown check \"{}\": the lint's checks are {}", allow.check, quoted_choices(names)));
  }
  if (const Json* at = JsonReader::member(value, "pointer")) {
    allow.pointer = reader.text(*at, pointer + "/pointer", 200);
    if (!allow.pointer.empty() && allow.pointer.front() != '/') {
      reader.fail(pointer + "/pointer",
                  fmt::format("must be a JSON Pointer such as \"/layers/2\" (got \"{}\")", allow.pointer));
    }
  }
  const Json* reason = JsonReader::member(value, "reason");
  if (reason == nullptr) reader.fail(pointer, "an accepted finding says why it is accepted: \"reason\"");
  allow.reason = reader.text(*reason, pointer + "/reason", kMaxReason);
  if (allow.reason.find_first_not_of(" \t\n") == std::string::npos) {
    reader.fail(pointer + "/reason", "the reason is empty: say why a reader of the figure can accept the finding");
  }
  return allow;
}

}  // namespace

LintSettings read_lint(const JsonReader& reader, const Json& value) {
  reader.object(value, "/lint", "\"lint\"");
  reader.check_fields(value, "/lint", kLintFields);
  LintSettings lint;
  if (const Json* x = JsonReader::member(value, "min_content_share")) {
    lint.min_content_share = reader.number(*x, "/lint/min_content_share", Interval{0.0, 1.0});
  }
  if (const Json* x = JsonReader::member(value, "min_motion_share")) {
    lint.min_motion_share = reader.number(*x, "/lint/min_motion_share", Interval{0.0, 1.0});
  }
  if (const Json* x = JsonReader::member(value, "min_frame_pixels")) {
    lint.min_frame_pixels = reader.number(*x, "/lint/min_frame_pixels", Interval{0.0, 1000.0});
  }
  if (const Json* x = JsonReader::member(value, "min_feature_pixels")) {
    lint.min_feature_pixels = reader.number(*x, "/lint/min_feature_pixels", Interval{0.0, 1000.0});
  }
  if (const Json* x = JsonReader::member(value, "max_hidden_share")) {
    lint.max_hidden_share = reader.number(*x, "/lint/max_hidden_share", Interval{0.0, 1.0});
  }
  if (const Json* allow = JsonReader::member(value, "allow")) {
    if (!allow->is_array() || allow->size() > kMaxAllowed) {
      reader.fail("/lint/allow", fmt::format("must be a list of at most {} accepted findings (got {})", kMaxAllowed,
                                             value_text(*allow)));
    }
    for (std::size_t i = 0; i < allow->size(); ++i) {
      lint.allow.push_back(read_allow(reader, (*allow)[i], element_pointer("/lint/allow", i)));
    }
  }
  return lint;
}

}  // namespace pita::scene::detail
