// The tables of layer kinds (src/scene/layer_kinds.hpp): every struct of the
// Layer and PoseLayer variants has exactly one row, each row names the struct
// its reader returns, and the "draws" column of arrow layers is what the
// reader enforces (the bad-input files points-*-layer of tests/data/bad/).
#include <filesystem>
#include <fstream>
#include <set>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/figure_reader.hpp"
#include "scene/layer_kinds.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {
namespace {

template <typename LayerType>
void expect_one_row_per_alternative(const std::vector<LayerKindInfo>& kinds) {
  std::set<std::size_t> alternatives;
  std::set<std::string> types;
  for (const LayerKindInfo& kind : kinds) {
    EXPECT_LT(kind.alternative, std::variant_size_v<LayerType>) << kind.type;
    EXPECT_TRUE(alternatives.insert(kind.alternative).second) << kind.type << ": a second row for one struct";
    EXPECT_TRUE(types.insert(std::string(kind.type)).second) << kind.type;
  }
  EXPECT_EQ(alternatives.size(), std::variant_size_v<LayerType>);
}

TEST(LayerKinds, EveryStructHasOneRow) {
  expect_one_row_per_alternative<Layer>(arrow_layer_kinds());
  expect_one_row_per_alternative<PoseLayer>(pose_layer_kinds());
}

// Each row's reader returns the struct its alternative names: in every scene
// of scenes/, the row kind_of finds for each layer read is the row of the
// layer's "type".
template <typename LayerType>
void expect_rows_of(const std::vector<LayerType>& layers, const nlohmann::json& given,
                    std::span<const LayerKind<LayerType>> table, const std::string& where) {
  ASSERT_EQ(layers.size(), given.size()) << where;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    EXPECT_EQ(kind_of(table, layers[i]).type, given[i].at("type").get<std::string>()) << where << i;
  }
}

TEST(LayerKinds, KindOfFindsTheRowOfEveryLayerOfTheScenes) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PITA_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream file(entry.path());
    const nlohmann::json document = nlohmann::json::parse(file);
    if (!document.contains("layers")) continue;
    const Scene scene = load_scene(entry.path().string());
    const std::string where = entry.path().filename().string() + " /layers/";
    std::visit(
        [&]<class Keys>(const Keys& keys) {
          if constexpr (std::is_same_v<FigureOf<Keys>, ArrowFigure>) {
            expect_rows_of(figure_of(scene, keys).layers, document["layers"], arrow_layer_table(), where);
          } else {
            expect_rows_of(figure_of(scene, keys).layers, document["layers"], pose_layer_table(), where);
          }
        },
        scene.keys);
    checked += static_cast<int>(document["layers"].size());
  }
  EXPECT_GT(checked, 100);
}

TEST(LayerKinds, WhatArrowLayersDraw) {
  for (const LayerKindInfo& kind : arrow_layer_kinds()) {
    const LayerDraws expected = kind.type == "point-trajectory"                 ? LayerDraws::points
                                : kind.type == "label" || kind.type == "legend" ? LayerDraws::either
                                                                                : LayerDraws::keyframes;
    EXPECT_EQ(kind.draws, expected) << kind.type;
  }
}

}  // namespace
}  // namespace pita::scene::detail
