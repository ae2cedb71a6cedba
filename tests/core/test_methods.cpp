// The one registry of methods (src/core/methods.cpp): every name of every
// method of both kinds resolves, no name means two methods of one kind (the pose PITAs share the arrow PITAs' names),
// the one wording of unknown names, and the method tables of docs/reference agree with the registry.
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

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
  std::set<std::string> arrow_ids, pose_ids;
  for (const MethodEntry& entry : every_method()) {
    const bool arrow = is_method_of<Method>(entry);
    (arrow ? arrows : poses)++;
    EXPECT_TRUE((arrow ? arrow_ids : pose_ids).insert(upper(std::string(entry.id))).second) << entry.id;
  }
  // The names both kinds share are the PITAs over affine poses, with the
  // arrow PITA's id and mnemonic (docs/paper-notes.md N73).
  std::vector<std::string> shared;
  for (const std::string& id : pose_ids) {
    if (arrow_ids.count(id) != 0) shared.push_back(id);
  }
  EXPECT_EQ(shared, (std::vector<std::string>{"P4", "P5", "P6", "P9"}));
  for (PoseMethod pita : {PoseMethod::p4, PoseMethod::p5, PoseMethod::p6, PoseMethod::p9}) {
    const MethodEntry& pose = entry_of(pita);
    const MethodEntry* arrow = find_method_entry(pose.id, is_method_of<Method>);
    ASSERT_NE(arrow, nullptr) << pose.id;
    EXPECT_EQ(arrow->mnemonic, pose.mnemonic) << pose.id;
    EXPECT_TRUE(info(pita).in_space) << pose.id;
  }
  EXPECT_EQ(arrows, all_methods().size());
  EXPECT_EQ(poses, all_pose_methods().size());
}

TEST(Methods, EveryNameResolvesInAnyCase) {
  for (const MethodEntry& entry : every_method()) {
    SCOPED_TRACE(std::string(entry.id));
    // Unfiltered, a name both kinds share is the arrow PITA's; filtered by
    // its own kind every entry answers to its names.
    const MethodFilter own = is_method_of<Method>(entry) ? is_method_of<Method> : is_method_of<PoseMethod>;
    for (const std::string& name : {std::string(entry.id), upper(std::string(entry.id)), std::string(entry.mnemonic)}) {
      const MethodEntry* found = find_method_entry(name, own);
      ASSERT_NE(found, nullptr) << name;
      EXPECT_EQ(found, &entry) << name;
    }
    // Filtered by its own kind it is found; by the other kind only when the
    // name is shared (P4, P5, P6, P9), and then as the other kind's entry.
    const bool arrow = is_method_of<Method>(entry);
    EXPECT_EQ(find_method_entry(entry.id, arrow ? is_method_of<Method> : is_method_of<PoseMethod>), &entry);
    const MethodEntry* other = find_method_entry(entry.id, arrow ? is_method_of<PoseMethod> : is_method_of<Method>);
    if (other != nullptr) {
      EXPECT_NE(is_method_of<Method>(*other), arrow);
    }
    EXPECT_EQ(find_method_of<Method>(entry.id) != nullptr, arrow || other != nullptr);
    EXPECT_EQ(find_method_of<PoseMethod>(entry.id) != nullptr, !arrow || other != nullptr);
  }
  EXPECT_EQ(find_method_entry("6")->method, AnyMethod(Method::P6));
  EXPECT_EQ(find_method_entry("5s")->method, AnyMethod(Method::P5S));
  EXPECT_EQ(find_method_entry("P6:La-LP")->method, AnyMethod(Method::P6));
  EXPECT_EQ(*find_method_of<Method>("lo-pe"), Method::P8);
  EXPECT_EQ(find_method_entry("POLYSAM")->method, AnyMethod(PoseMethod::poly_sam));
  EXPECT_EQ(*find_method_of<PoseMethod>("four-point-sam"), PoseMethod::four_point);
  // Unfiltered, a shared name is the arrow PITA (the registry's order); the
  // pose PITA answers to the same names, number included.
  EXPECT_EQ(find_method_entry("La-LP")->method, AnyMethod(Method::P6));
  EXPECT_EQ(*find_method_of<PoseMethod>("6"), PoseMethod::p6);
  EXPECT_EQ(*find_method_of<PoseMethod>("p9:ne-lp"), PoseMethod::p9);
  EXPECT_EQ(*find_method_of<PoseMethod>("BE-LP"), PoseMethod::p4);
  EXPECT_EQ(find_method_of<PoseMethod>("5s"), nullptr);  // P5S is of arrows only
  EXPECT_EQ(find_method_of<PoseMethod>("P8"), nullptr);
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
            "P4, P5, P6, P9, rARAP, ASAP, TSB, Alexa");
  // Unfiltered, the shared names are listed and suggested once each.
  const std::string every = method_ids();
  EXPECT_EQ(every.find("P6"), every.rfind("P6")) << every;
  EXPECT_EQ(unknown_method_reason("P66"), "unknown method \"P66\"; did you mean P6 (La-LP), P1 (Pa-Ca) or P2 (LS-Po)?");
}

TEST(Methods, LabelsAsMessagesNameThem) {
  EXPECT_EQ(method_label(entry_of(Method::P6)), "P6 (La-LP)");
  EXPECT_EQ(method_label(entry_of(Method::SMA)), "SMA");
  EXPECT_EQ(method_label(entry_of(PoseMethod::bezier_sam)), "bezier-SAM");
  EXPECT_EQ(method_label(entry_of(PoseMethod::p6)), "P6 (La-LP)");
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
