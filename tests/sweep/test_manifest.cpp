// The manifest (src/sweep/manifest.cpp): written and read back field for
// field, quoting included; file names; a foreign manifest is refused.
#include <exception>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include "sweep/manifest.hpp"

namespace pita::sweep {
namespace {

namespace fs = std::filesystem;

TEST(Manifest, RoundTripsQuotedFields) {
  Row a;
  a.index = 0;
  a.values = {"0.5", "P6"};
  a.status = "ok";
  a.outputs = {"s-0.scene.json", "s-0.svg"};
  a.hash = "0123456789abcdef";
  a.metrics[0] = "1.5";
  a.metrics[10] = "B.t";
  Row b = a;
  b.index = 7;
  b.values = {"a,b", "say \"hi\"\nthere"};
  b.status = "s.json: /keyframes/1/m: magnitude must be > 0 (got -1)";
  b.outputs.clear();
  b.metrics = {};
  const std::vector<std::string> pointers = {"/keyframes/1/t", "/method"};
  const fs::path file = fs::temp_directory_path() / "pita-test-manifest.csv";
  std::ofstream(file, std::ios::binary) << manifest_csv(pointers, std::vector<Row>{a, b});
  const auto rows = read_manifest(file, pointers);
  ASSERT_TRUE(rows.has_value());
  ASSERT_EQ(rows->size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Row& want = i == 0 ? a : b;
    const Row& got = (*rows)[i];
    EXPECT_EQ(got.index, want.index);
    EXPECT_EQ(got.values, want.values);
    EXPECT_EQ(got.status, want.status);
    EXPECT_EQ(got.outputs, want.outputs);
    EXPECT_EQ(got.hash, want.hash);
    EXPECT_EQ(got.metrics, want.metrics);
  }
  EXPECT_FALSE((*rows)[1].ok());
  // Another sweep's manifest (other pointers) is refused, not misread.
  EXPECT_THROW((void)read_manifest(file, {"/keyframes/0/t", "/method"}), std::runtime_error);
  EXPECT_FALSE(read_manifest(file.string() + ".none", pointers).has_value());
  fs::remove(file);
}

TEST(Manifest, ALastLineCutShortIsNotARow) {
  // What a killed sweep may leave at the end of its journal: the row's fields
  // all there but the last one cut, and no line break.
  Row a;
  a.index = 3;
  a.values = {"0.5"};
  a.status = "ok";
  a.hash = "0123456789abcdef";
  a.metrics[15] = "yes";
  std::string text;
  append_row(text, a);
  a.index = 4;
  std::string cut;
  append_row(cut, a);
  cut.resize(cut.size() - 2);  // "...,ye"
  const fs::path file = fs::temp_directory_path() / "pita-test-journal";
  std::ofstream(file, std::ios::binary) << text << cut;
  std::optional<ManifestReader> reader = ManifestReader::open(file, {"/keyframes/1/t"}, true);
  ASSERT_TRUE(reader.has_value());
  Row row;
  ASSERT_TRUE(reader->next(row));
  EXPECT_EQ(row.index, 3);
  EXPECT_EQ(row.metrics[15], "yes");
  EXPECT_FALSE(reader->next(row));
  fs::remove(file);
}

TEST(Manifest, NamesAreTheSceneAndTheIndex) {
  EXPECT_EQ(variant_file("fig01", 7, 1000, "svg"), "fig01-7.svg");
  EXPECT_EQ(variant_file("fig01", 999, 1000, "scene.json"), "fig01-999.scene.json");
  EXPECT_EQ(variant_file("x", 0, 1, "csv"), "x-0.csv");
  EXPECT_EQ(manifest_name(std::nullopt), "manifest.csv");
  EXPECT_EQ(manifest_name(std::pair{2, 5}), "manifest.2-of-5.csv");
}

// A manifest that exists but cannot be opened (here: no file descriptor
// left) is an error naming it; only a missing one is "no manifest", so that
// neither a resumed run nor --merge leaves its rows out without a word.
TEST(Manifest, OneThatCannotBeOpenedIsAnErrorNotAbsent) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pita-test-manifest-" + std::to_string(::getpid()) + ".csv");
  std::ofstream(path) << manifest_header({"/a"});
  EXPECT_FALSE(ManifestReader::open(path.string() + ".missing", {"/a"}).has_value());
  ASSERT_TRUE(ManifestReader::open(path, {"/a"}).has_value());
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &saved), 0);
  const int lowest_free = ::dup(0);
  ASSERT_GE(lowest_free, 0);
  ::close(lowest_free);
  rlimit none = saved;
  none.rlim_cur = static_cast<rlim_t>(lowest_free);  // the next open fails with EMFILE
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &none), 0);
  // Caught as it is, and looked at only once descriptors are back: UBSan's
  // check of a virtual call (e.what()) opens a pipe to probe memory.
  std::exception_ptr thrown;
  try {
    (void)ManifestReader::open(path, {"/a"});
  } catch (...) {
    thrown = std::current_exception();
  }
  ::setrlimit(RLIMIT_NOFILE, &saved);
  std::string message;
  try {
    if (thrown) std::rethrow_exception(thrown);
  } catch (const io::OutputError& e) {  // exit 3, never "no manifest"
    message = e.what();
  }
  EXPECT_NE(message.find(path.string() + ": cannot read (Too many open files)"), std::string::npos) << message;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace pita::sweep
