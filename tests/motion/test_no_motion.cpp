// The motion stage's one error (src/motion/no_motion.hpp).
#include <gtest/gtest.h>

#include "motion/no_motion.hpp"

namespace pita::motion {
namespace {

TEST(NoMotion, NamesFilePointerAndReason) {
  const NoMotion error("a.json", "/keyframes", "method P7 has no motion");
  EXPECT_STREQ(error.what(), "a.json: /keyframes: method P7 has no motion");
  EXPECT_EQ(error.file(), "a.json");
  EXPECT_EQ(error.pointer(), "/keyframes");
  EXPECT_EQ(error.reason(), "method P7 has no motion");
  EXPECT_STREQ(NoMotion("a.json", "", "too far apart").what(), "a.json: too far apart");
}

}  // namespace
}  // namespace pita::motion
