// `pita eval` on keyframe tracks (docs/reference/scene-format.md "Keyframe tracks"): random tracks of
// 4-12 keyframes pass every keyframe, are C1 at interior knots (blend,
// neville), equal the method at n = 3, continue past the ends, and sample
// [t_0, t_n]. Everything is read back from the binary's output.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_pita.hpp"

namespace pita::test {
namespace {

using Json = nlohmann::ordered_json;

struct Key {
  double t, x, y, m, w;
};

// Knot gaps over a factor e^{2 knot_spread}; windings drift by up to
// `drift` radians per keyframe.
std::vector<Key> random_track(std::mt19937_64& rng, int n, double drift, double knot_spread = 1.5) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Key> keys;
  double t = 2.0 * u(rng), w = 3.0 * u(rng);
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      t += std::exp(knot_spread * u(rng));
      w += drift * u(rng);
    }
    keys.push_back({t, 5.0 * u(rng), 5.0 * u(rng), std::exp(0.7 * u(rng)), w});
  }
  return keys;
}

std::string scene_text(const std::string& method, const std::vector<Key>& keys, const std::string& extra = "") {
  std::string text = fmt::format(R"({{"method": "{}", "keyframes": [)", method);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const Key& k = keys[i];
    text += fmt::format(R"({}{{"t": {}, "p": [{}, {}], "m": {}, "w": {}}})", i ? ", " : "", Json(k.t).dump(),
                        Json(k.x).dump(), Json(k.y).dump(), Json(k.m).dump(), Json(k.w).dump());
  }
  return text + "]" + extra + "}";
}

struct Frame {
  double t, px, py, qx, qy, m, w;
};

class EvalChains : public ::testing::Test {
 protected:
  // The frames pita prints at `times` (exits the test on failure).
  std::vector<Frame> eval(const std::string& scene, const std::vector<double>& times, Json* document = nullptr) {
    dir.write("track.json", scene);
    std::string list;
    for (const double t : times) {
      if (!list.empty()) list += ',';
      list += Json(t).dump();
    }
    const RunResult run = run_pita({"eval", "track.json", "--t", list}, dir.path());
    EXPECT_EQ(run.exit_code, 0) << run.err;
    std::vector<Frame> frames;
    if (run.exit_code != 0) return frames;
    const Json out = Json::parse(run.out);
    if (document) *document = out;
    for (const Json& f : out["frames"]) {
      frames.push_back({f["t"].get<double>(), f["p"][0].get<double>(), f["p"][1].get<double>(), f["q"][0].get<double>(),
                        f["q"][1].get<double>(), f["m"].get<double>(), f["w"].get<double>()});
    }
    return frames;
  }
  ScratchDir dir;
};

// Second-order one-sided slopes of p and q from frames at t, t +- h, t +- 2h.
double slope_jump(const Frame& m2, const Frame& m1, const Frame& c, const Frame& p1, const Frame& p2, double h,
                  double scale) {
  double jump = 0.0, speed = scale;
  const auto one = [&](double f_2, double f_1, double f0, double f1, double f2) {
    const double left = (3.0 * f0 - 4.0 * f_1 + f_2) / (2.0 * h);
    const double right = (-3.0 * f0 + 4.0 * f1 - f2) / (2.0 * h);
    jump = std::max(jump, std::abs(left - right));
    speed = std::max({speed, std::abs(left), std::abs(right)});
  };
  one(m2.px, m1.px, c.px, p1.px, p2.px);
  one(m2.py, m1.py, c.py, p1.py, p2.py);
  one(m2.qx, m1.qx, c.qx, p1.qx, p2.qx);
  one(m2.qy, m1.qy, c.qy, p1.qy, p2.qy);
  return jump / speed;
}

