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
    entry.method = about.method;
    entry.id = about.id;
    entry.mnemonic = about.mnemonic;
    entry.title = about.title;
    entry.min_count = entry.max_count = about.keyframe_count;
    entry.in_basket = about.in_basket;
    entries.push_back(entry);
  }
  for (const PoseMethodInfo& about : all_pose_methods()) {
    MethodEntry entry;
    entry.method = about.method;
    entry.id = about.id;
    entry.mnemonic = about.mnemonic.empty() ? about.id : about.mnemonic;
    entry.title = about.title;
    entry.min_count = about.min_poses;
    entry.max_count = about.max_poses;
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
  // A PITA, of arrows or of poses, also answers to its number ("6", "5s").
  if (m.id.size() > 1 && m.id[0] == 'P' && std::isdigit(static_cast<unsigned char>(m.id[1]))) {
    names.push_back(lower(m.id.substr(1)));
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

bool kept(const MethodEntry& entry, MethodFilter filter) { return filter == nullptr || filter(entry); }

}  // namespace

std::span<const MethodEntry> every_method() { return registry(); }

const MethodEntry* find_method_entry(std::string_view name, MethodFilter filter) {
  const std::string key = lower(name);
  for (const MethodEntry& entry : registry()) {
    if (!kept(entry, filter)) continue;
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
    if (const Method* m = std::get_if<Method>(&entry.method); m != nullptr && *m == method) return entry;
  }
  return registry().front();
}

const MethodEntry& entry_of(PoseMethod method) {
  for (const MethodEntry& entry : registry()) {
    if (const PoseMethod* m = std::get_if<PoseMethod>(&entry.method); m != nullptr && *m == method) return entry;
  }
  return registry().front();
}

std::vector<std::string> suggest_methods(std::string_view name, MethodFilter filter, std::size_t most) {
  const std::string key = lower(name);
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const MethodEntry& entry : registry()) {
    if (!kept(entry, filter)) continue;
    std::size_t best = std::string::npos;
    for (const std::string& n : names_of(entry)) best = std::min(best, edit_distance(key, n));
    // The arrow and pose PITAs share their labels: each label once.
    const std::string label = method_label(entry);
    const bool seen = std::any_of(scored.begin(), scored.end(), [&](const auto& s) { return s.second == label; });
    if (best <= 2 && !seen) scored.emplace_back(best, label);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (auto& s : scored) {
    if (out.size() == most) break;
    out.push_back(std::move(s.second));
  }
  return out;
}

std::string unknown_method_reason(std::string_view name, MethodFilter filter) {
  std::string reason = "unknown method \"" + std::string(name) + "\"";
  const std::vector<std::string> suggestions = suggest_methods(name, filter);
  if (!suggestions.empty()) {
    reason += "; did you mean ";
    for (std::size_t i = 0; i < suggestions.size(); ++i) {
      if (i > 0) reason += i + 1 == suggestions.size() ? " or " : ", ";
      reason += suggestions[i];
    }
    return reason + "?";
  }
  return reason + "; known methods: " + method_ids(filter);
}

std::string method_ids(MethodFilter filter) {
  std::string ids;
  std::vector<std::string_view> listed;  // the arrow and pose PITAs share their ids
  for (const MethodEntry& entry : registry()) {
    if (!kept(entry, filter) || std::find(listed.begin(), listed.end(), entry.id) != listed.end()) continue;
    listed.push_back(entry.id);
    if (!ids.empty()) ids += ", ";
    ids += entry.id;
  }
  return ids;
}

}  // namespace pita
