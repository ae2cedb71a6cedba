// Options of the methods that have any, and the one table of their names
// (the scene reader, `pita eval --help`, the schema test and the layer
// overlays all read it; none keeps a list of its own).
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "core/mean_kind.hpp"

namespace pita {

// Where P2's log-spiral is applied: the start point (Sec. 3.1) or the midpoint
// of the arrow (the variant drawn in Fig. 1).
enum class Anchor { start, midpoint };

// How the keyframes reach a three-keyframe method: sorted by knot (the
// default; the knots must increase), or in the order given, so that
// P(b, B, a, A, c, C, t) of order-independence (Sec. 4, PITA Eq. 42) can be
// evaluated (docs/paper-notes.md N41).
enum class KnotOrder { increasing, as_given };

// The order in which the appendix-D variants (La-T1, La-T2, Ne-M) take the
// timed keyframes: "BAC" evaluates T1(b, B, a, A, c, C, t) (appendix D.1,
// PITA Eq. D.3's notation; docs/paper-notes.md N55).
enum class Permutation { ABC, ACB, BAC, BCA, CAB, CBA };

// Per-method options. Each method reads only the fields that concern it
// (MethodInfo::options, core/pitas/registry.hpp).
struct MethodOptions {
  Anchor anchor = Anchor::start;                  // P2
  MeanKind path_mean = MeanKind::geometric;       // SMA, P9 (Sec. 2.7, Fig. D.36)
  MeanKind magnitude_mean = MeanKind::geometric;  // SMA, P9
  KnotOrder knots = KnotOrder::increasing;        // every three-keyframe method
  Permutation permutation = Permutation::ABC;     // La-T1, La-T2, Ne-M (appendix D)
  bool symmetrize = false;                        // La-T1, La-T2, Ne-M: average with the time reverse
};

// One bit per field of MethodOptions.
enum MethodOption : unsigned {
  kAnchorOption = 1U << 0U,
  kPathMeanOption = 1U << 1U,
  kMagnitudeMeanOption = 1U << 2U,
  kKnotsOption = 1U << 3U,
  kPermutationOption = 1U << 4U,
  kSymmetrizeOption = 1U << 5U,
};

struct MethodOptionKey {
  std::string_view name;  // the scene's key: "anchor", "path_mean", ...
  MethodOption option;
};

// The keys of "options", in the order messages and docs/reference/methods.md list them.
inline constexpr std::array<MethodOptionKey, 6> kMethodOptionKeys{{
    {"anchor", kAnchorOption},
    {"path_mean", kPathMeanOption},
    {"magnitude_mean", kMagnitudeMeanOption},
    {"knots", kKnotsOption},
    {"permutation", kPermutationOption},
    {"symmetrize", kSymmetrizeOption},
}};

// The keys alone (for the reader's check of unknown fields).
inline constexpr std::array<std::string_view, kMethodOptionKeys.size()> method_option_names() {
  std::array<std::string_view, kMethodOptionKeys.size()> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kMethodOptionKeys[i].name;
  return names;
}

// The values' names, each beside its enum in the same order.
inline constexpr std::array<std::string_view, 2> kAnchorNames = {"start", "midpoint"};
inline constexpr std::array<Anchor, 2> kAnchors = {Anchor::start, Anchor::midpoint};
inline constexpr std::array<std::string_view, 3> kMeanNames = {"arithmetic", "geometric", "harmonic"};
inline constexpr std::array<MeanKind, 3> kMeans = {MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic};
inline constexpr std::array<std::string_view, 2> kKnotOrderNames = {"increasing", "as-given"};
inline constexpr std::array<KnotOrder, 2> kKnotOrders = {KnotOrder::increasing, KnotOrder::as_given};
inline constexpr std::array<std::string_view, 6> kPermutationNames = {"ABC", "ACB", "BAC", "BCA", "CAB", "CBA"};
inline constexpr std::array<Permutation, 6> kPermutations = {Permutation::ABC, Permutation::ACB, Permutation::BAC,
                                                             Permutation::BCA, Permutation::CAB, Permutation::CBA};

// "BAC" for Permutation::BAC.
inline constexpr std::string_view permutation_name(Permutation p) {
  for (std::size_t i = 0; i < kPermutations.size(); ++i) {
    if (kPermutations[i] == p) return kPermutationNames[i];
  }
  return kPermutationNames[0];
}

inline constexpr std::array<std::string_view, 2> kBooleanNames = {"false", "true"};

// The name of `value` among `names` (each name beside its value, as above).
template <class E, std::size_t N>
constexpr std::string_view name_of(const std::array<std::string_view, N>& names, const std::array<E, N>& values,
                                   E value) {
  for (std::size_t i = 0; i < N; ++i) {
    if (values[i] == value) return names[i];
  }
  return {};
}

// An option's values, by name, and the one a method gets when the scene
// gives none: read from MethodOptions{} itself, so that `pita eval --help`,
// the reference and the schema (each checked against this by a test) say
// what the code does.
struct OptionChoices {
  std::span<const std::string_view> names;
  std::string_view default_name;
};

constexpr OptionChoices option_choices(MethodOption option) {
  constexpr MethodOptions defaults{};
  switch (option) {
    case kAnchorOption:
      return {kAnchorNames, name_of(kAnchorNames, kAnchors, defaults.anchor)};
    case kPathMeanOption:
      return {kMeanNames, name_of(kMeanNames, kMeans, defaults.path_mean)};
    case kMagnitudeMeanOption:
      return {kMeanNames, name_of(kMeanNames, kMeans, defaults.magnitude_mean)};
    case kKnotsOption:
      return {kKnotOrderNames, name_of(kKnotOrderNames, kKnotOrders, defaults.knots)};
    case kPermutationOption:
      return {kPermutationNames, name_of(kPermutationNames, kPermutations, defaults.permutation)};
    case kSymmetrizeOption:
      return {kBooleanNames, kBooleanNames[defaults.symmetrize ? 1 : 0]};
  }
  return {};
}

// `to` with the fields of `from` named by the bits of `given`.
inline MethodOptions with_options(MethodOptions to, const MethodOptions& from, unsigned given) {
  if ((given & kAnchorOption) != 0U) to.anchor = from.anchor;
  if ((given & kPathMeanOption) != 0U) to.path_mean = from.path_mean;
  if ((given & kMagnitudeMeanOption) != 0U) to.magnitude_mean = from.magnitude_mean;
  if ((given & kKnotsOption) != 0U) to.knots = from.knots;
  if ((given & kPermutationOption) != 0U) to.permutation = from.permutation;
  if ((given & kSymmetrizeOption) != 0U) to.symmetrize = from.symmetrize;
  return to;
}

}  // namespace pita