TEST_F(EvalChains, RandomTracksPassEveryKeyframeAndAreC1AtInteriorKnots) {
  std::mt19937_64 rng(42);
  for (const std::string chain : {"", "blend", "neville"}) {
    for (const std::string method : {"P6", "P3", "P9", "P1"}) {
      // Neville is global: its windows are evaluated far from their own
      // knots, so uneven or long tracks overflow or lose every digit
      // (docs/reference/scene-format.md "Keyframe tracks"); it is checked on near-even tracks.
      const bool global = chain == "neville";
      const int n = global ? 4 + static_cast<int>(rng() % 3) : 4 + static_cast<int>(rng() % 9);
      const std::vector<Key> keys = random_track(rng, n, global ? 3.0 : 8.0, global ? 0.3 : 1.5);
      std::vector<double> times;
      for (std::size_t i = 0; i < keys.size(); ++i) {
        const double gap = i + 1 < keys.size() ? keys[i + 1].t - keys[i].t : keys[i].t - keys[i - 1].t;
        const double before = i > 0 ? keys[i].t - keys[i - 1].t : gap;
        const double h = 1e-4 * std::min(gap, before);
        for (int k = -2; k <= 2; ++k) times.push_back(keys[i].t + k * h);
      }
      const std::string extra = chain.empty() ? "" : fmt::format(R"(, "chain": "{}")", chain);
      Json document;
      const std::vector<Frame> frames = eval(scene_text(method, keys, extra), times, &document);
      ASSERT_EQ(frames.size(), times.size());
      EXPECT_EQ(document["chain"], chain.empty() ? "blend" : chain);
      for (std::size_t i = 0; i < keys.size(); ++i) {
        const Frame& at = frames[5 * i + 2];
        const Key& k = keys[i];
        EXPECT_NEAR(at.px, k.x, 1e-9 * 6) << method << " " << chain << " keyframe " << i;
        EXPECT_NEAR(at.py, k.y, 1e-9 * 6);
        EXPECT_NEAR(at.m, k.m, 1e-9 * k.m);
        // P1 is not winding-aware: its windings count modulo 2 pi.
        const double dw = method == "P1" ? std::remainder(at.w - k.w, 2.0 * M_PI) : at.w - k.w;
        EXPECT_NEAR(dw, 0.0, 1e-9 * std::max(1.0, std::abs(k.w)));
        // C1 everywhere: at interior knots and, since the ends continue the
        // end span's motion, at the first and last knot too.
        const double h = times[5 * i + 3] - times[5 * i + 2];
        const double gap = i + 1 < keys.size() ? keys[i + 1].t - keys[i].t : keys[i].t - keys[i - 1].t;
        EXPECT_LT(slope_jump(frames[5 * i], frames[5 * i + 1], at, frames[5 * i + 3], frames[5 * i + 4], h, 10.0 / gap),
                  1e-4)
            << method << " " << chain << " knot " << i << " of " << n;
      }
    }
  }
}

TEST_F(EvalChains, ThreeKeyframesWithAChainAreTheMethodItself) {
  std::mt19937_64 rng(7);
  for (const std::string method : {"P2", "P4", "P6", "P8"}) {
    const std::vector<Key> keys = random_track(rng, 3, 4.0);
    std::vector<double> times;
    for (int i = -8; i <= 24; ++i) times.push_back(keys[0].t + i / 16.0 * (keys[2].t - keys[0].t));
    const std::vector<Frame> plain = eval(scene_text(method, keys), times);
    for (const std::string chain : {"blend", "neville"}) {
      const std::vector<Frame> chained =
          eval(scene_text(method, keys, fmt::format(R"(, "chain": "{}")", chain)), times);
      ASSERT_EQ(chained.size(), plain.size());
      for (std::size_t i = 0; i < plain.size(); ++i) {
        EXPECT_NEAR(chained[i].px, plain[i].px, 1e-12 * 6) << method << " " << chain;
        EXPECT_NEAR(chained[i].qy, plain[i].qy, 1e-12 * 12);
        EXPECT_NEAR(chained[i].w, plain[i].w, 1e-12 * std::max(1.0, std::abs(plain[i].w)));
      }
    }
  }
}

TEST_F(EvalChains, EveryChainContinuesPastBothEnds) {
  std::mt19937_64 rng(9);
  const std::vector<Key> keys = random_track(rng, 6, 6.0, 0.3);
  for (const std::string chain : {"blend", "neville", "spiral", "bezier-spiral"}) {
    const double first = keys.front().t, last = keys.back().t;
    const std::vector<double> times{first - 1e-9, first, first + 1e-9, last - 1e-9, last, last + 1e-9, last + 2.0};
    const std::vector<Frame> f = eval(scene_text("P6", keys, fmt::format(R"(, "chain": "{}")", chain)), times);
    ASSERT_EQ(f.size(), times.size());
    for (const std::size_t centre : {std::size_t{1}, std::size_t{4}}) {
      for (const std::size_t side : {centre - 1, centre + 1}) {
        EXPECT_NEAR(f[side].px, f[centre].px, 1e-6) << chain;
        EXPECT_NEAR(f[side].qy, f[centre].qy, 1e-6) << chain;
        EXPECT_NEAR(f[side].w, f[centre].w, 1e-6) << chain;
      }
    }
    EXPECT_TRUE(std::isfinite(f[6].px)) << chain;
  }
}

