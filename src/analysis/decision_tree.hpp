// Fig. 10's decision trees, computed from the measured property table (the
// audit, analysis/audit.hpp): a key that tells PITAs apart by the properties
// of Sec. 4, asked in a given order. Each question splits the methods still
// in play into those that have the property and those that lack it; a
// property on which they all agree is not asked; a leaf holds the methods
// no remaining question separates (docs/paper-notes.md N72).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "analysis/audit.hpp"

namespace pita::analysis {

struct DecisionNode {
  std::optional<Property> question;  // nullopt: a leaf
  std::vector<Method> methods;       // the methods that reach this node, in the given order
  int yes = -1, no = -1;             // children (indices into DecisionTree::nodes), -1 for a leaf
};

struct DecisionTree {
  std::vector<DecisionNode> nodes;  // nodes[0] is the root
  int depth() const;                // questions on the longest path
};

// The key of `methods` by the properties of `order`, as the report measured
// them. Throws std::out_of_range for a method or property the report lacks.
DecisionTree decision_tree(const AuditReport& report, std::span<const Method> methods, std::span<const Property> order);

}  // namespace pita::analysis
