// The axes and the grid of a sweep (src/sweep/grid.cpp): the three SPEC forms,
// the order of the product, --zip, and the limits.
#include <cmath>

#include <gtest/gtest.h>

#include "sweep/grid.hpp"

namespace pita::sweep {
namespace {

std::vector<Json> all(const Axis& a) {
  std::vector<Json> v;
  for (std::size_t i = 0; i < a.size(); ++i) v.push_back(a.value(i));
  return v;
}

TEST(Grid, LinearSpecHasBothEndsAndEvenSteps) {
  const Axis a = parse_axis("/keyframes/1/t=0.1:0.9:5");
  EXPECT_EQ(a.pointer, "/keyframes/1/t");
  ASSERT_EQ(a.size(), 5u);
  const std::vector<Json> v = all(a);
  EXPECT_EQ(v[0].get<double>(), 0.1);
  EXPECT_EQ(v[4].get<double>(), 0.9);
  EXPECT_EQ(v[2].get<double>(), 0.5);
  EXPECT_EQ(v[1].get<double>(), 0.3);  // rounded to 15 digits, not 0.30000000000000004
  for (std::size_t i = 1; i < 5; ++i) EXPECT_NEAR(v[i].get<double>() - v[i - 1].get<double>(), 0.2, 1e-15);
}

TEST(Grid, IntegralValuesAreIntegers) {
  const std::vector<Json> v = all(parse_axis("/samples=5:25:5"));
  ASSERT_EQ(v.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_TRUE(v[i].is_number_integer()) << v[i];
    EXPECT_EQ(v[i].get<int>(), 5 + 5 * static_cast<int>(i));
  }
  EXPECT_EQ(all(parse_axis("/x=3:7:1")), std::vector<Json>{Json(3)});  // n = 1 gives a
}

TEST(Grid, GeometricSpecHasAConstantRatio) {
  const std::vector<Json> v = all(parse_axis("/keyframes/1/m=log:0.1:10:5"));
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v.front().get<double>(), 0.1);
  EXPECT_EQ(v.back().get<double>(), 10);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_NEAR(v[i].get<double>() / v[i - 1].get<double>(), std::sqrt(10.0), 1e-12);
}

// Issue 37: b/a overflows (1e600), the values do not: the steps are taken in
// logarithms. Negative ends give negative values.
TEST(Grid, GeometricSpecSpanningTheDoublesIsFine) {
  const std::vector<Json> v = all(parse_axis("/keyframes/1/m=log:1e-300:1e300:5"));
  ASSERT_EQ(v.size(), 5u);
  const double expected[] = {1e-300, 1e-150, 1, 1e150, 1e300};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(v[i].get<double>() / expected[i], 1.0, 1e-12) << i;
  const std::vector<Json> negative = all(parse_axis("/x=log:-1:-100:3"));
  EXPECT_NEAR(negative[1].get<double>(), -10.0, 1e-12);
}

TEST(Grid, ListsHoldNumbersStringsAndLiterals) {
  const std::vector<Json> v = all(parse_axis("/method=P1,La-LP,2.5,-3,true,null"));
  ASSERT_EQ(v.size(), 6u);
  EXPECT_EQ(v[0], Json("P1"));
  EXPECT_EQ(v[1], Json("La-LP"));
  EXPECT_EQ(v[2], Json(2.5));
  EXPECT_EQ(v[3], Json(-3));
  EXPECT_EQ(v[4], Json(true));
  EXPECT_TRUE(v[5].is_null());
  EXPECT_EQ(all(parse_axis("/method=P6")), std::vector<Json>{Json("P6")});
}

TEST(Grid, QuotedItemsAreJsonStrings) {
  const std::vector<Json> v = all(parse_axis(R"(/title="a, b","say \"hi\"","1",plain,"x:y:3")"));
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], Json("a, b"));
  EXPECT_EQ(v[1], Json("say \"hi\""));
  EXPECT_EQ(v[2], Json("1"));
  EXPECT_EQ(v[3], Json("plain"));
  EXPECT_EQ(v[4], Json("x:y:3"));
  EXPECT_THROW((void)parse_axis(R"(/title="open)"), SweepUsageError);
  EXPECT_THROW((void)parse_axis(R"(/title="a"b)"), SweepUsageError);
}

TEST(Grid, MalformedSpecsAreUsageErrors) {
  for (const char* bad :
       {"/x", "x=1:2:3", "/x=", "/x=1:2", "/x=1:2:0", "/x=1:2:-4", "/x=1:2:2.5", "/x=a:2:3", "/x=1:inf:3",
        "/x=log:0:1:3", "/x=log:-1:1:3", "/x=1,,2", "/x=1:2:3:4", "/x=1:2:20000000", "/x=-1e308:1e308:3", "/x~2=1,2",
        R"(/title="a\u0000b")", R"(/title="\u001b[31mred")", R"(/title="\u0007")"}) {
    EXPECT_THROW((void)parse_axis(bad), SweepUsageError) << bad;
  }
}

TEST(Grid, ProductVariesTheLastAxisFastest) {
  const Grid g({parse_axis("/a=1,2"), parse_axis("/b=x,y,z")}, false);
  ASSERT_EQ(g.size(), 6);
  EXPECT_EQ(g.values(0), (std::vector<Json>{Json(1), Json("x")}));
  EXPECT_EQ(g.values(2), (std::vector<Json>{Json(1), Json("z")}));
  EXPECT_EQ(g.values(3), (std::vector<Json>{Json(2), Json("x")}));
  EXPECT_EQ(g.values(5), (std::vector<Json>{Json(2), Json("z")}));
}

TEST(Grid, ZipPairsValuesAndNeedsEqualLengths) {
  const Grid g({parse_axis("/a=1:3:3"), parse_axis("/b=x,y,z")}, true);
  ASSERT_EQ(g.size(), 3);
  EXPECT_EQ(g.values(1), (std::vector<Json>{Json(2), Json("y")}));
  EXPECT_THROW(Grid({parse_axis("/a=1:3:3"), parse_axis("/b=x,y")}, true), SweepUsageError);
}

TEST(Grid, LimitsAndRepeatsAreUsageErrors) {
  EXPECT_THROW(Grid({}, false), SweepUsageError);
  EXPECT_THROW(Grid({parse_axis("/a=1,2"), parse_axis("/a=3,4")}, false), SweepUsageError);
  EXPECT_THROW(Grid({parse_axis("/a=0:1:10000"), parse_axis("/b=0:1:1001")}, false), SweepUsageError);
  // Exactly at the limit is allowed, and costs no memory: values are computed.
  const Grid big({parse_axis("/a=0:1:10000"), parse_axis("/b=0:1:1000")}, false);
  EXPECT_EQ(big.size(), kMaxVariants);
  EXPECT_EQ(big.values(kMaxVariants - 1), (std::vector<Json>{Json(1), Json(1)}));
}

}  // namespace
}  // namespace pita::sweep
