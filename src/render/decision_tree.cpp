#include "render/decision_tree.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "render/painter.hpp"

namespace pita::render {

namespace {

constexpr double kLevel = 64.0;  // pixels between the tops of two levels
constexpr double kTitleHeight = 30.0;
constexpr double kGap = 14.0;  // between two leaves
constexpr double kPad = 6.0;   // inside a box
constexpr double kQuestionSize = 12.0, kLeafSize = 12.0, kLettersSize = 11.0, kBranchSize = 10.0;
const Color kInk{0.1, 0.1, 0.1, 1.0};
const Color kQuestionFill{0.93, 0.93, 0.93, 1.0};
const Color kLeafFill{0.80, 0.93, 0.80, 1.0};
const Color kEdge{0.45, 0.45, 0.45, 1.0};

class Layout {
 public:
  Layout(const analysis::DecisionTree& tree, const analysis::AuditReport& report, const std::string& font)
      : tree_(tree), report_(report), font_(font), x_(tree.nodes.size(), 0.0), width_(tree.nodes.size(), 0.0) {}

  // The ink box of `text` drawn at (0, 0).
  Rect ink(const std::string& text, double size) const {
    return text_ink_box(text, font_, size, TextPlacement{0.0, 0.0, TextAlign::left}, false);
  }

  // A label whose ink is centred on (cx, cy).
  Label centred(const std::string& text, double size, Point centre, const Color& color) const {
    const Rect box = ink(text, size);
    // paint_text puts the layout's top 0.6 size above the anchor (render/painter.cpp).
    return Label{text,
                 {centre.real() - (box.x + 0.5 * box.width), centre.imag() - (box.y + 0.5 * box.height) + 0.6 * size},
                 size,
                 color};
  }

  std::string leaf_text(const analysis::DecisionNode& node) const {
    std::string text;
    for (const Method m : node.methods) text += fmt::format("{}{}", text.empty() ? "" : ", ", method_name(m));
    return text;
  }
  std::string letters_text(const analysis::DecisionNode& node) const {
    const std::string letters = property_letters(report_, node.methods.front());
    return letters.empty() ? std::string("-") : letters;
  }
  double box_width(int i) const {
    const analysis::DecisionNode& n = tree_.nodes[static_cast<std::size_t>(i)];
    if (n.question) return ink(std::string(info(*n.question).id) + "?", kQuestionSize).width + 2 * kPad;
    return std::max(ink(leaf_text(n), kLeafSize).width, ink(letters_text(n), kLettersSize).width) + 2 * kPad;
  }

  // Places the leaves left to right ("yes" before "no"), each parent over the
  // middle of its children; returns the next free x.
  double place(int i, double left) {
    const analysis::DecisionNode& n = tree_.nodes[static_cast<std::size_t>(i)];
    width_[static_cast<std::size_t>(i)] = box_width(i);
    if (!n.question) {
      x_[static_cast<std::size_t>(i)] = left + 0.5 * width_[static_cast<std::size_t>(i)];
      return left + width_[static_cast<std::size_t>(i)] + kGap;
    }
    const double after_yes = place(n.yes, left);
    double right = place(n.no, after_yes);
    double centre = 0.5 * (x_[static_cast<std::size_t>(n.yes)] + x_[static_cast<std::size_t>(n.no)]);
    // A question wider than its children's span moves them right.
    const double overhang = left + 0.5 * width_[static_cast<std::size_t>(i)] - centre;
    if (overhang > 0.0) {
      shift(i, overhang);
      centre += overhang;
      right += overhang;
    }
    x_[static_cast<std::size_t>(i)] = centre;
    return std::max(right, centre + 0.5 * width_[static_cast<std::size_t>(i)] + kGap);
  }

  void draw(int i, int depth, std::vector<Shape>& out) const {
    const analysis::DecisionNode& n = tree_.nodes[static_cast<std::size_t>(i)];
    const double x = x_[static_cast<std::size_t>(i)], w = width_[static_cast<std::size_t>(i)];
    const double top = kTitleHeight + kLevel * depth;
    if (!n.question) {
      const double h = 38.0;
      out.push_back(
          FilledPath{{rectangle_corners(x - 0.5 * w, top, w, h)}, kLeafFill, 1.0, LineStyle{kEdge, 0.8, 1.0, {}}});
      out.push_back(centred(leaf_text(n), kLeafSize, {x, top + 12.0}, kInk));
      out.push_back(centred(letters_text(n), kLettersSize, {x, top + 27.0}, kInk));
      return;
    }
    const double h = 24.0;
    out.push_back(
        FilledPath{{rectangle_corners(x - 0.5 * w, top, w, h)}, kQuestionFill, 1.0, LineStyle{kEdge, 0.8, 1.0, {}}});
    out.push_back(centred(std::string(info(*n.question).id) + "?", kQuestionSize, {x, top + 0.5 * h}, kInk));
    for (const auto& [child, word] : {std::pair{n.yes, "yes"}, std::pair{n.no, "no"}}) {
      const Point from{x, top + h}, to{x_[static_cast<std::size_t>(child)], top + kLevel};
      out.push_back(Polyline{{from, to}, false, LineStyle{kEdge, 1.0, 1.0, {}}});
      // The branch's word beside its edge, on the outer side.
      const Point middle = 0.5 * (from + to);
      const double side = child == n.yes ? -1.0 : 1.0;
      out.push_back(centred(word, kBranchSize, middle + Point{side * 16.0, -4.0}, kEdge));
      draw(child, depth + 1, out);
    }
  }

  double x(int i) const { return x_[static_cast<std::size_t>(i)]; }
  double width(int i) const { return width_[static_cast<std::size_t>(i)]; }

 private:
  void shift(int i, double by) {
    x_[static_cast<std::size_t>(i)] += by;
    const analysis::DecisionNode& n = tree_.nodes[static_cast<std::size_t>(i)];
    if (n.question) {
      shift(n.yes, by);
      shift(n.no, by);
    }
  }

  const analysis::DecisionTree& tree_;
  const analysis::AuditReport& report_;
  const std::string& font_;
  std::vector<double> x_, width_;
};

}  // namespace

std::string property_letters(const analysis::AuditReport& report, Method method) {
  std::string has;
  for (const analysis::Property property : report.properties) {
    const analysis::PropertyInfo& p = info(property);
    if (p.letter.empty() || !report.cell(method, property).holds) continue;
    if (has.find(p.letter) == std::string::npos) has += p.letter;
  }
  return has;
}

TreeDrawing draw_decision_tree(const analysis::DecisionTree& tree, const analysis::AuditReport& report,
                               const std::string& title, const std::string& font) {
  TreeDrawing out;
  if (tree.nodes.empty()) return out;
  Layout layout(tree, report, font);
  const double right = layout.place(0, 0.0) - kGap;
  out.shapes.push_back(Label{title, {0.0, 0.6 * 14.0}, 14.0, kInk});
  layout.draw(0, 0, out.shapes);
  out.width = std::max(right, layout.ink(title, 14.0).width);
  out.height = kTitleHeight + kLevel * tree.depth() + 38.0;
  return out;
}

}  // namespace pita::render
