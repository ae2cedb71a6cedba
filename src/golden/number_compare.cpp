#include "golden/number_compare.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/limits.hpp"

namespace pita::golden {

namespace {

class Walker {
 public:
  Walker(NumberComparison& result, double relative) : r_(result), relative_(relative) {}

  void panels(const Json& expected, const Json& actual) {
    const Json& e = expected.at("panels");
    const Json& a = actual.at("panels");
    if (e.size() != a.size()) {
      return structural("/panels", fmt::format("{} panels instead of {}", a.size(), e.size()));
    }
    for (std::size_t i = 0; i < e.size() && r_.structure.empty(); ++i) {
      const std::string at = "/panels/" + std::to_string(i);
      extent_ = std::max(e[i].at("extent").get<double>(), limits::kTinyScale);
      panel_ = e[i].at("pointer").get<std::string>();
      const Json& ei = e[i].at("items");
      const Json& ai = a[i].at("items");
      if (ei.size() != ai.size()) {
        return structural(at + "/items", fmt::format("{} shapes instead of {}", ai.size(), ei.size()));
      }
      for (std::size_t k = 0; k < ei.size() && r_.structure.empty(); ++k) {
        layer_ = ei[k].value("layer", std::string());
        index_ = ei[k].value("index", -1);
        value(ei[k], ai[k], at + "/items/" + std::to_string(k));
      }
    }
  }

 private:
  void structural(const std::string& pointer, const std::string& what) {
    r_.matches = false;
    r_.structure = pointer + ": " + what;
  }

  void value(const Json& e, const Json& a, const std::string& at) {
    if (e.is_number() && a.is_number()) {
      const double x = e.get<double>(), y = a.get<double>();
      const double d = std::abs(y - x) / extent_;
      ++r_.compared;
      if (!(d <= relative_)) {  // also NaN
        ++r_.differing;
        r_.matches = false;
      }
      // The worst offender so far (a NaN is the worst of all).
      if (r_.compared == 1 || std::isnan(d) || d > r_.relative) {
        r_.relative = std::isnan(d) ? INFINITY : d;
        r_.pointer = at;
        r_.panel = panel_;
        r_.layer = layer_;
        r_.index = index_;
        r_.expected = x;
        r_.actual = y;
      }
      return;
    }
    if (e.type() != a.type()) return structural(at, "a different kind of value");
    if (e.is_array()) {
      if (e.size() != a.size()) {
        return structural(at, fmt::format("{} elements instead of {}", a.size(), e.size()));
      }
      for (std::size_t i = 0; i < e.size() && r_.structure.empty(); ++i) {
        value(e[i], a[i], at + "/" + std::to_string(i));
      }
      return;
    }
    if (e.is_object()) {
      if (e.size() != a.size()) return structural(at, "different fields");
      for (auto it = e.begin(); it != e.end() && r_.structure.empty(); ++it) {
        const auto other = a.find(it.key());
        if (other == a.end()) return structural(at, "no field \"" + it.key() + "\"");
        value(*it, *other, at + "/" + it.key());
      }
      return;
    }
    if (e != a) structural(at, fmt::format("{} instead of {}", a.dump(), e.dump()));
  }

  NumberComparison& r_;
  double relative_;
  double extent_ = 1.0;
  std::string panel_, layer_;
  int index_ = -1;
};

}  // namespace

NumberComparison compare_numbers(const Json& expected, const Json& actual, double relative) {
  NumberComparison result;
  Walker(result, relative).panels(expected, actual);
  return result;
}

std::string describe(const NumberComparison& c, double relative) {
  if (!c.structure.empty()) return "the drawing's structure differs at " + c.structure;
  std::string where = c.layer.empty() ? "" : "layer " + c.layer;
  if (!c.panel.empty()) where = "panel " + c.panel + (where.empty() ? "" : ", " + where);
  if (c.index >= 0) where += fmt::format(", frame {}", c.index);
  return fmt::format(
      "{} of {} numbers differ; worst at {} ({}): {} instead of {} ({:.3g} of the "
      "panel's extent; tolerance {:g})",
      c.differing, c.compared, c.pointer, where, c.actual, c.expected, c.relative, relative);
}

}  // namespace pita::golden
