// Fig. 10's decision trees (analysis/decision_tree.hpp) drawn as a key: a
// box per question ("winding-aware?"), its "yes" branch to the left and its
// "no" branch to the right, a green box per leaf with the PITAs that reach
// it and the letters they have. Coordinates are pixels, y down, from the
// tree's top-left corner; texts are measured with the figure's font so that
// boxes fit them (render/painter.hpp).
#pragma once

#include <string>
#include <vector>

#include "analysis/decision_tree.hpp"
#include "render/drawing.hpp"

namespace pita::render {

struct TreeDrawing {
  std::vector<Shape> shapes;
  double width = 0.0;
  double height = 0.0;
};

// The letters of Fig. 10 that `method` has, as measured ("HWPK").
std::string property_letters(const analysis::AuditReport& report, Method method);

TreeDrawing draw_decision_tree(const analysis::DecisionTree& tree, const analysis::AuditReport& report,
                               const std::string& title, const std::string& font);

}  // namespace pita::render