TEST_F(EvalChains, SamplesRunFromTheFirstKnotToTheLast) {
  std::mt19937_64 rng(11);
  const std::vector<Key> keys = random_track(rng, 9, 3.0);
  dir.write("track.json", scene_text("P6", keys));
  const RunResult run = run_pita({"eval", "track.json", "--samples", "17"}, dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json frames = Json::parse(run.out)["frames"];
  ASSERT_EQ(frames.size(), 17u);
  EXPECT_EQ(frames.front()["t"].get<double>(), keys.front().t);
  EXPECT_EQ(frames.back()["t"].get<double>(), keys.back().t);
}

TEST_F(EvalChains, PerSpanTimingStillReachesEveryKeyframeAtItsKnot) {
  std::mt19937_64 rng(13);
  const std::vector<Key> keys = random_track(rng, 6, 3.0);
  std::vector<double> knots;
  for (const Key& k : keys) knots.push_back(k.t);
  const std::vector<Frame> f =
      eval(scene_text("P6", keys, R"(, "timing": {"ease": "ease-in-out", "per": "span"})"), knots);
  ASSERT_EQ(f.size(), keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    EXPECT_NEAR(f[i].px, keys[i].x, 1e-9 * 6) << i;
    EXPECT_NEAR(f[i].w, keys[i].w, 1e-9 * std::max(1.0, std::abs(keys[i].w))) << i;
  }
}

}  // namespace
}  // namespace pita::test

namespace pita::test {
namespace {

// Fig. 29's scene through the binary: PITA Eq. 48-50's four conditions
// p(0) = a, p(1/3) = b, p(2/3) = c, p(1) = d for every method P1-P8 (the
// scene's points, read back from the file), and the CSV form.
TEST(EvalPoints, Fig29PassesItsFourPointsWithEveryPita) {
  const std::filesystem::path scene = std::filesystem::path(PITA_SOURCE_DIR) / "scenes/fig29-four-points.json";
  const Json document = Json::parse(read_file(scene));
  const Json& points = document.at("points");
  ASSERT_EQ(points.size(), 4u);
  std::string times;
  for (const Json& point : points) {
    if (!times.empty()) times += ',';
    times += point.at("t").dump();
  }
  ScratchDir dir;
  for (const std::string method : {"P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8"}) {
    const RunResult run = run_pita({"eval", scene.string(), "--method", method, "--t", times}, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = Json::parse(run.out);
    EXPECT_EQ(out.at("curve"), "pita");
    ASSERT_EQ(out.at("frames").size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      const Json& frame = out.at("frames")[i];
      EXPECT_NEAR(frame.at("p")[0].get<double>(), points[i].at("p")[0].get<double>(), 1e-12) << method << " " << i;
      EXPECT_NEAR(frame.at("p")[1].get<double>(), points[i].at("p")[1].get<double>(), 1e-12) << method << " " << i;
    }
  }
  const RunResult csv = run_pita({"eval", scene.string(), "--samples", "3", "--format", "csv"}, dir.path());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')), "t,x,y");
}

}  // namespace
}  // namespace pita::test

namespace pita::test {
namespace {

// Work is weighed by what a frame costs: a neville chain over 64 keyframes
// costs ~1950 method frames per frame, so a million frames are refused before
// any is computed (exit 2, naming /chain), as is a figure that would draw
// 10 000 of them.
TEST(EvalChainsWork, NevilleFramesAreWeighedByTheirCost) {
  ScratchDir dir;
  std::string keys;
  for (int i = 0; i < 64; ++i) {
    keys += fmt::format(R"({}{{"t": {}, "p": [{}, {}], "m": 1, "w": {}}})", i ? ", " : "", i, i, (i * i) % 5, 0.1 * i);
  }
  dir.write("n64.json", R"({"method": "P6", "chain": "neville", "keyframes": [)" + keys + "]}");
  const RunResult many = run_pita({"eval", "n64.json", "--samples", "1000000"}, dir.path());
  EXPECT_EQ(many.exit_code, 2);
  EXPECT_EQ(many.out, "");
  EXPECT_NE(many.err.find("n64.json: /chain: 1000000 frames of the P6 (La-LP), neville chain cost about"),
            std::string::npos)
      << many.err;
  const RunResult few = run_pita({"eval", "n64.json", "--samples", "20"}, dir.path());
  EXPECT_EQ(few.exit_code, 0) << few.err;
  dir.write("fig.json", R"({"method": "P6", "chain": "neville", "samples": 10000, "keyframes": [)" + keys + "]}");
  const RunResult figure = run_pita({"render", "fig.json", "-o", "out.svg"}, dir.path());
  EXPECT_EQ(figure.exit_code, 2) << figure.err;
  EXPECT_NE(figure.err.find("fig.json: /samples"), std::string::npos) << figure.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.svg"));
}

}  // namespace
}  // namespace pita::test
