// The one registry of methods, for both kinds of scene: the PITAs and the
// steady morph between arrows (pitas/registry.hpp builds them) and the pose
// methods of the SAM paper (pose_motion.hpp builds them). Names, mnemonics,
// case, numbers and "did you mean" are handled here and nowhere else; the CLI
// help, the schema's examples and the docs' tables are derived from (or
// tested against) every_method().
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/pitas/registry.hpp"
#include "core/pose_motion.hpp"

namespace pita {

enum class MotionKind { arrows, poses };

struct MethodEntry {
  MotionKind kind = MotionKind::arrows;
  std::string_view id;        // "P6", "SAM"
  std::string_view mnemonic;  // "La-LP"; the id again where there is none
  std::string_view title;
  int min_count = 0;          // keyframes (arrows) or poses
  int max_count = 0;
  Method method = Method::P6;               // when kind == arrows
  PoseMethod pose_method = PoseMethod::sam;  // when kind == poses
  bool in_basket = true;      // false for Fig. 7's extra independent combinations
};

// Every method: the arrow methods in the order of all_methods(), then the
// pose methods in the order of all_pose_methods().
std::span<const MethodEntry> every_method();

// The method a name means, any case: an id ("P6", "sam"), a mnemonic
// ("la-lp"), both ("P6:La-LP") or a PITA's number ("6", "5s"); nullptr if none.
// With `kind`, only methods of that kind answer.
const MethodEntry* find_method_entry(std::string_view name, std::optional<MotionKind> kind = std::nullopt);

// "P6 (La-LP)", "SMA", "SAM": a method as messages and titles name it.
std::string method_label(const MethodEntry& entry);
const MethodEntry& entry_of(Method method);
const MethodEntry& entry_of(PoseMethod method);

// The closest names to a misspelt one, best first, at most `most`, labelled
// as method_label does ("did you mean").
std::vector<std::string> suggest_methods(std::string_view name, std::optional<MotionKind> kind = std::nullopt,
                                         std::size_t most = 3);

// "SAM, polySAM, bezier-SAM, ...": the ids of every method of `kind`, in
// registry order (for messages).
std::string method_ids(MotionKind kind);

// The one wording of an unknown method:
//   unknown method "P66"; did you mean P6 (La-LP), P1 (Pa-Ca) or P2 (LS-Po)?
//   unknown method "zz"; known methods: P1, P2, ...
// With `kind`, suggestions and the list are of that kind.
std::string unknown_method_reason(std::string_view name, std::optional<MotionKind> kind = std::nullopt);

}  // namespace pita
