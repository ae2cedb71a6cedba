// The one registry of methods, for both kinds of scene: the PITAs and the
// steady morph between arrows (pitas/registry.hpp builds them) and the pose
// methods of the SAM paper (pose_motion.hpp builds them). Names, mnemonics,
// case, numbers and "did you mean" are handled here and nowhere else; the CLI
// help, the schema's examples and the docs' tables are derived from (or
// tested against) every_method().
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/pitas/registry.hpp"
#include "core/pose_motion.hpp"

namespace pita {

// A method of either kind: a PITA (or the SMA) between arrows, or a pose
// method of the SAM paper. Which alternative it holds is the kind of scene the
// method interpolates; nothing else records it.
using AnyMethod = std::variant<Method, PoseMethod>;

struct MethodEntry {
  AnyMethod method;
  std::string_view id;        // "P6", "SAM"
  std::string_view mnemonic;  // "La-LP"; the id again where there is none
  std::string_view title;
  int min_count = 0;  // keyframes (arrows) or poses
  int max_count = 0;
  bool in_basket = true;  // false for Fig. 7's extra independent combinations
};

// Whether the entry is a method of kind M (Method: arrows; PoseMethod: poses).
template <class M>
bool is_method_of(const MethodEntry& entry) {
  return std::holds_alternative<M>(entry.method);
}

// Which entries a look-up considers: every one (nullptr) or those a
// predicate keeps (is_method_of<M>).
using MethodFilter = bool (*)(const MethodEntry&);

// Every method: the arrow methods in the order of all_methods(), then the
// pose methods in the order of all_pose_methods().
std::span<const MethodEntry> every_method();

// The method a name means, any case: an id ("P6", "sam"), a mnemonic
// ("la-lp"), both ("P6:La-LP") or a PITA's number ("6", "5s"); nullptr if none.
// With a filter, only the methods it keeps answer.
const MethodEntry* find_method_entry(std::string_view name, MethodFilter filter = nullptr);

// The method of kind M a name means (find_method_entry), or nullptr.
template <class M>
const M* find_method_of(std::string_view name) {
  const MethodEntry* entry = find_method_entry(name, is_method_of<M>);
  return entry == nullptr ? nullptr : std::get_if<M>(&entry->method);
}

// "P6 (La-LP)", "SMA", "SAM": a method as messages and titles name it.
std::string method_label(const MethodEntry& entry);
const MethodEntry& entry_of(Method method);
const MethodEntry& entry_of(PoseMethod method);

// The closest names to a misspelt one, best first, at most `most`, labelled
// as method_label does ("did you mean").
std::vector<std::string> suggest_methods(std::string_view name, MethodFilter filter = nullptr, std::size_t most = 3);

// "SAM, polySAM, bezier-SAM, ...": the ids of every method the filter keeps
// (every method for nullptr), in registry order (for messages).
std::string method_ids(MethodFilter filter = nullptr);

// The one wording of an unknown method:
//   unknown method "P66"; did you mean P6 (La-LP), P1 (Pa-Ca) or P2 (LS-Po)?
//   unknown method "zz"; known methods: P1, P2, ...
// With a filter, suggestions and the list are of the methods it keeps.
std::string unknown_method_reason(std::string_view name, MethodFilter filter = nullptr);

}  // namespace pita
