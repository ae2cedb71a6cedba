#include "analysis/decision_tree.hpp"

#include <algorithm>
#include <functional>

namespace pita::analysis {

namespace {

struct Builder {
  const AuditReport& report;
  std::span<const Property> order;
  DecisionTree tree;

  int add(std::vector<Method> methods, std::size_t from) {
    const int index = static_cast<int>(tree.nodes.size());
    tree.nodes.push_back({std::nullopt, methods, -1, -1});
    // The next property of the order that splits these methods. One that does
    // not split them splits none of their subsets either, so the scan goes on
    // from there in both branches.
    for (std::size_t k = from; k < order.size(); ++k) {
      std::vector<Method> having, lacking;
      for (const Method m : methods) (report.cell(m, order[k]).holds ? having : lacking).push_back(m);
      if (having.empty() || lacking.empty()) continue;
      tree.nodes[static_cast<std::size_t>(index)].question = order[k];
      const int yes = add(std::move(having), k + 1);
      const int no = add(std::move(lacking), k + 1);
      tree.nodes[static_cast<std::size_t>(index)].yes = yes;
      tree.nodes[static_cast<std::size_t>(index)].no = no;
      break;
    }
    return index;
  }
};

}  // namespace

int DecisionTree::depth() const {
  const std::function<int(int)> depth_of = [&](int i) -> int {
    const DecisionNode& n = nodes[static_cast<std::size_t>(i)];
    return n.question ? 1 + std::max(depth_of(n.yes), depth_of(n.no)) : 0;
  };
  return nodes.empty() ? 0 : depth_of(0);
}

DecisionTree decision_tree(const AuditReport& report, std::span<const Method> methods,
                           std::span<const Property> order) {
  Builder builder{report, order, {}};
  builder.add(std::vector<Method>(methods.begin(), methods.end()), 0);
  return std::move(builder.tree);
}

}  // namespace pita::analysis
