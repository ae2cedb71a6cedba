// Fig. 10's decision trees (src/analysis/decision_tree.cpp), built from
// tables of properties written here by hand: every method reaches one leaf,
// the answers on its path are its own, a question that splits nothing is
// not asked, and the paper's printed table gives the tree worked out below.
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "analysis/decision_tree.hpp"

namespace pita::analysis {
namespace {

constexpr Method kEight[] = {Method::P1, Method::P2, Method::P3, Method::P4,
                             Method::P5, Method::P6, Method::P7, Method::P8};
constexpr Property kLettered[] = {Property::winding_aware,      Property::handle_invariant,  Property::pop_free,
                                  Property::knot_controlled,    Property::order_independent, Property::affine_invariant,
                                  Property::locally_perseverant};

// A report whose cells say that each method has exactly the properties of
// its letters (H W P K O A L; L: locally perseverant), and every other.
AuditReport report_of(const std::map<Method, std::string>& letters) {
  AuditReport report;
  for (const auto& [method, has] : letters) report.methods.push_back(method);
  for (const PropertyInfo& p : all_properties()) report.properties.push_back(p.property);
  for (const auto& [method, has] : letters) {
    for (const PropertyInfo& p : all_properties()) {
      const char letter = p.property == Property::locally_perseverant ? 'L'
                          : p.property == Property::globally_perseverant || p.property == Property::radially_perseverant
                              ? '?'
                          : p.letter.empty() ? '*'
                                             : p.letter.front();
      AuditCell cell;
      cell.method = method;
      cell.property = p.property;
      cell.holds = letter == '*' || has.find(letter) != std::string::npos;
      report.cells.push_back(cell);
    }
  }
  return report;
}

// Fig. 10 as printed, read per PITA (the reading notes' column).
const std::map<Method, std::string> kPrinted = {{Method::P1, "HPKOAL"}, {Method::P2, "W"},  {Method::P3, "WPKO"},
                                                {Method::P4, "HP"},     {Method::P5, "KO"}, {Method::P6, "HWPK"},
                                                {Method::P7, "H"},      {Method::P8, "HAL"}};

// Walks the tree: every method reaches exactly one leaf, along answers that are its own.
void expect_consistent(const DecisionTree& tree, const AuditReport& report, std::span<const Method> methods) {
  std::multiset<Method> reached;
  const std::function<void(int, std::vector<std::pair<Property, bool>>)> walk =
      [&](int i, std::vector<std::pair<Property, bool>> path) {
        const DecisionNode& n = tree.nodes.at(static_cast<std::size_t>(i));
        if (!n.question) {
          ASSERT_FALSE(n.methods.empty());
          for (const Method m : n.methods) {
            reached.insert(m);
            for (const auto& [property, answer] : path) {
              EXPECT_EQ(report.cell(m, property).holds, answer) << info(m).id << " " << info(property).id;
            }
          }
          return;
        }
        // A question splits the methods that reach it.
        bool some = false, not_all = false;
        for (const Method m : n.methods) (report.cell(m, *n.question).holds ? some : not_all) = true;
        EXPECT_TRUE(some && not_all) << info(*n.question).id;
        auto yes = path, no = path;
        yes.emplace_back(*n.question, true);
        no.emplace_back(*n.question, false);
        walk(n.yes, yes);
        walk(n.no, no);
      };
  walk(0, {});
  EXPECT_EQ(reached, std::multiset<Method>(methods.begin(), methods.end()));
}

TEST(DecisionTree, EveryMethodReachesOneLeafAlongItsOwnAnswers) {
  const AuditReport report = report_of(kPrinted);
  const DecisionTree tree = decision_tree(report, kEight, kLettered);
  expect_consistent(tree, report, kEight);
}

// The printed table, winding-aware first: W splits {2 3 6} from the rest;
// among them H gives {6} against {2 3}; P then splits P3 from P2. Among the
// others, H gives {1 4 7 8} against {5}; P {1 4} against {7 8}; K P1
// against P4; A P8 against P7. Each PITA has a leaf of its own.
TEST(DecisionTree, ThePrintedTableWindingFirst) {
  const AuditReport report = report_of(kPrinted);
  const DecisionTree tree = decision_tree(report, kEight, kLettered);
  ASSERT_EQ(tree.nodes[0].question, Property::winding_aware);
  const DecisionNode& turning = tree.nodes[static_cast<std::size_t>(tree.nodes[0].yes)];
  EXPECT_EQ(turning.methods, (std::vector<Method>{Method::P2, Method::P3, Method::P6}));
  EXPECT_EQ(turning.question, Property::handle_invariant);
  std::map<Method, int> depth_of;
  const std::function<void(int, int)> leaves = [&](int i, int depth) {
    const DecisionNode& n = tree.nodes[static_cast<std::size_t>(i)];
    if (!n.question) {
      ASSERT_EQ(n.methods.size(), 1u);
      depth_of[n.methods.front()] = depth;
      return;
    }
    leaves(n.yes, depth + 1);
    leaves(n.no, depth + 1);
  };
  leaves(0, 0);
  EXPECT_EQ(depth_of.size(), 8u);
  EXPECT_EQ(depth_of[Method::P6], 2);  // W yes, H yes
  EXPECT_EQ(depth_of[Method::P5], 2);  // W no, H no
  EXPECT_EQ(depth_of[Method::P1], 4);  // W no, H yes, P yes, K yes
  EXPECT_EQ(depth_of[Method::P8], 4);  // W no, H yes, P no, A yes
  EXPECT_EQ(tree.depth(), 4);
}

// Methods with the same properties share a leaf; a property all of them
// have (or lack) is never asked.
TEST(DecisionTree, AlikeMethodsShareALeafAndNothingIsAskedInVain) {
  const AuditReport report = report_of({{Method::P1, "HW"}, {Method::P2, "HW"}, {Method::P3, "H"}});
  const Method methods[] = {Method::P1, Method::P2, Method::P3};
  const DecisionTree tree = decision_tree(report, methods, kLettered);
  ASSERT_EQ(tree.nodes.size(), 3u);
  EXPECT_EQ(tree.nodes[0].question, Property::winding_aware);  // H is shared: not the root
  EXPECT_EQ(tree.nodes[static_cast<std::size_t>(tree.nodes[0].yes)].methods,
            (std::vector<Method>{Method::P1, Method::P2}));
  EXPECT_FALSE(tree.nodes[static_cast<std::size_t>(tree.nodes[0].yes)].question);
  expect_consistent(tree, report, methods);
  // One method, or no question that splits: a single leaf.
  const Property only_handle[] = {Property::handle_invariant};
  const DecisionTree leaf = decision_tree(report, methods, only_handle);
  ASSERT_EQ(leaf.nodes.size(), 1u);
  EXPECT_EQ(leaf.depth(), 0);
}

}  // namespace
}  // namespace pita::analysis
