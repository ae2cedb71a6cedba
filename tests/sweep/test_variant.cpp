// Variants of a base scene (src/sweep/variant.cpp): values set where the
// pointers say, pointers that cannot be set refused with the nearest one that
// exists, and the content hash.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "sweep/variant.hpp"

namespace pita::sweep {
namespace {

const std::string kScene = std::string(PITA_SOURCE_DIR) + "/scenes/fig13-knot-ratio.json";

std::string usage_error(const std::vector<std::string>& vary) {
  std::vector<Axis> axes;
  for (const std::string& v : vary) axes.push_back(parse_axis(v));
  try {
    (void)load_base(kScene, Grid(axes, false));
  } catch (const SweepUsageError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(Variant, SetsEachValueAtItsPointerAndNothingElse) {
  const Grid grid({parse_axis("/keyframes/1/t=0.2,0.3"), parse_axis("/timing/ease=linear,smoothstep")}, false);
  const BaseScene base = load_base(kScene, grid);
  const Json v = variant_document(base, grid, grid.values(3));
  EXPECT_EQ(v["keyframes"][1]["t"], Json(0.3));
  EXPECT_EQ(v["timing"]["ease"], Json("smoothstep"));  // created inside a new "timing"
  // The title says what varies (its values follow it); nothing else changes.
  EXPECT_EQ(v["title"],
            base.document["title"].get<std::string>() + " (/keyframes/1/t = 0.3, /timing/ease = smoothstep)");
  Json back = v;
  back["keyframes"][1]["t"] = base.document["keyframes"][1]["t"];
  back["title"] = base.document["title"];
  back.erase("timing");
  EXPECT_EQ(back, base.document);
  EXPECT_EQ(variant_text(v).back(), '\n');
}

TEST(Variant, PointersThatCannotBeSetNameTheNearestOne) {
  EXPECT_NE(usage_error({"/keyframes/7/t=1,2"}).find("nearest pointer that exists is /keyframes/2/t"),
            std::string::npos);
  const std::string typo = usage_error({"/keyframs/1/t=1,2"});
  EXPECT_NE(typo.find("nearest pointer that exists is /keyframes/1/t"), std::string::npos) << typo;
  // A missing member inside an existing object: the reader's "did you mean".
  EXPECT_NE(usage_error({"/optoins=1,2"}).find("did you mean \"options\""), std::string::npos);
  // Arrays are never made up: /points/0/t on a scene without points.
  EXPECT_NE(usage_error({"/points/0/t=1,2"}).find("cannot create an array"), std::string::npos);
  EXPECT_NE(usage_error({"/keyframes/1/tt=1,2"}).find("did you mean \"t\""), std::string::npos);
  EXPECT_NE(usage_error({"/keyframes/1/t/x=1,2"}).find("not an object or array"), std::string::npos);
  EXPECT_EQ(usage_error({"/keyframes/1/t=1,2"}), "(accepted)");
  // A value the scene refuses is the variant's failure, not a usage error.
  EXPECT_EQ(usage_error({"/keyframes/1/m=-1,1"}), "(accepted)");
}

TEST(Variant, HashFollowsTheTextAndTheSalt) {
  EXPECT_EQ(content_hash("a", "svg"), content_hash("a", "svg"));
  EXPECT_NE(content_hash("a", "svg"), content_hash("b", "svg"));
  EXPECT_NE(content_hash("a", "svg"), content_hash("a", "svg png"));
  EXPECT_NE(content_hash("ab", ""), content_hash("a", "b"));
  EXPECT_EQ(content_hash("", "").size(), 16u);
  // FNV-1a 64 of the empty text and salt: the offset basis run over one NUL.
  EXPECT_EQ(content_hash("", ""), "af63bd4c8601b7df");
}

}  // namespace
}  // namespace pita::sweep
