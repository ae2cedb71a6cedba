#include "core/methods.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace pita {

namespace {

std::vector<MethodEntry> build_registry() {
  std::vector<MethodEntry> entries;
  for (const MethodInfo& about : all_methods()) {
    MethodEntry entry;
    entry.kind = MotionKind::arrows;
    entry.id = about.id;
    entry.mnemonic = about.mnemonic;
    entry.title = about.title;
    entry.min_count = entry.max_count = about.keyframe_count;
    entry.method = about.method;
    entry.in_basket = about.in_basket;
    entries.push_back(entry);
  }
  for (const PoseMethodInfo& about : all_pose_methods()) {
    MethodEntry entry;
    entry.kind = MotionKind::poses;
    entry.id = about.id;
    entry.mnemonic = about.id;
    entry.title = about.title;
    entry.min_count = about.min_poses;
    entry.max_count = about.max_poses;
    entry.pose_method = about.method;
    entries.push_back(entry);
  }
  return entries;
}

const std::vector<MethodEntry>& registry() {
  static const std::vector<MethodEntry> entries = build_registry();
  return entries;
}

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& ch : r) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return r;
}

// The names a method answers to, lower case.
std::vector<std::string> names_of(const MethodEntry& m) {
  std::vector<std::string> names{lower(m.id)};
  if (m.mnemonic != m.id) {
    names.push_back(lower(m.mnemonic));
    names.push_back(lower(std::string(m.id) + ":" + std::string(m.mnemonic)));
  }
  if (m.kind == MotionKind::arrows && m.id.size() > 1 && m.id[0] == 'P' &&
      std::isdigit(static_cast<unsigned char>(m.id[1]))) {
    names.push_back(lower(m.id.substr(1)));  // "6", "5s"
  }
  return names;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

bool of_kind(const MethodEntry& entry, std::optional<MotionKind> kind) {
  return !kind || entry.kind == *kind;
}

}  // namespace

std::span<const MethodEntry> every_method() { return registry(); }

const MethodEntry* find_method_entry(std::string_view name, std::optional<MotionKind> kind) {
  const std::string key = lower(name);
  for (const MethodEntry& entry : registry()) {
    if (!of_kind(entry, kind)) continue;
    for (const std::string& n : names_of(entry)) {
      if (n == key) return &entry;
    }
  }
  return nullptr;
}

std::string method_label(const MethodEntry& entry) {
  if (entry.mnemonic.empty() || entry.mnemonic == entry.id) return std::string(entry.id);
  return std::string(entry.id) + " (" + std::string(entry.mnemonic) + ")";
}

const MethodEntry& entry_of(Method method) {
  for (const MethodEntry& entry : registry()) {
    if (entry.kind == MotionKind::arrows && entry.method == method) return entry;
  }
  return registry().front();
}

const MethodEntry& entry_of(PoseMethod method) {
  for (const MethodEntry& entry : registry()) {
    if (entry.kind == MotionKind::poses && entry.pose_method == method) return entry;
  }
  return registry().front();
}

std::vector<std::string> suggest_methods(std::string_view name, std::optional<MotionKind> kind,
                                         std::size_t most) {
  const std::string key = lower(name);
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const MethodEntry& entry : registry()) {
    if (!of_kind(entry, kind)) continue;
    std::size_t best = std::string::npos;
    for (const std::string& n : names_of(entry)) best = std::min(best, edit_distance(key, n));
    if (best <= 2) scored.emplace_back(best, method_label(entry));
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (auto& s : scored) {
    if (out.size() == most) break;
    out.push_back(std::move(s.second));
  }
  return out;
}

std::string unknown_method_reason(std::string_view name, std::optional<MotionKind> kind) {
  std::string reason = "unknown method \"" + std::string(name) + "\"";
  const std::vector<std::string> suggestions = suggest_methods(name, kind);
  if (!suggestions.empty()) {
    reason += "; did you mean ";
    for (std::size_t i = 0; i < suggestions.size(); ++i) {
      if (i > 0) reason += i + 1 == suggestions.size() ? " or " : ", ";
      reason += suggestions[i];
    }
    return reason + "?";
  }
  const std::string known = kind ? method_ids(*kind) : method_ids(MotionKind::arrows) + ", " + method_ids(MotionKind::poses);
  return reason + "; known methods: " + known;
}

std::string method_ids(MotionKind kind) {
  std::string ids;
  for (const MethodEntry& entry : registry()) {
    if (entry.kind != kind) continue;
    if (!ids.empty()) ids += ", ";
    ids += entry.id;
  }
  return ids;
}

}  // namespace pita
