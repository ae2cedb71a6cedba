// The appendix-D variants (src/core/pitas/appendix_d_variants.cpp): the
// identities and properties appendix D states, each checked on random
// configurations against another construction (T2 against T1, the
// symmetrized T1 against P6, Ne-M against P9) or against the time reverse of
// PITA Eq. 41 computed by relabelling the keyframes.
#include <array>
#include <numbers>
#include <string>

#include "../test_support.hpp"
#include "core/pitas/appendix_d_variants.hpp"
#include "core/steady_morph.hpp"

namespace pita::test {
namespace {

constexpr std::array<Permutation, 6> kAll = {Permutation::ABC, Permutation::ACB, Permutation::BAC,
                                             Permutation::BCA, Permutation::CAB, Permutation::CBA};

MethodOptions with(Permutation p, bool symmetrize = false) {
  MethodOptions o;
  o.permutation = p;
  o.symmetrize = symmetrize;
  return o;
}

// PITA Eq. 41's counterpart: (a, C), (a + c - b, B), (c, A), evaluated at a + c - t.
KeyframeTriple reversed(const KeyframeTriple& k) {
  return {{k.a.t, k.c.arrow}, {k.a.t + k.c.t - k.b.t, k.b.arrow}, {k.c.t, k.a.arrow}};
}

std::vector<KeyframeTriple> configurations() {
  Sampler s(1616);
  std::vector<KeyframeTriple> out;
  for (Config c : {Config::tame, Config::uneven, Config::wild}) {
    for (int i = 0; i < 20; ++i) out.push_back(s.triple(c));
  }
  return out;
}

// The largest frame distance between two motions over the sample times,
// relative to the configuration's extent.
template <class F, class G>
double worst(const KeyframeTriple& k, F&& f, G&& g) {
  double d = 0.0;
  for (double t : sample_times(k)) d = std::max(d, frame_distance(f(t), g(t)) / extent(k));
  return d;
}

// T1_XYZ = T2_YXZ: T1ABC = T2BAC, T1BCA = T2CBA, T1CAB = T2ACB, T1CBA = T2BCA,
// T1ACB = T2CAB, T1BAC = T2ABC (appendix D.1), the list as the paper prints it.
TEST(AppendixD, EachT1IsTheT2ThePaperNames) {
  const std::array<std::pair<Permutation, Permutation>, 6> pairs = {{
      {Permutation::ABC, Permutation::BAC},
      {Permutation::BCA, Permutation::CBA},
      {Permutation::CAB, Permutation::ACB},
      {Permutation::CBA, Permutation::BCA},
      {Permutation::ACB, Permutation::CAB},
      {Permutation::BAC, Permutation::ABC},
  }};
  for (const KeyframeTriple& k : configurations()) {
    for (const auto& [t1, t2] : pairs) {
      SCOPED_TRACE(std::string("T1") + std::string(permutation_name(t1)) + " = T2" + std::string(permutation_name(t2)));
      const auto one = motion(Method::LaT1, k, with(t1));
      const auto two = motion(Method::LaT2, k, with(t2));
      EXPECT_LE(worst(
                    k, [&](double t) { return one->at(t); }, [&](double t) { return two->at(t); }),
                1e-9);
      // The windings agree exactly too (winding-aware).
      EXPECT_NEAR(one->at(k.a.t + 0.3 * (k.c.t - k.a.t)).w, two->at(k.a.t + 0.3 * (k.c.t - k.a.t)).w, 1e-9);
    }
  }
}

// ... and no other pairing holds: the permutations differ.
TEST(AppendixD, ThePermutationsAreDifferentMotions) {
  Sampler s(7);
  const KeyframeTriple k = s.triple(Config::tame);
  for (Permutation p : kAll) {
    for (Permutation r : kAll) {
      if (p == r) continue;
      const auto x = motion(Method::LaT1, k, with(p));
      const auto y = motion(Method::LaT1, k, with(r));
      EXPECT_GT(worst(
                    k, [&](double t) { return x->at(t); }, [&](double t) { return y->at(t); }),
                1e-3)
          << permutation_name(p) << " vs " << permutation_name(r);
    }
  }
}

TEST(AppendixD, EveryVariantInterpolatesTheKeyframes) {
  for (const KeyframeTriple& k : configurations()) {
    for (Method m : {Method::LaT1, Method::LaT2, Method::NeM}) {
      for (Permutation p : kAll) {
        for (bool sym : {false, true}) {
          const auto x = motion(m, k, with(p, sym));
          for (const Keyframe* key : {&k.a, &k.b, &k.c}) {
            EXPECT_TRUE(arrows_near(x->at(key->t), key->arrow, 1e-9, extent(k), false))
                << name(m) << " " << permutation_name(p) << (sym ? " symmetrized" : "");
          }
        }
      }
    }
  }
}

// P6 is the average of T1ABC and T1CBA (PITA Eq. 34 and appendix D.1).
TEST(AppendixD, P6IsTheAverageOfT1AbcAndT1Cba) {
  for (const KeyframeTriple& k : configurations()) {
    const auto p6 = motion(Method::P6, k);
    const auto abc = motion(Method::LaT1, k, with(Permutation::ABC));
    const auto cba = motion(Method::LaT1, k, with(Permutation::CBA));
    const auto sym = motion(Method::LaT1, k, with(Permutation::ABC, true));
    EXPECT_LE(
        worst(
            k, [&](double t) { return p6->at(t); }, [&](double t) { return steady_average(abc->at(t), cba->at(t)); }),
        1e-9);
    EXPECT_LE(worst(
                  k, [&](double t) { return p6->at(t); }, [&](double t) { return sym->at(t); }),
              1e-9);
  }
}

// T1ABC is the time reverse of T1CBA, T1BCA of T1BAC, T1CAB of T1ACB: the
// variant on the reversed keyframes (PITA Eq. 41) at a + c - t is its partner.
TEST(AppendixD, T1PairsAreTimeReverses) {
  const std::array<std::pair<Permutation, Permutation>, 3> pairs = {{
      {Permutation::ABC, Permutation::CBA},
      {Permutation::BCA, Permutation::BAC},
      {Permutation::CAB, Permutation::ACB},
  }};
  for (const KeyframeTriple& k : configurations()) {
    const KeyframeTriple r = reversed(k);
    for (const auto& [p, partner] : pairs) {
      EXPECT_EQ(time_reverse(p), partner);
      EXPECT_EQ(time_reverse(partner), p);
      const auto x = motion(Method::LaT1, r, with(p));
      const auto y = motion(Method::LaT1, k, with(partner));
      EXPECT_LE(worst(
                    k, [&](double t) { return x->at(k.a.t + k.c.t - t); }, [&](double t) { return y->at(t); }),
                1e-9)
          << permutation_name(p);
    }
  }
}

// Fig. D.32's bottom row (scenes/appD-fig32-t1-permutations.json): C is A
// mirrored about the line x = 2.5 through B, which points straight up, knots
// even. The reversed keyframes of PITA Eq. 41 are then the mirrored ones, so each
// T1 pair is a pair of mirror images run backwards: T1_partner(t) is the
// mirror of T1_p(a + c - t), as the scene's description says.
TEST(AppendixD, T1PairsAreMirrorImagesInTheSymmetricConfiguration) {
  constexpr double pi = std::numbers::pi;
  const KeyframeTriple k{{0.0, {{0, 0}, 1.0, 0.3}}, {0.5, {{2.5, 3.0}, 0.5, pi / 2}}, {1.0, {{5, 0}, 1.0, pi - 0.3}}};
  const auto mirror = [](const Arrow& x) {  // about x = 2.5: p and the vector reflected
    return Arrow{{5.0 - x.p.real(), x.p.imag()}, x.m, pi - x.w};
  };
  const std::array<std::pair<Permutation, Permutation>, 3> pairs = {{
      {Permutation::ABC, Permutation::CBA},
      {Permutation::BCA, Permutation::BAC},
      {Permutation::CAB, Permutation::ACB},
  }};
  for (const auto& [p, partner] : pairs) {
    const auto x = motion(Method::LaT1, k, with(p));
    const auto y = motion(Method::LaT1, k, with(partner));
    EXPECT_LE(worst(
                  k, [&](double t) { return mirror(x->at(1.0 - t)); }, [&](double t) { return y->at(t); }),
              1e-12)
        << permutation_name(p);
    // Not trivially: the two differ as drawn (each is not its own mirror image).
    EXPECT_GT(worst(
                  k, [&](double t) { return x->at(t); }, [&](double t) { return y->at(t); }),
              1e-3)
        << permutation_name(p);
  }
}

// The three averages are symmetric (PITA Eq. 41), as appendix D.1 says.
TEST(AppendixD, SymmetrizedVariantsAreSymmetric) {
  for (const KeyframeTriple& k : configurations()) {
    const KeyframeTriple r = reversed(k);
    for (Method m : {Method::LaT1, Method::LaT2, Method::NeM}) {
      for (Permutation p : kAll) {
        const auto x = motion(m, r, with(p, true));
        const auto y = motion(m, k, with(p, true));
        EXPECT_LE(worst(
                      k, [&](double t) { return x->at(k.a.t + k.c.t - t); }, [&](double t) { return y->at(t); }),
                  1e-9)
            << name(m) << " " << permutation_name(p);
      }
    }
  }
}

// Appendix D.2: M_ABC = P9; M_ABC = M_CBA, M_ACB = M_BCA, M_BAC = M_CAB;
// M_ABC symmetric; M_ACB and M_BAC time reverses of each other.
TEST(AppendixD, NevillePermutationsHaveTheStatedProperties) {
  for (const KeyframeTriple& k : configurations()) {
    const KeyframeTriple r = reversed(k);
    const auto M = [&](Permutation p) { return motion(Method::NeM, k, with(p)); };
    const auto M_reversed = [&](Permutation p) { return motion(Method::NeM, r, with(p)); };
    const auto p9 = motion(Method::P9, k);
    const auto abc = M(Permutation::ABC);
    EXPECT_LE(worst(
                  k, [&](double t) { return abc->at(t); }, [&](double t) { return p9->at(t); }),
              1e-9);
    const std::array<std::pair<Permutation, Permutation>, 3> equal = {{
        {Permutation::ABC, Permutation::CBA},
        {Permutation::ACB, Permutation::BCA},
        {Permutation::BAC, Permutation::CAB},
    }};
    for (const auto& [p, q] : equal) {
      const auto x = M(p), y = M(q);
      EXPECT_LE(worst(
                    k, [&](double t) { return x->at(t); }, [&](double t) { return y->at(t); }),
                1e-9)
          << permutation_name(p) << " = " << permutation_name(q);
    }
    const auto abc_r = M_reversed(Permutation::ABC);
    EXPECT_LE(worst(
                  k, [&](double t) { return abc_r->at(k.a.t + k.c.t - t); }, [&](double t) { return abc->at(t); }),
              1e-9);
    const auto acb_r = M_reversed(Permutation::ACB);
    const auto bac = M(Permutation::BAC);
    EXPECT_LE(worst(
                  k, [&](double t) { return acb_r->at(k.a.t + k.c.t - t); }, [&](double t) { return bac->at(t); }),
              1e-9);
  }
  // ... while M_ACB itself is not symmetric (so the check above can fail).
  Sampler s(3);
  const KeyframeTriple k = s.triple(Config::tame);
  const auto acb = motion(Method::NeM, k, with(Permutation::ACB));
  const auto acb_r = motion(Method::NeM, reversed(k), with(Permutation::ACB));
  EXPECT_GT(worst(
                k, [&](double t) { return acb_r->at(k.a.t + k.c.t - t); }, [&](double t) { return acb->at(t); }),
            1e-3);
}

TEST(AppendixD, PermutationNamesRoundTrip) {
  for (Permutation p : kAll) {
    const std::array<int, 3> slots = permutation_slots(p);
    std::string text;
    for (int i : slots) text += static_cast<char>('A' + i);
    EXPECT_EQ(text, permutation_name(p));
  }
}

}  // namespace
}  // namespace pita::test
