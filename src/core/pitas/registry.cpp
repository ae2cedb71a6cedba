#include "core/pitas/registry.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/pitas/appendix_d_variants.hpp"
#include "core/pitas/independent.hpp"
#include "core/pitas/p01_pa_ca.hpp"
#include "core/pitas/p02_ls_po.hpp"
#include "core/pitas/p03_pa_lp.hpp"
#include "core/pitas/p04_be_lp.hpp"
#include "core/pitas/p05_he_lp.hpp"
#include "core/pitas/p05s_hs_lp.hpp"
#include "core/pitas/p06_la_lp.hpp"
#include "core/pitas/p07_ra_pe.hpp"
#include "core/pitas/p08_lo_pe.hpp"
#include "core/pitas/p09_ne_lp.hpp"
#include "core/pitas/p10_pa_el.hpp"
#include "core/pitas/sma.hpp"

namespace pita {
namespace {

// winding_aware is what tests/core/test_fig10.cpp measures (W row of Fig. 10,
// plus P4 and P9, which are built from winding-aware steady morphs).
template <typename Pita>
std::unique_ptr<Motion> build(const KeyframeTriple& k, const MethodOptions&) {
  return std::make_unique<Pita>(k);
}

constexpr std::array<MethodInfo, 19> kMethods{{
    {Method::P1, "P1", "Pa-Ca", "parabolic point, Cartesian vector", 3, false, true, build<PaCa>},
    {Method::P2, "P2", "LS-Po", "log-spiral point, polar vector", 3, true, true,
     [](const KeyframeTriple& k, const MethodOptions& o) -> std::unique_ptr<Motion> {
       return std::make_unique<LsPo>(k, o.anchor);
     },
     false, kAnchorOption},
    {Method::P3, "P3", "Pa-LP", "parabolic point, log-polar vector", 3, true, true, build<PaLp>},
    {Method::P4, "P4", "Be-LP", "Bezier of steady morphs (BiSAM), log-polar vector", 3, true, true, build<BeLp>},
    {Method::P5, "P5", "He-LP", "homogeneous exponential about the centroid", 3, false, true, build<HeLp>},
    {Method::P5S, "P5S", "Hs-LP", "homogeneous exponential in the frame of M(A, C)", 3, false, true, build<HsLp>},
    {Method::P6, "P6", "La-LP", "Lagrange form with steady morphs and transports", 3, true, true, build<LaLp>},
    {Method::P7, "P7", "Ra-Pe", "radially perseverant point, perseverant vector", 3, false, true, build<RaPe>},
    {Method::P8, "P8", "Lo-Pe", "locally perseverant (PAM on similarities)", 3, false, true, build<LoPe>},
    {Method::P9, "P9", "Ne-LP", "Neville form with steady morphs", 3, true, true,
     [](const KeyframeTriple& k, const MethodOptions& o) -> std::unique_ptr<Motion> {
       return std::make_unique<NeLp>(k, o.path_mean, o.magnitude_mean);
     },
     false, kPathMeanOption | kMagnitudeMeanOption},
    {Method::P10, "P10", "Pa-EL", "parabolic point, exponential of log linear parts", 3, false, true, build<PaEl>},
    {Method::SMA, "SMA", "SMA", "steady morph between two arrows", 2, true, true, nullptr, false,
     kPathMeanOption | kMagnitudeMeanOption},
    {Method::PaPo, "Pa-Po", "Pa-Po", "parabolic point, polar vector (Fig. 7)", 3, true, false,
     [](const KeyframeTriple& k, const MethodOptions&) -> std::unique_ptr<Motion> {
       return std::make_unique<IndependentPita>(k, PointMotion::parabola, VectorMotion::polar);
     }},
    {Method::LSCa, "LS-Ca", "LS-Ca", "log-spiral point, Cartesian vector (Fig. 7)", 3, false, false,
     [](const KeyframeTriple& k, const MethodOptions&) -> std::unique_ptr<Motion> {
       return std::make_unique<IndependentPita>(k, PointMotion::log_spiral, VectorMotion::cartesian);
     }},
    {Method::LSLP, "LS-LP", "LS-LP", "log-spiral point, log-polar vector (Fig. 7)", 3, true, false,
     [](const KeyframeTriple& k, const MethodOptions&) -> std::unique_ptr<Motion> {
       return std::make_unique<IndependentPita>(k, PointMotion::log_spiral, VectorMotion::log_polar);
     }},
    {Method::HeG, "He-G", "He-G", "homogeneous exponential about the global origin (app. C)", 3, false, false,
     [](const KeyframeTriple& k, const MethodOptions&) -> std::unique_ptr<Motion> {
       return std::make_unique<HeLp>(k, HomogeneousCenter::global_origin);
     },
     true},
    {Method::LaT1, "La-T1", "La-T1", "Lagrange half T1 of PITA Eq. 34, keyframes permuted (app. D.1)", 3, true, false,
     [](const KeyframeTriple& k, const MethodOptions& o) -> std::unique_ptr<Motion> {
       return std::make_unique<AppendixDVariant>(k, AppendixDForm::lagrange_t1, o.permutation, o.symmetrize);
     },
     true, kPermutationOption | kSymmetrizeOption},
    {Method::LaT2, "La-T2", "La-T2", "Lagrange variant T2 of PITA Eq. D.1, keyframes permuted (app. D.1)", 3, true,
     false,
     [](const KeyframeTriple& k, const MethodOptions& o) -> std::unique_ptr<Motion> {
       return std::make_unique<AppendixDVariant>(k, AppendixDForm::lagrange_t2, o.permutation, o.symmetrize);
     },
     true, kPermutationOption | kSymmetrizeOption},
    {Method::NeM, "Ne-M", "Ne-M", "Neville form M of PITA Eq. D.2, keyframes permuted (app. D.2)", 3, true, false,
     [](const KeyframeTriple& k, const MethodOptions& o) -> std::unique_ptr<Motion> {
       return std::make_unique<AppendixDVariant>(k, AppendixDForm::neville, o.permutation, o.symmetrize);
     },
     true, kPermutationOption | kSymmetrizeOption},
}};

}  // namespace

std::span<const MethodInfo> all_methods() { return kMethods; }

const MethodInfo& info(Method m) {
  for (const MethodInfo& i : kMethods) {
    if (i.method == m) return i;
  }
  throw std::logic_error("unregistered method");
}

std::unique_ptr<Motion> make_pita(Method m, const KeyframeTriple& k, const MethodOptions& o) {
  const MethodInfo& about = info(m);
  if (about.make == nullptr) throw std::invalid_argument("SMA interpolates two keyframes, not three");
  return about.make(k, o);
}

std::string method_name(Method m) {
  const MethodInfo& about = info(m);
  std::string name(about.id);
  if (!about.mnemonic.empty() && about.mnemonic != about.id) name += " " + std::string(about.mnemonic);
  return name;
}

bool reads_option(Method m, MethodOption option, bool chained) {
  const MethodInfo& about = info(m);
  if ((about.options & option) != 0U) return true;
  if (option == kKnotsOption) return about.keyframe_count == 3;
  return chained && (option == kPathMeanOption || option == kMagnitudeMeanOption);
}

Chain default_chain(Method m) { return info(m).keyframe_count == 2 ? Chain::spiral : Chain::blend; }

std::unique_ptr<Motion> make_motion(Method m, std::span<const Keyframe> keyframes, const MethodOptions& options,
                                    std::optional<Chain> chain) {
  const MethodInfo& mi = info(m);
  if (static_cast<int>(keyframes.size()) < mi.keyframe_count) {
    throw std::invalid_argument(std::string(mi.id) + " takes at least " + std::to_string(mi.keyframe_count) +
                                " keyframes, got " + std::to_string(keyframes.size()));
  }
  const bool as_given = options.knots == KnotOrder::as_given;
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    const Keyframe& k = keyframes[i];
    if (!std::isfinite(k.t) || !is_finite(k.arrow) || !(k.arrow.m > 0.0)) {
      throw std::invalid_argument("keyframe " + std::to_string(i) + " must have finite values and a magnitude > 0");
    }
    if (!as_given && i > 0 && !(keyframes[i - 1].t < k.t)) {
      throw std::invalid_argument("knots must be strictly increasing (keyframe " + std::to_string(i) + ")");
    }
    for (std::size_t j = 0; as_given && j < i; ++j) {
      if (keyframes[j].t == k.t) {
        throw std::invalid_argument("knots must be distinct (keyframes " + std::to_string(j) + " and " +
                                    std::to_string(i) + ")");
      }
    }
  }
  if (as_given) {
    // The keyframes in the order given, as P(a, A, b, B, c, C, t) takes them
    // (docs/paper-notes.md N41): one window, no chain.
    if (mi.keyframe_count != 3 || keyframes.size() != 3 || chain) {
      throw std::invalid_argument(
          "knots \"as-given\" hands exactly three keyframes to a three-keyframe method, "
          "without a chain");
    }
    return make_pita(m, KeyframeTriple{keyframes[0], keyframes[1], keyframes[2]}, options);
  }
  const WindowMotion sma = [&options](std::span<const Keyframe> pair) -> std::unique_ptr<Motion> {
    return std::make_unique<SteadyMorphMotion>(pair[0], pair[1], options.path_mean, options.magnitude_mean);
  };
  const WindowMotion window = [m, &options, &sma](std::span<const Keyframe> keys) -> std::unique_ptr<Motion> {
    if (keys.size() == 2) return sma(keys);
    return make_pita(m, KeyframeTriple{keys[0], keys[1], keys[2]}, options);
  };
  if (!chain && static_cast<int>(keyframes.size()) == mi.keyframe_count) return window(keyframes);
  return make_chain(chain.value_or(default_chain(m)), keyframes, window, mi.keyframe_count, sma, mi.winding_aware);
}

}  // namespace pita
