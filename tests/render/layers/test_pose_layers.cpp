// The drawers of pose layers (render/layers/pose_layers.hpp) against the
// table of pose layer kinds (scene/layer_kinds.hpp): every kind has a drawer
// in the plane, and a drawer in space exactly when its row says 3D scenes
// draw it (the "in_space" column the reader enforces).
#include <cstddef>
#include <utility>
#include <variant>

#include <gtest/gtest.h>

#include "render/layers/pose_layers.hpp"
#include "scene/layer_kinds.hpp"

namespace pita::render {
namespace {

template <std::size_t... I>
void expect_drawers_match_the_table(std::index_sequence<I...>) {
  const auto check = []<std::size_t K>(std::integral_constant<std::size_t, K>) {
    using Layer = std::variant_alternative_t<K, scene::PoseLayer>;
    bool found = false;
    for (const auto& kind : scene::detail::pose_layer_table()) {
      if (kind.alternative != K) continue;
      found = true;
      EXPECT_TRUE((DrawnIn<Affine2, Layer>)) << kind.type << ": no drawer in the plane";
      EXPECT_EQ((DrawnIn<Affine3, Layer>), kind.in_space)
          << kind.type << ": a drawer in space exactly when the table's in_space says so";
    }
    EXPECT_TRUE(found) << "alternative " << K << " has no row";
  };
  (check(std::integral_constant<std::size_t, I>{}), ...);
}

TEST(PoseLayers, EveryKindHasItsDrawersAsTheTableSays) {
  expect_drawers_match_the_table(std::make_index_sequence<std::variant_size_v<scene::PoseLayer>>{});
}

}  // namespace
}  // namespace pita::render
