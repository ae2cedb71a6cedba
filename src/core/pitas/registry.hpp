// The arrow methods: their table (ids, mnemonics, titles, keyframe counts)
// and how each is built. core/methods.hpp resolves names over it.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/chains/chain.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

enum class Method {
  P1,   // Pa-Ca
  P2,   // LS-Po
  P3,   // Pa-LP
  P4,   // Be-LP
  P5,   // He-LP, as appendix C builds it (translation-invariant only)
  P5S,  // Hs-LP, He-LP blended in the frame of M(A, C) (similarity-invariant)
  P6,   // La-LP
  P7,   // Ra-Pe
  P8,   // Lo-Pe
  P9,   // Ne-LP
  P10,  // Pa-EL
  SMA,  // steady morph between two arrows (PITA Eq. 21)
  // The independent combinations of Fig. 7 that are not in the basket.
  PaPo,  // parabolic point, polar vector
  LSCa,  // log-spiral point, Cartesian vector
  LSLP,  // log-spiral point, log-polar vector
  // The non-chosen candidates of appendices C and D (docs/paper-notes.md N55, N56).
  HeG,   // H(t) of appendix C about the global origin (Fig. C.31)
  LaT1,  // T1 of PITA Eq. 34 in a permutation of the keyframes (Fig. D.32, D.33)
  LaT2,  // T2 of PITA Eq. D.1 in a permutation of the keyframes
  NeM,   // M of PITA Eq. D.2 in a permutation of the keyframes (Fig. D.35)
};

struct MethodInfo {
  Method method;
  std::string_view id;        // "P6"
  std::string_view mnemonic;  // "La-LP"
  std::string_view title;     // "Lagrange point, log-polar vector"
  int keyframe_count;         // 3, or 2 for SMA
  bool winding_aware;         // measured, see tests/core/test_fig10.cpp
  bool in_basket = true;      // one of the paper's PITAs (P1-P10, P5S) or SMA; false for
                              // the other independent combinations of Fig. 7
  // Builds the PITA through three timed keyframes (nullptr for SMA, which
  // make_motion builds from two).
  std::unique_ptr<Motion> (*make)(const KeyframeTriple&, const MethodOptions&) = nullptr;
  // One of the appendices' non-chosen candidates (He-G, La-T1, La-T2, Ne-M):
  // not measured by pita audit unless named (default_audit_methods).
  bool appendix_variant = false;
  // The MethodOption bits the method itself reads (core/pitas/method_options.hpp);
  // every three-keyframe method also reads the knot order, and every chain
  // the means of its steady-morph windows (reads_option).
  unsigned options = 0;
};

// Whether building `m` reads option `option`: its own (MethodInfo::options),
// the knot order (three-keyframe methods), or, when `chained` (more keyframes
// than it takes, or a chain asked for), the means of the steady morphs
// (SMAs) that chains build between keyframes.
bool reads_option(Method m, MethodOption option, bool chained);

// Every method, in display order.
std::span<const MethodInfo> all_methods();
const MethodInfo& info(Method m);
// As titles, legends and messages name it: "P6 La-LP", "SMA".
std::string method_name(Method m);

// Names ("P6", "la-lp", "6", ...) are resolved by core/methods.hpp, the one
// registry of both kinds of method.

// Builds the motion through the keyframes: the method itself when there are
// as many as it takes (keyframe_count) and no chain is asked for, else the
// chain through all of them (core/chains/chain.hpp; default_chain when
// `chain` is unset). Throws std::invalid_argument when there are fewer
// keyframes than the method takes, a keyframe is not finite or has no
// magnitude, the knots are not strictly increasing, or the chain cannot be
// built; MotionDomainError when the method does not exist for some window.
std::unique_ptr<Motion> make_motion(Method m, std::span<const Keyframe> keyframes, const MethodOptions& options = {},
                                    std::optional<Chain> chain = std::nullopt);

// The chain a track of more keyframes than the method takes uses unless told:
// "spiral" for the SMA, "blend" for the three-keyframe methods.
Chain default_chain(Method m);

// The PITA through three timed keyframes with any distinct knots, unchecked
// (the order-independence property, PITA Eq. 42, swaps knots). Not for SMA.
std::unique_ptr<Motion> make_pita(Method m, const KeyframeTriple& keyframes, const MethodOptions& options = {});

}  // namespace pita
