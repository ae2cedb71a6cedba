// The frame writers (src/scene/frames.cpp): exact JSON and CSV forms.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/frames.hpp"

namespace pita::scene {
namespace {

// Windings of zero make q exact: q = p + (m, 0).
const std::vector<Frame> kTwoFrames = {
    {0.0, Arrow{make_point(0, 0), 1.0, 0.0}},
    {0.5, Arrow{make_point(1.5, -2), 2.0, 0.0}},
};

TEST(FramesToJson, ExactForm) {
  EXPECT_EQ(frames_to_json("P6", kTwoFrames),
            "{\"method\": \"P6\", \"frames\": [\n"
            "  {\"t\": 0.0, \"p\": [0.0, 0.0], \"m\": 1.0, \"w\": 0.0, \"q\": [1.0, 0.0]},\n"
            "  {\"t\": 0.5, \"p\": [1.5, -2.0], \"m\": 2.0, \"w\": 0.0, \"q\": [3.5, -2.0]}\n"
            "]}\n");
}

TEST(FramesToJson, NoFrames) { EXPECT_EQ(frames_to_json("SMA", {}), "{\"method\": \"SMA\", \"frames\": []}\n"); }

TEST(FramesToJson, KeysInOrderAndDoublesRoundTrip) {
  const std::vector<Frame> frames = {
      {0.1, Arrow{make_point(1.0 / 3.0, -2.0 / 7.0), 0.1 + 0.2, 1e-300}},
      {1e10, Arrow{make_point(-1e300, 5e-324), 1.7976931348623157e308, -123.456}},
  };
  const auto document = nlohmann::ordered_json::parse(frames_to_json("P6", frames));
  ASSERT_EQ(document["frames"].size(), frames.size());
  std::vector<std::string> top_keys;
  for (const auto& [key, value] : document.items()) top_keys.push_back(key);
  EXPECT_EQ(top_keys, (std::vector<std::string>{"method", "frames"}));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& frame = document["frames"][i];
    std::vector<std::string> keys;
    for (const auto& [key, value] : frame.items()) keys.push_back(key);
    EXPECT_EQ(keys, (std::vector<std::string>{"t", "p", "m", "w", "q"})) << "frame " << i;
    EXPECT_EQ(frame["t"].get<double>(), frames[i].t) << "frame " << i;
    EXPECT_EQ(frame["p"][0].get<double>(), frames[i].arrow.p.real()) << "frame " << i;
    EXPECT_EQ(frame["p"][1].get<double>(), frames[i].arrow.p.imag()) << "frame " << i;
    EXPECT_EQ(frame["m"].get<double>(), frames[i].arrow.m) << "frame " << i;
    EXPECT_EQ(frame["w"].get<double>(), frames[i].arrow.w) << "frame " << i;
  }
}

TEST(FramesToJson, EscapesTheMethodName) {
  EXPECT_EQ(frames_to_json("a\"b", {}), "{\"method\": \"a\\\"b\", \"frames\": []}\n");
}

TEST(FramesToCsv, HeaderAndSeventeenDigits) {
  EXPECT_EQ(frames_to_csv(kTwoFrames),
            "t,px,py,m,w,qx,qy\n"
            "0,0,0,1,0,1,0\n"
            "0.5,1.5,-2,2,0,3.5,-2\n");
  const std::vector<Frame> third = {{0.1, Arrow{make_point(1.0 / 3.0, 0), 1.0, 0.0}}};
  EXPECT_EQ(frames_to_csv(third),
            "t,px,py,m,w,qx,qy\n"
            "0.10000000000000001,0.33333333333333331,0,1,0,1.3333333333333333,0\n");
}

TEST(FramesToCsv, NoFramesIsJustTheHeader) { EXPECT_EQ(frames_to_csv({}), "t,px,py,m,w,qx,qy\n"); }

TEST(Frames, NonFiniteFramesAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::vector<Frame>> bad = {
      {{nan, Arrow{}}},
      {{0.0, Arrow{make_point(inf, 0), 1.0, 0.0}}},
      {{0.0, Arrow{make_point(0, 0), nan, 0.0}}},
      {{0.0, Arrow{make_point(0, 0), 1.0, -inf}}},
      {{0.0, Arrow{make_point(1.7e308, 0), 1.7e308, 0.0}}},  // q overflows
  };
  for (std::size_t i = 0; i < bad.size(); ++i) {
    EXPECT_THROW(frames_to_json("P6", bad[i]), std::invalid_argument) << "case " << i;
    EXPECT_THROW(frames_to_csv(bad[i]), std::invalid_argument) << "case " << i;
  }
}

// 3D poses: the rows [a, b, c, tx], [d, e, f, ty], [g, h, i, tz] of x -> L x + b.
PoseFrame<Affine3> space_frame() {
  PoseFrame<Affine3> frame;
  frame.t = 0.25;
  frame.pose.L << 1, 2, 3, 4, 5, 6, 7, 8, 9.5;
  frame.pose.b << -1, -2, 0.1;
  return frame;
}

TEST(SpacePoseFrames, ExactJsonAndCsv) {
  const std::vector<PoseFrame<Affine3>> frames = {space_frame()};
  EXPECT_EQ(pose_frames_to_json("SAM", frames),
            "{\"method\": \"SAM\", \"frames\": [\n"
            "  {\"t\": 0.25, \"matrix\": [[1.0, 2.0, 3.0, -1.0], [4.0, 5.0, 6.0, -2.0], [7.0, 8.0, 9.5, 0.1]]}\n"
            "]}\n");
  EXPECT_EQ(pose_frames_to_csv(frames),
            "t,a,b,c,tx,d,e,f,ty,g,h,i,tz\n"
            "0.25,1,2,3,-1,4,5,6,-2,7,8,9.5,0.10000000000000001\n");
}

TEST(SpacePoseFrames, RefuseNonFiniteFrames) {
  PoseFrame<Affine3> frame = space_frame();
  frame.pose.L(2, 1) = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PoseFrame<Affine3>> frames = {frame};
  EXPECT_THROW(pose_frames_to_json("SAM", frames), std::invalid_argument);
  EXPECT_THROW(pose_frames_to_csv(frames), std::invalid_argument);
}

// The printer behind the functions above, used row by row by the streaming
// writers: a refused frame leaves neither text nor a separator behind, so the
// rows around it print as if it had not been offered.
TEST(FramesPrinter, ARefusedRowLeavesNoTrace) {
  const Frame bad{0.25, Arrow{make_point(std::numeric_limits<double>::infinity(), 0), 1.0, 0.0}};
  for (const FramesFormat format : {FramesFormat::json, FramesFormat::csv}) {
    FramesPrinter<Frame> printer(format, "P6");
    FramesBuffer text;
    printer.head(text);
    printer.row(text, kTwoFrames[0]);
    const std::string before = fmt::to_string(text);
    EXPECT_THROW(printer.row(text, bad), std::invalid_argument);
    EXPECT_EQ(fmt::to_string(text), before);
    printer.row(text, kTwoFrames[1]);
    printer.tail(text);
    EXPECT_EQ(fmt::to_string(text),
              format == FramesFormat::json ? frames_to_json("P6", kTwoFrames) : frames_to_csv(kTwoFrames));
  }
}

TEST(FramesPrinter, RequireFiniteIsWhatRowChecks) {
  EXPECT_NO_THROW(FramesPrinter<Frame>::require_finite(kTwoFrames[0]));
  EXPECT_THROW(FramesPrinter<Frame>::require_finite(Frame{std::nan(""), Arrow{}}), std::invalid_argument);
  EXPECT_THROW(FramesPrinter<PointFrame>::require_finite(PointFrame{0.0, make_point(0, std::nan(""))}),
               std::invalid_argument);
  PoseFrame<Affine3> frame = space_frame();
  EXPECT_NO_THROW(FramesPrinter<PoseFrame<Affine3>>::require_finite(frame));
  frame.pose.b(2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(FramesPrinter<PoseFrame<Affine3>>::require_finite(frame), std::invalid_argument);
}

// Printed piece by piece into separate strings, the pieces join into the text
// of the whole-document functions (a chunked stream is the same file).
TEST(FramesPrinter, PiecesJoinIntoTheWholeDocument) {
  const std::vector<PointFrame> points = {{0.0, make_point(1, 2)}, {1.0, make_point(-3, 0.5)}};
  FramesPrinter<PointFrame> printer(FramesFormat::json, "P6", "blend");
  FramesBuffer head, first, second, tail;
  printer.head(head);
  printer.row(first, points[0]);
  printer.row(second, points[1]);
  printer.tail(tail);
  EXPECT_EQ(fmt::to_string(head) + fmt::to_string(first) + fmt::to_string(second) + fmt::to_string(tail),
            point_frames_to_json("P6", points, "blend"));
  EXPECT_EQ(fmt::to_string(head), "{\"method\": \"P6\", \"chain\": \"blend\", \"curve\": \"pita\", \"frames\": [");
}

}  // namespace
}  // namespace pita::scene
