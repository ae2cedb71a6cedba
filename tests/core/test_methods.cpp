// The one registry of methods (src/core/methods.cpp): every name of every
// method of both kinds resolves, no name means two methods, the one wording of
// unknown names, and the method tables of docs/reference agree with the registry.
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/methods.hpp"

namespace pita {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

TEST(Methods, EveryMethodOfBothKindsIsRegisteredOnce) {
  std::size_t arrows = 0, poses = 0;
  std::set<std::string> ids;
  for (const MethodEntry& entry : every_method()) {
    (is_method_of<Method>(entry) ? arrows : poses)++;
    EXPECT_TRUE(ids.insert(upper(std::string(entry.id))).second) << entry.id;
  }
  EXPECT_EQ(arrows, all_methods().size());
  EXPECT_EQ(poses, all_pose_methods().size());
}

TEST(Methods, EveryNameResolvesInAnyCase) {
  for (const MethodEntry& entry : every_method()) {
    SCOPED_TRACE(std::string(entry.id));
    for (const std::string& name : {std::string(entry.id), upper(std::string(entry.id)), std::string(entry.mnemonic)}) {
      const MethodEntry* found = find_method_entry(name);
      ASSERT_NE(found, nullptr) << name;
      EXPECT_EQ(found, &entry) << name;
    }
    // Filtered by its own kind it is found; by the other kind it is not.
    const bool arrow = is_method_of<Method>(entry);
    EXPECT_EQ(find_method_entry(entry.id, arrow ? is_method_of<Method> : is_method_of<PoseMethod>), &entry);
    EXPECT_EQ(find_method_entry(entry.id, arrow ? is_method_of<PoseMethod> : is_method_of<Method>), nullptr);
    EXPECT_EQ(find_method_of<Method>(entry.id) != nullptr, arrow);
    EXPECT_EQ(find_method_of<PoseMethod>(entry.id) != nullptr, !arrow);
  }
  EXPECT_EQ(find_method_entry("6")->method, AnyMethod(Method::P6));
  EXPECT_EQ(find_method_entry("5s")->method, AnyMethod(Method::P5S));
  EXPECT_EQ(find_method_entry("P6:La-LP")->method, AnyMethod(Method::P6));
  EXPECT_EQ(*find_method_of<Method>("lo-pe"), Method::P8);
  EXPECT_EQ(find_method_entry("POLYSAM")->method, AnyMethod(PoseMethod::poly_sam));
  EXPECT_EQ(*find_method_of<PoseMethod>("four-point-sam"), PoseMethod::four_point);
  EXPECT_EQ(find_method_of<PoseMethod>("6"), nullptr);  // PITA numbers are arrow names only
  EXPECT_EQ(find_method_entry("P66"), nullptr);
}

TEST(Methods, UnknownNamesHaveOneWording) {
  EXPECT_EQ(unknown_method_reason("P66", is_method_of<Method>),
            "unknown method \"P66\"; did you mean P6 (La-LP), P1 (Pa-Ca) or P2 (LS-Po)?");
  EXPECT_EQ(unknown_method_reason("polysan", is_method_of<PoseMethod>),
            "unknown method \"polysan\"; did you mean polySAM?");
  const std::string none = unknown_method_reason("zzzzzz", is_method_of<PoseMethod>);
  EXPECT_EQ(none,
            "unknown method \"zzzzzz\"; known methods: SAM, polySAM, bezier-SAM, biarc-SAM, linear, four-point-SAM, "
            "rARAP, ASAP, TSB, Alexa");
}

TEST(Methods, LabelsAsMessagesNameThem) {
  EXPECT_EQ(method_label(entry_of(Method::P6)), "P6 (La-LP)");
  EXPECT_EQ(method_label(entry_of(Method::SMA)), "SMA");
  EXPECT_EQ(method_label(entry_of(PoseMethod::bezier_sam)), "bezier-SAM");
}

// The reference's method tables list every method of the registry, once each
// (docs/reference/methods.md for arrows, docs/reference/pose-scenes.md for poses).
TEST(Methods, ReferenceListsEveryMethod) {
  std::string pages;
  for (const char* page : {"/docs/reference/methods.md", "/docs/reference/pose-scenes.md"}) {
    std::ifstream in(std::string(PITA_SOURCE_DIR) + page);
    std::stringstream text;
    text << in.rdbuf();
    ASSERT_FALSE(text.str().empty()) << page;
    pages += text.str();
  }
  for (const MethodEntry& entry : every_method()) {
    const std::string cell =
        is_method_of<Method>(entry) ? "| " + std::string(entry.id) + " |" : "`" + std::string(entry.id) + "`";
    EXPECT_NE(pages.find(cell), std::string::npos) << "docs/reference does not list " << entry.id << " as " << cell;
  }
}

}  // namespace
}  // namespace pita
