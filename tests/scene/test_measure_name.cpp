// The names of a "measures" layer (src/scene/measure_name.cpp): what each
// parses into, which scene kind measures it, and why a name is refused.
#include <cmath>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scene/layers.hpp"
#include "scene/measure_name.hpp"

namespace pita::scene {
namespace {

// Parsed in an arrow scene (layers Layer), or a pose scene (PoseLayer).
template <class LayerType = Layer>
MeasureName accepted(std::string_view text) {
  auto parsed = parse_measure<LayerType>(text);
  if (const std::string* reason = std::get_if<std::string>(&parsed)) {
    ADD_FAILURE() << text << " refused: " << *reason;
    return {};
  }
  return std::get<MeasureName>(parsed);
}

template <class LayerType = Layer>
std::string refused(std::string_view text) {
  auto parsed = parse_measure<LayerType>(text);
  if (std::holds_alternative<MeasureName>(parsed)) {
    ADD_FAILURE() << text << " was accepted";
    return {};
  }
  return std::get<std::string>(parsed);
}

TEST(MeasureName, PlainNamesAndTheirKinds) {
  EXPECT_EQ(accepted("discrepancy-max").kind, MeasureKind::discrepancy_max);
  EXPECT_EQ(accepted("path-length").kind, MeasureKind::path_length);
  EXPECT_EQ(accepted("turning").kind, MeasureKind::turning);
  EXPECT_EQ(accepted("winding-range").kind, MeasureKind::winding_range);
  EXPECT_EQ(accepted("overreaction").kind, MeasureKind::overreaction);
  EXPECT_EQ(accepted("pop").kind, MeasureKind::pop);
  EXPECT_EQ(accepted("handle-shift").kind, MeasureKind::handle_shift);
  EXPECT_EQ(accepted<PoseLayer>("ara").kind, MeasureKind::ara);
  EXPECT_EQ(accepted<PoseLayer>("area").kind, MeasureKind::area);
  EXPECT_EQ(accepted("pop").text, "pop");
}

// Each family's names parse in its scenes to their own kind, and are refused
// in the other family's, "only", but for "frame-distance:" and "property:",
// which both have (a claim compares two panels' frames, or two panels' poses;
// a property of pita audit or of pita audit poses); together they are every
// measure.
template <class LayerType, class Other>
void check_family_entries() {
  for (const MeasureEntry& entry : measure_entries_of<LayerType>()) {
    const std::string argument =
        entry.kind == MeasureKind::angle                                                            ? "P6@0.5"
        : entry.kind == MeasureKind::frame_distance || entry.kind == MeasureKind::carried_distance  ? "/panels/1"
        : entry.kind == MeasureKind::property                                                       ? "pop-free"
        : entry.kind == MeasureKind::discrepancy_of || entry.kind == MeasureKind::discrepancy_time  ? "average"
        : entry.kind == MeasureKind::guess_distance || entry.kind == MeasureKind::guess_discrepancy ? "L"
                                                                                                    : "A.p";
    const std::string text = entry.argument ? std::string(entry.name) + argument : std::string(entry.name);
    EXPECT_EQ(accepted<LayerType>(text).kind, entry.kind) << text;
    if (entry.kind == MeasureKind::frame_distance || entry.kind == MeasureKind::property) {
      EXPECT_EQ(accepted<Other>(text).kind, entry.kind) << text;
    } else {
      EXPECT_NE(refused<Other>(text).find("only"), std::string::npos) << text;
    }
  }
}

TEST(MeasureName, EveryEntryParsesToItsOwnKind) {
  check_family_entries<Layer, PoseLayer>();
  check_family_entries<PoseLayer, Layer>();
  EXPECT_EQ(measure_entries_of<Layer>().size() + measure_entries_of<PoseLayer>().size(), measure_entries().size() + 2);
  EXPECT_EQ(measure_entries_of<PoseLayer>().size(),
            5u);  // "property:", "frame-distance:", "ara", "area", "velocity-jump"
}

// "frame-distance:M": an arrow method instead of a panel; "guess-distance:G"
// and "guess-discrepancy:G": any name (the panel's guesses are looked up
// when measured); "knot-distance": no argument.
TEST(MeasureName, FrameDistanceToAMethodGuessesAndKnots) {
  const MeasureName p10 = accepted("frame-distance:P10");
  EXPECT_EQ(p10.kind, MeasureKind::frame_distance);
  EXPECT_EQ(p10.versus, std::optional<AnyMethod>(Method::P10));
  EXPECT_FALSE(p10.panel);
  EXPECT_EQ(accepted("frame-distance:La-LP").versus, std::optional<AnyMethod>(Method::P6));
  const MeasureName layer = accepted("frame-distance:/panels/1/layers/4");
  EXPECT_EQ(layer.panel, std::optional<std::size_t>(1));
  EXPECT_EQ(layer.layer, std::optional<std::size_t>(4));
  EXPECT_FALSE(accepted("frame-distance:/panels/1").layer);
  for (const char* bad : {"frame-distance:/panels/1/layers/", "frame-distance:/panels/1/layers/x"}) {
    EXPECT_NE(refused(bad).find("must be \"frame-distance:/panels/K/layers/L\""), std::string::npos) << bad;
  }
  EXPECT_NE(refused("frame-distance:P99").find("or \"frame-distance:M\", M a method of arrow (keyframe) scenes"),
            std::string::npos);
  const MeasureName guess = accepted("guess-discrepancy:L");
  EXPECT_EQ(guess.kind, MeasureKind::guess_discrepancy);
  EXPECT_EQ(guess.parameter, "L");
  EXPECT_EQ(accepted("guess-distance:E 2").parameter, "E 2");
  EXPECT_NE(refused("guess-distance:").find("must be \"guess-distance:G\""), std::string::npos);
  EXPECT_EQ(accepted("knot-distance").kind, MeasureKind::knot_distance);
  EXPECT_NE(refused<PoseLayer>("knot-distance").find("only"), std::string::npos);
}

// "property:NAME": a name of lower-case words; which names exist is the
// properties' table's (analysis/properties.hpp), checked when measured.
TEST(MeasureName, PropertiesAreNamedInLowerCaseWords) {
  const MeasureName local = accepted("property:locally-perseverant");
  EXPECT_EQ(local.kind, MeasureKind::property);
  EXPECT_EQ(local.parameter, "locally-perseverant");
  for (const char* bad : {"property:", "property:Pop", "property:pop free", "property:a.b"}) {
    EXPECT_NE(refused(bad).find("must be \"property:NAME\""), std::string::npos) << bad;
  }
}

// "discrepancy:P", "discrepancy-t:P": P one of the three predictors of Sec. 6.1.
TEST(MeasureName, DiscrepancyNamesAPredictor) {
  const MeasureName worst = accepted("discrepancy:pita");
  EXPECT_EQ(worst.kind, MeasureKind::discrepancy_of);
  EXPECT_EQ(worst.parameter, "pita");
  EXPECT_EQ(accepted("discrepancy-t:previous").kind, MeasureKind::discrepancy_time);
  for (const char* bad : {"discrepancy:", "discrepancy:mean", "discrepancy-t:Average"}) {
    EXPECT_NE(refused(bad).find("a predictor of Sec. 6.1: \"previous\", \"average\" or \"pita\""), std::string::npos)
        << bad << ": " << refused(bad);
  }
}

TEST(MeasureName, KeyframeParameters) {
  const MeasureName gain = accepted("gain:B.q");
  EXPECT_EQ(gain.kind, MeasureKind::gain);
  EXPECT_EQ(gain.parameter, "B.q");
  EXPECT_EQ(accepted("jump:K27.p.x").parameter, "K27.p.x");
  EXPECT_EQ(accepted("turn:C.w").kind, MeasureKind::turn);
  for (const char* bad : {"gain:", "gain:b.q", "gain:B", "gain:B.q.z", "jump:K2x.p", "gain:AB.q", "gain:Bq"}) {
    EXPECT_NE(refused(bad).find("must name a keyframe and a parameter"), std::string::npos) << bad;
  }
  EXPECT_NE(refused("size:B.q").find("unknown measure"), std::string::npos);
}

TEST(MeasureName, PanelsAreNamedByTheirIndex) {
  EXPECT_EQ(accepted("frame-distance:/panels/12").panel, std::optional<std::size_t>(12));
  EXPECT_EQ(accepted("angle:/panels/0@0.25").panel, std::optional<std::size_t>(0));
  EXPECT_EQ(accepted("angle:/panels/0@0.25").t, 0.25);
  EXPECT_FALSE(accepted("angle:P6@0.25").panel.has_value());
  for (const char* bad : {"frame-distance:", "frame-distance:/panels/", "frame-distance:/panels/x",
                          "frame-distance:/panels/1/", "frame-distance:panels/1", "frame-distance:/panels/-1"}) {
    EXPECT_NE(refused(bad).find("must be \"frame-distance:/panels/K\""), std::string::npos) << bad;
  }
  EXPECT_FALSE(accepted("frame-distance:/panels/2").at.has_value());
  EXPECT_EQ(accepted("frame-distance:/panels/2@1.5").at, std::optional<double>(1.5));
  EXPECT_EQ(accepted("frame-distance:/panels/2@1.5").panel, std::optional<std::size_t>(2));
  EXPECT_EQ(accepted<PoseLayer>("frame-distance:/panels/0@-0.25").at, std::optional<double>(-0.25));
  for (const char* bad : {"frame-distance:/panels/2@", "frame-distance:/panels/2@x", "frame-distance:/panels/2@inf"}) {
    EXPECT_NE(refused(bad).find("the time after \"@\" must be a finite number"), std::string::npos) << bad;
  }
  EXPECT_NE(refused("carried-distance:/panels/2@1").find("must be \"carried-distance:/panels/K\""), std::string::npos);
  EXPECT_EQ(accepted("carried-distance:/panels/3").kind, MeasureKind::carried_distance);
  EXPECT_EQ(accepted("carried-distance:/panels/3").panel, std::optional<std::size_t>(3));
  EXPECT_NE(refused("carried-distance:/panels/").find("must be \"carried-distance:/panels/K\""), std::string::npos);
  EXPECT_NE(refused<PoseLayer>("carried-distance:/panels/1").find("only"), std::string::npos);
  EXPECT_NE(refused("angle:/panels/one@0.5").find("must be \"/panels/\" and a panel's index"), std::string::npos);
}

// "frame-distance:M": another method of the scene's kind instead of a panel.
TEST(MeasureName, FrameDistanceToAMethodOfTheScenesKind) {
  EXPECT_EQ(accepted("frame-distance:P8").versus, std::optional<AnyMethod>(Method::P8));
  EXPECT_FALSE(accepted("frame-distance:P8").panel.has_value());
  EXPECT_EQ(accepted<PoseLayer>("frame-distance:Alexa").versus, std::optional<AnyMethod>(PoseMethod::alexa));
  EXPECT_FALSE(accepted("frame-distance:/panels/1").versus.has_value());
  // A method of the other kind is not one of the scene's.
  EXPECT_NE(refused("frame-distance:Alexa").find("\"frame-distance:M\", M a method of arrow (keyframe) scenes"),
            std::string::npos)
      << refused("frame-distance:Alexa");
  EXPECT_NE(refused<PoseLayer>("frame-distance:P1").find("M a method of pose scenes"), std::string::npos);
}

TEST(MeasureName, AnglesNameAnArrowMethodAndAFiniteTime) {
  const MeasureName angle = accepted("angle:Pa-Po@0.25");
  EXPECT_EQ(angle.kind, MeasureKind::angle);
  EXPECT_EQ(angle.method, Method::PaPo);  // Fig. 7's parabolic point, polar vector
  EXPECT_EQ(angle.t, 0.25);
  EXPECT_EQ(accepted("angle:p1@-1e-1").t, -0.1);
  EXPECT_EQ(accepted("angle:P8@2").method, Method::P8);
  // Only what the schema's pattern accepts: no sign "+", no spaces, no hex, finite.
  for (const char* bad : {"angle:P3@", "angle:P3@0.5x", "angle:P3@1e999", "angle:P3@ 0.5", "angle:P3@+0.5",
                          "angle:P3@0x1p-2", "angle:P3@nan", "angle:P3@inf", "angle:P3@-inf"}) {
    EXPECT_NE(refused(bad).find("must be a finite number"), std::string::npos) << bad;
  }
  EXPECT_NE(refused("angle:P3").find("must be \"angle:M@t\""), std::string::npos);
  EXPECT_NE(refused("angle:@0.5").find("must be \"angle:M@t\""), std::string::npos);
  EXPECT_NE(refused("angle:P99@0.5").find("unknown method \"P99\""), std::string::npos);
  EXPECT_NE(refused("angle:SAM@0.5").find("unknown method \"SAM\""), std::string::npos);  // a pose method
}

TEST(MeasureName, EachSceneKindRefusesWhatItDoesNotMeasure) {
  EXPECT_EQ(refused("ara"),
            "\"ara\" is measured in pose scenes only; arrow (keyframe) scenes measure "
            "\"discrepancy-max\", \"path-length\", \"turning\", \"inflections\", \"winding-range\", \"overreaction\", "
            "\"pop\", \"handle-shift\", \"scale-step\", \"turn-step\", \"scale-min\", \"scale-max\", "
            "\"turn-step-t\" or \"knot-distance\"");
  EXPECT_EQ(refused<PoseLayer>("handle-shift"),
            "\"handle-shift\" is measured in arrow (keyframe) scenes only; pose scenes measure \"ara\", \"area\" or "
            "\"velocity-jump\"");
  EXPECT_NE(refused<PoseLayer>("angle:P6@0.5").find("arrow (keyframe) scenes only"), std::string::npos);
  EXPECT_NE(refused<PoseLayer>("gain:A.p").find("arrow (keyframe) scenes only"), std::string::npos);
}

TEST(MeasureName, UnknownNamesGetSuggestionsOrTheList) {
  EXPECT_EQ(refused("pops"), "unknown measure \"pops\"; did you mean \"pop\"?");
  EXPECT_NE(refused("zzzzzz").find("\"angle:M@t\""), std::string::npos);
  EXPECT_EQ(refused<PoseLayer>("zzzzzz"),
            "unknown measure \"zzzzzz\"; pose scenes measure \"ara\", \"area\" or \"velocity-jump\", or in a "
            "claim \"frame-distance:/panels/K\" (or \"frame-distance:M\", M a pose method) and \"property:NAME\" (a "
            "property as pita audit poses names it)");
}

TEST(MeasureName, DefaultsOfEachSceneKind) {
  const std::vector<MeasureName> arrows = default_measures<Layer>();
  ASSERT_EQ(arrows.size(), 2u);
  EXPECT_EQ(arrows[0].kind, MeasureKind::overreaction);
  EXPECT_EQ(arrows[1].kind, MeasureKind::pop);
  const std::vector<MeasureName> poses = default_measures<PoseLayer>();
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].kind, MeasureKind::ara);
  EXPECT_EQ(poses[1].kind, MeasureKind::area);
}

}  // namespace
}  // namespace pita::scene
