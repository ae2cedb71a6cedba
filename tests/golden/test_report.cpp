// The report of `pita check --report DIR` (src/golden/report.cpp): one
// index.html listing every scene, and the expected, actual and diff images
// (and SVGs) of the scenes that differ, written as given.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "golden/report.hpp"

namespace pita::golden {
namespace {

namespace fs = std::filesystem;

class Report : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-report-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  fs::path dir_;
};

FileCheck file(FileKind kind, Verdict verdict, std::string expected, std::string actual, std::string diff = "") {
  return FileCheck{kind,
                   "golden/x/x" + std::string(suffix(kind)),
                   verdict,
                   "detail <" + std::string(suffix(kind)) + ">",
                   std::move(expected),
                   std::move(actual),
                   std::move(diff)};
}

TEST_F(Report, ListsEverySceneAndWritesTheImagesOfThoseThatDiffer) {
  ReportEntry same{
      SceneCheck{"scenes/same.json",
                 "same",
                 {file(FileKind::data, Verdict::match, "d", "d"), file(FileKind::svg, Verdict::match, "s", "s"),
                  file(FileKind::png, Verdict::match, "P", "P")},
                 {},
                 {}},
      ""};
  ReportEntry moved{SceneCheck{"scenes/moved.json",
                               "moved",
                               {file(FileKind::data, Verdict::differs, "d1", "d2"),
                                file(FileKind::svg, Verdict::differs, "<svg>1</svg>", "<svg>2</svg>"),
                                file(FileKind::png, Verdict::differs, "EXPECTED", "ACTUAL", "DIFF")},
                               {},
                               {}},
                    ""};
  ReportEntry bad{SceneCheck{"scenes/bad.json", "bad<&>", {}, {}, {}}, "bad.json: /method: unknown \"P66\""};
  write_report(dir_, {same, moved, bad}, {});

  const std::string html = read("index.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<p>3 scene(s) checked, 2 differ or could not be checked.</p>"), std::string::npos) << html;
  EXPECT_NE(html.find("<tr><td><a href=\"#same\">same</a></td><td class=\"match\">match</td></tr>"), std::string::npos)
      << html;
  EXPECT_NE(html.find("<tr><td><a href=\"#moved\">moved</a></td><td class=\"DIFFERS\">DIFFERS</td></tr>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td class=\"ERROR\">ERROR</td>"), std::string::npos) << html;
  // Names, paths and messages are escaped.
  EXPECT_NE(html.find("bad&lt;&amp;&gt;"), std::string::npos) << html;
  EXPECT_NE(html.find("<p class=\"ERROR\">bad.json: /method: unknown &quot;P66&quot;</p>"), std::string::npos) << html;
  EXPECT_NE(html.find("detail &lt;.svg&gt;"), std::string::npos) << html;
  EXPECT_EQ(html.find("bad<&>"), std::string::npos);
  EXPECT_EQ(html.substr(html.size() - 15), "</body></html>\n");

  // The differing scene's files, byte for byte; nothing for the others.
  EXPECT_EQ(read("moved.expected.png"), "EXPECTED");
  EXPECT_EQ(read("moved.actual.png"), "ACTUAL");
  EXPECT_EQ(read("moved.diff.png"), "DIFF");
  EXPECT_EQ(read("moved.expected.svg"), "<svg>1</svg>");
  EXPECT_EQ(read("moved.actual.svg"), "<svg>2</svg>");
  EXPECT_NE(html.find("<img src=\"moved.diff.png\""), std::string::npos) << html;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(names.size(), 6u);  // index.html and the five files of "moved"
}

