// Fig. 10's decision trees drawn (src/render/decision_tree.cpp and the
// property-table layer's "trees"): one box per question and per leaf, none
// over another, a "yes" and a "no" per question, each parent above the
// middle of its children; an unknown property is the tree's error.
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/decision_tree.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

// A report in which P1 has every property, P2 is only winding-aware and P3
// only handle-invariant (the property table's cells, written by hand).
analysis::AuditReport small_report() {
  analysis::AuditReport report;
  report.methods = {Method::P1, Method::P2, Method::P3};
  for (const analysis::PropertyInfo& p : analysis::all_properties()) report.properties.push_back(p.property);
  for (const Method m : report.methods) {
    for (const analysis::PropertyInfo& p : analysis::all_properties()) {
      analysis::AuditCell cell;
      cell.method = m;
      cell.property = p.property;
      cell.holds = m == Method::P1 || p.letter.empty() ||
                   (m == Method::P2 && p.property == analysis::Property::winding_aware) ||
                   (m == Method::P3 && p.property == analysis::Property::handle_invariant);
      report.cells.push_back(cell);
    }
  }
  return report;
}

TEST(DecisionTreeDrawing, BoxesApartAndParentsOverTheirChildren) {
  const analysis::AuditReport report = small_report();
  const analysis::Property order[] = {analysis::Property::winding_aware, analysis::Property::handle_invariant};
  const analysis::DecisionTree tree = analysis::decision_tree(report, report.methods, order);
  ASSERT_EQ(tree.depth(), 2);  // W: {P1 P2} yes, {P3} no; then H splits P1 from P2
  const TreeDrawing drawing = draw_decision_tree(tree, report, "a tree", "Sans");
  std::vector<std::pair<double, double>> boxes;  // x ranges of the boxes, per row (top y)
  std::vector<double> tops;
  int yes = 0, no = 0;
  std::vector<std::string> texts;
  for (const Shape& shape : drawing.shapes) {
    if (const auto* box = std::get_if<FilledPath>(&shape)) {
      const auto& c = box->contours.front();
      boxes.emplace_back(c[0].real(), c[1].real());
      tops.push_back(c[0].imag());
    } else if (const auto* label = std::get_if<Label>(&shape)) {
      texts.push_back(label->text);
      yes += label->text == "yes";
      no += label->text == "no";
    }
  }
  EXPECT_EQ(boxes.size(), 5u);  // two questions, three leaves
  EXPECT_EQ(yes, 2);
  EXPECT_EQ(no, 2);
  for (const std::string expected :
       {"winding-aware?", "handle-invariant?", "P1 Pa-Ca", "P2 LS-Po", "P3 Pa-LP", "HWPKOAL", "W", "H", "a tree"}) {
    EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end()) << expected;
  }
  // Boxes on one row do not overlap.
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (tops[i] != tops[j]) continue;
      EXPECT_TRUE(boxes[i].second < boxes[j].first || boxes[j].second < boxes[i].first) << i << " " << j;
    }
  }
  // The root is above the middle of its two children.
  const double root = 0.5 * (boxes[0].first + boxes[0].second);
  const double left = 0.5 * (boxes[1].first + boxes[1].second);  // drawn next: the "yes" subtree
  EXPECT_GT(root, left);
  EXPECT_GT(drawing.width, 0.0);
  EXPECT_DOUBLE_EQ(drawing.height, 30.0 + 64.0 * 2 + 38.0);
}

TEST(DecisionTreeDrawing, AnUnknownPropertyIsTheTreesError) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [3, 1.5], "m": 1, "w": 1},
          {"t": 1, "p": [6, 0], "m": 1, "w": 2}],
          "layers": [{"type": "property-table", "configs": 1, "methods": ["P1", "P2"],
                      "trees": [{"order": ["winding-aware", "pop-fre"], "methods": ["P1", "P2"]}]}]})",
      "t.json");
  try {
    build_figure(scene);
    FAIL() << "an unknown property was drawn";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("t.json: /layers/0/trees/0/order/1: unknown property \"pop-fre\"; did you "
                                         "mean \"pop-free\"?"),
              std::string::npos)
        << e.what();
  }
  // A leaf method that is not a column of the table has no measurements.
  const scene::Scene missing = scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [3, 1.5], "m": 1, "w": 1},
          {"t": 1, "p": [6, 0], "m": 1, "w": 2}],
          "layers": [{"type": "property-table", "configs": 1, "methods": ["P1", "P2"],
                      "trees": [{"order": ["winding-aware"], "methods": ["P1", "P3"]}]}]})",
      "t.json");
  EXPECT_THROW(build_figure(missing), RenderError);
}

// The schema lists the properties a tree may ask: the one table's names, in its order.
TEST(DecisionTreeDrawing, TheSchemaNamesEveryProperty) {
  std::ifstream in(std::string(PITA_SOURCE_DIR) + "/schema/scene.schema.json");
  const nlohmann::json schema = nlohmann::json::parse(in);
  std::vector<std::string> names;
  for (const analysis::PropertyInfo& p : analysis::all_properties()) names.emplace_back(p.id);
  EXPECT_EQ(schema.at("definitions")
                .at("propertyTableLayer")
                .at("properties")
                .at("trees")
                .at("items")
                .at("properties")
                .at("order")
                .at("items")
                .at("enum"),
            nlohmann::json(names));
}

}  // namespace
}  // namespace pita::render
