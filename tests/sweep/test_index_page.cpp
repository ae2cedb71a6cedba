// index.html's data files (src/sweep/index_page.cpp): rows-K.js holds the
// manifest's rows kIndexRowsPerFile at a time, as it prints them; column-C.js
// one column of every row, numbers as numbers (sorted as such), text as
// strings, empty as null; data files of a larger earlier run go; the page
// embeds no markup from the data. The page itself in Chromium:
// tests/sweep/test_index_page.py.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "sweep/index_page.hpp"
#include "sweep/index_script.hpp"

namespace pita::sweep {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The JSON array inside "pitaRows(K,[...]);" or "pitaColumn("C",[...]);".
nlohmann::json payload(const std::string& text, const std::string& head) {
  EXPECT_TRUE(text.starts_with(head)) << text.substr(0, 80);
  EXPECT_TRUE(text.ends_with("]);\n")) << text.substr(text.size() > 80 ? text.size() - 80 : 0);
  return nlohmann::json::parse(text.substr(head.size() - 1, text.size() - head.size() - 2));
}

class IndexPage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-index-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A manifest of `rows` variants over /method and a pointer that needs escaping.
  SheetInput write_manifest(std::int64_t rows) {
    const std::vector<std::string> pointers = {"/method", "/a</script>"};
    std::string manifest = manifest_header(pointers);
    for (std::int64_t i = 0; i < rows; ++i) {
      Row row;
      row.index = i;
      row.values = {i % 2 == 0 ? "P1" : "P6", std::to_string(i)};
      row.status = i % 3 == 2 ? "x.scene.json: /keyframes/1/m: magnitude must be > 0 (got -1)" : "ok";
      row.outputs = {fmt::format("v-{}.png", i), fmt::format("v {}.svg", i)};
      row.hash = "h";
      if (row.ok()) {
        row.metrics[0] = fmt::format("{}", 0.5 * static_cast<double>(i));
        row.metrics[6] = "1.5e-07";
        row.metrics[13] = "no";
      }
      append_row(manifest, row);
    }
    std::ofstream(dir_ / "manifest.csv") << manifest;
    SheetInput input;
    input.dir = dir_;
    input.name = "v";
    input.base_path = "base.json";
    input.pointers = pointers;
    input.axis_sizes = {2, static_cast<std::size_t>(rows)};
    input.variants = rows;
    input.figures = true;
    return input;
  }

  fs::path dir_;
};

TEST_F(IndexPage, RowsFilesHoldTheManifestsRowsAsPrinted) {
  const std::int64_t rows = kIndexRowsPerFile + 5;
  EXPECT_EQ(write_index_html(write_manifest(rows)), "");
  const nlohmann::json first = payload(read(dir_ / "index/rows-0.js"), "pitaRows(0,[");
  const nlohmann::json second = payload(read(dir_ / "index/rows-1.js"), "pitaRows(1,[");
  ASSERT_EQ(first.size(), static_cast<std::size_t>(kIndexRowsPerFile));
  ASSERT_EQ(second.size(), 5u);
  EXPECT_FALSE(fs::exists(dir_ / "index/rows-2.js"));
  // [index, status, thumbnail, full figure, /method, /a</script>, status, metrics...]
  const nlohmann::json& row = second[1];  // variant 1001: failed
  EXPECT_EQ(row[0], kIndexRowsPerFile + 1);
  EXPECT_EQ(row[1], "x.scene.json: /keyframes/1/m: magnitude must be > 0 (got -1)");
  EXPECT_EQ(row[2], fmt::format("v-{}.png", kIndexRowsPerFile + 1));
  EXPECT_EQ(row[3], fmt::format("v%20{}.svg", kIndexRowsPerFile + 1));  // a URL
  EXPECT_EQ(row[4], "P6");
  EXPECT_EQ(row[5], std::to_string(kIndexRowsPerFile + 1));
  EXPECT_EQ(first[1][7], "0.5");  // path_length_p as the manifest prints it
  EXPECT_EQ(first[1][13], "1.5e-07");
}

TEST_F(IndexPage, ColumnsHoldNumbersTextAndNullInManifestOrder) {
  const std::int64_t rows = 7;
  write_index_html(write_manifest(rows));
  const nlohmann::json method = payload(read(dir_ / "index/column-v0.js"), "pitaColumn(\"v0\",[");
  const nlohmann::json value = payload(read(dir_ / "index/column-v1.js"), "pitaColumn(\"v1\",[");
  const nlohmann::json length = payload(read(dir_ / "index/column-m0.js"), "pitaColumn(\"m0\",[");
  const nlohmann::json discrepancy = payload(read(dir_ / "index/column-m6.js"), "pitaColumn(\"m6\",[");
  const nlohmann::json pops = payload(read(dir_ / "index/column-m13.js"), "pitaColumn(\"m13\",[");
  ASSERT_EQ(method.size(), 7u);
  EXPECT_EQ(method[0], "P1");
  EXPECT_EQ(method[1], "P6");
  EXPECT_EQ(value[6], 6);  // a number: sorted as one
  EXPECT_EQ(length[4], 2.0);
  EXPECT_TRUE(length[2].is_null());  // a failed variant: no metric, sorted last
  EXPECT_EQ(discrepancy[0], 1.5e-07);
  EXPECT_EQ(pops[0], "no");
  EXPECT_TRUE(fs::exists(dir_ / "index/column-status.js"));
  for (std::size_t m = 0; m < kMetricColumns.size(); ++m) {
    EXPECT_TRUE(fs::exists(dir_ / fmt::format("index/column-m{}.js", m))) << m;
  }
}

TEST_F(IndexPage, ALargerEarlierRunsDataFilesAndTemporariesGo) {
  fs::create_directories(dir_ / "index");
  for (const char* stale : {"rows-3.js", "column-v7.js", ".rows-0.js.a1B2c3"})
    std::ofstream(dir_ / "index" / stale) << "x";
  std::ofstream(dir_ / "index/notes.txt") << "mine";
  write_index_html(write_manifest(3));
  EXPECT_TRUE(fs::exists(dir_ / "index/rows-0.js"));
  EXPECT_FALSE(fs::exists(dir_ / "index/rows-3.js"));
  EXPECT_FALSE(fs::exists(dir_ / "index/column-v7.js"));
  EXPECT_FALSE(fs::exists(dir_ / "index/.rows-0.js.a1B2c3"));
  EXPECT_TRUE(fs::exists(dir_ / "index/notes.txt"));  // not pita's: left alone
}

TEST_F(IndexPage, ThePageEmbedsNoMarkupFromTheData) {
  write_index_html(write_manifest(3));
  const std::string page = read(dir_ / "index.html");
  // The pointer "/a</script>" appears escaped in the text and in the page's data.
  EXPECT_NE(page.find("<code>/a&lt;/script&gt;</code>"), std::string::npos);
  EXPECT_NE(page.find(R"("/a\u003c/script>")"), std::string::npos);
  EXPECT_EQ(page.find("/a</script>"), std::string::npos);
  EXPECT_NE(page.find("3 of 3 variants (1 failed)"), std::string::npos);
  EXPECT_NE(page.find("\"count\":3"), std::string::npos);
}

TEST_F(IndexPage, ThePageEndsWithTheBuiltInScript) {
  write_index_html(write_manifest(3));
  const std::string page = read(dir_ / "index.html");
  EXPECT_TRUE(page.ends_with("<script>\n" + std::string(index_script()) + "</script>\n</body></html>\n"));
}

}  // namespace
}  // namespace pita::sweep