// A report file that would replace an input of the check (here an image a
// scene draws, named as the report names the actual PNG) is refused before
// anything is written.
TEST_F(Report, NeverReplacesAnInput) {
  ReportEntry moved{
      SceneCheck{
          "scenes/moved.json", "moved", {file(FileKind::png, Verdict::differs, "EXPECTED", "ACTUAL", "DIFF")}, {}, {}},
      ""};
  fs::create_directories(dir_);
  std::ofstream(dir_ / "moved.actual.png") << "AN INPUT";
  try {
    write_report(dir_, {moved}, {dir_ / "moved.actual.png"});
    ADD_FAILURE() << "the report replaced an input";
  } catch (const GoldenError& error) {
    EXPECT_NE(std::string(error.what()).find("moved.actual.png, an input of this check"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(read("moved.actual.png"), "AN INPUT");
  EXPECT_FALSE(fs::exists(dir_ / "index.html"));
  EXPECT_FALSE(fs::exists(dir_ / "moved.expected.png"));
}

// A scene named like a URL scheme ("javascript:alert(1)") writes files of
// that name: the report links to them as files, never as a script.
TEST_F(Report, LinksOnlyToFilesWhateverTheSceneIsNamed) {
  ReportEntry named{SceneCheck{"scenes/javascript:alert(1).json",
                               "javascript:alert(1)",
                               {file(FileKind::png, Verdict::differs, "EXPECTED", "ACTUAL", "DIFF")},
                               {},
                               {}},
                    ""};
  write_report(dir_, {named}, {});
  const std::string html = read("index.html");
  EXPECT_EQ(read("javascript:alert(1).diff.png"), "DIFF");
  EXPECT_NE(html.find("<a href=\"javascript%3Aalert%281%29.diff.png\"><img src=\"javascript%3Aalert%281%29.diff.png\""),
            std::string::npos)
      << html;
  EXPECT_EQ(html.find("href=\"javascript:"), std::string::npos) << html;
  EXPECT_EQ(html.find("src=\"javascript:"), std::string::npos) << html;
}

// Every claim is listed, held or not; a failed one marks its scene though
// its goldens match, and no image is written for it.
TEST_F(Report, ListsEveryClaim) {
  ReportEntry claimed{
      SceneCheck{"scenes/c.json",
                 "c",
                 {file(FileKind::data, Verdict::match, "d", "d"), file(FileKind::png, Verdict::match, "P", "P")},
                 {{"/claims/0", "P8 is <soft>", true, "scale-step of panel 3 = 0.06, below 0.24"},
                  {"/claims/1", "P2 turns fast", false, "turn-step of panel 1 = 0.22, not above 0.3"}},
                 {}},
      ""};
  write_report(dir_, {claimed}, {});
  const std::string html = read("index.html");
  EXPECT_NE(html.find("<p>1 scene(s) checked, 1 differ or could not be checked.</p>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td class=\"CLAIM FAILED\">CLAIM FAILED</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<tr><td>/claims/0</td><td>P8 is &lt;soft&gt;</td><td class=\"match\">holds</td>"
                      "<td>scale-step of panel 3 = 0.06, below 0.24</td></tr>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td class=\"DIFFERS\">FAILS</td><td>turn-step of panel 1 = 0.22, not above 0.3</td>"),
            std::string::npos)
      << html;
  EXPECT_FALSE(fs::exists(dir_ / "c.actual.png"));  // the figure matches its golden
}

// Every finding of the lint is listed, accepted or not; one not accepted
// marks its scene though its goldens match and its claims hold.
TEST_F(Report, ListsEveryLintFinding) {
  lint::Report findings;
  findings.findings.push_back(
      {"text-over-data", "/layers/3", "the label \"<q>\" lies over /layers/0", "move it", "", ""});
  findings.findings.push_back({"same-color", "/layers/2", "items 1 and 2 are both #d08000", "give it colours",
                               "the inner control poses", "/lint/allow/0"});
  ReportEntry linted{SceneCheck{"scenes/l.json", "l", {file(FileKind::data, Verdict::match, "d", "d")}, {}, findings},
                     ""};
  write_report(dir_, {linted}, {});
  const std::string html = read("index.html");
  EXPECT_NE(html.find("<p>1 scene(s) checked, 1 differ or could not be checked.</p>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td class=\"LINT\">LINT</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<tr><td>text-over-data</td><td>/layers/3</td><td class=\"DIFFERS\">FINDING</td>"
                      "<td>the label &quot;&lt;q&gt;&quot; lies over /layers/0; fix: move it</td></tr>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td class=\"match\">accepted: the inner control poses</td>"), std::string::npos) << html;
}

// A new scene: no golden, so no expected image; the actual one is written.
TEST_F(Report, MissingGoldenHasNoExpectedImage) {
  ReportEntry fresh{
      SceneCheck{"scenes/new.json",
                 "new",
                 {file(FileKind::data, Verdict::missing, "", "d"), file(FileKind::svg, Verdict::missing, "", "<svg/>"),
                  file(FileKind::png, Verdict::missing, "", "ACTUAL")},
                 {},
                 {}},
      ""};
  write_report(dir_, {fresh}, {});
  const std::string html = read("index.html");
  EXPECT_NE(html.find("<td><em>none</em><br>expected (golden)</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td><em>none</em><br>differing pixels in red</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td class=\"MISSING\">MISSING</td>"), std::string::npos) << html;
  EXPECT_FALSE(fs::exists(dir_ / "new.expected.png"));
  EXPECT_EQ(read("new.actual.png"), "ACTUAL");
  EXPECT_EQ(read("new.actual.svg"), "<svg/>");
  EXPECT_FALSE(fs::exists(dir_ / "new.expected.svg"));
}

}  // namespace
}  // namespace pita::golden
