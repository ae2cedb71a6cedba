#include "golden/report.hpp"

#include <fmt/format.h>

#include "io/input_file.hpp"
#include "io/output_file.hpp"
#include "text/html.hpp"

namespace pita::golden {

namespace fs = std::filesystem;
using text::html_escaped;

namespace {

std::string_view kind_name(FileKind kind) {
  switch (kind) {
    case FileKind::data:
      return "numbers";
    case FileKind::svg:
      return "SVG geometry";
    case FileKind::png:
      return "PNG pixels";
  }
  return "";
}

std::string_view verdict_name(Verdict v) {
  switch (v) {
    case Verdict::match:
      return "match";
    case Verdict::differs:
      return "DIFFERS";
    case Verdict::missing:
      return "MISSING";
  }
  return "";
}

// An image cell: the file if it was written, else a note.
std::string image_cell(const std::string& file, const std::string& caption) {
  if (file.empty()) return "<td><em>none</em><br>" + html_escaped(caption) + "</td>";
  // The file's name as a URL: a scene named "javascript:..." gives files
  // that must not read as a script (text::relative_url).
  return fmt::format("<td><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><br>{1}</td>", text::relative_url(file),
                     html_escaped(caption));
}

// The summary table: one row per scene, its result.
std::string summary_table(const std::vector<ReportEntry>& entries) {
  std::size_t bad = 0;
  for (const ReportEntry& e : entries) {
    bad += (!e.error.empty() || !e.check.passes()) ? 1 : 0;
  }
  std::string html =
      fmt::format("<p>{} scene(s) checked, {} differ or could not be checked.</p>\n", entries.size(), bad);
  html += "<table><tr><th>scene</th><th>result</th></tr>\n";
  for (const ReportEntry& e : entries) {
    const std::string result = !e.error.empty()         ? "ERROR"
                               : !e.check.matches()     ? "DIFFERS"
                               : !e.check.claims_hold() ? "CLAIM FAILED"
                               : !e.check.legible()     ? "LINT"
                                                        : "match";
    html += fmt::format("<tr><td><a href=\"#{0}\">{0}</a></td><td class=\"{1}\">{1}</td></tr>\n",
                        html_escaped(e.check.name), result);
  }
  html += "</table>\n";
  return html;
}

// A scene's outputs against its goldens, one row each.
std::string files_table(const ReportEntry& e) {
  std::string html = "<table><tr><th>output</th><th>golden</th><th>result</th><th>details</th></tr>\n";
  for (const FileCheck& f : e.check.files) {
    html += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"{}\">{}</td><td>{}</td></tr>\n", kind_name(f.kind),
                        html_escaped(f.golden.string()), verdict_name(f.verdict), verdict_name(f.verdict),
                        html_escaped(f.detail));
  }
  html += "</table>\n";
  return html;
}

// Every claim, held or not (docs/reference/check.md "Claims"); "" when none.
std::string claims_table(const ReportEntry& e) {
  if (e.check.claims.empty()) return "";
  std::string html = "<table><tr><th>claim</th><th>says</th><th>result</th><th>measured</th></tr>\n";
  for (const analysis::ClaimOutcome& c : e.check.claims) {
    const std::string_view held = c.held ? "match" : "DIFFERS";
    html += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"{}\">{}</td><td>{}</td></tr>\n", html_escaped(c.pointer),
                        html_escaped(c.says), held, c.held ? "holds" : "FAILS", html_escaped(c.measured));
  }
  html += "</table>\n";
  return html;
}

// Every finding of the lint, accepted or not (docs/reference/lint.md "Lint"); "" when none.
std::string lint_table(const ReportEntry& e) {
  if (e.check.lint.findings.empty()) return "";
  std::string html = "<table><tr><th>lint</th><th>pointer</th><th>result</th><th>finding</th></tr>\n";
  for (const lint::Finding& f : e.check.lint.findings) {
    const bool accepted = !f.reason.empty();
    html += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"{}\">{}</td><td>{}</td></tr>\n", html_escaped(f.check),
                        html_escaped(f.pointer), accepted ? "match" : "DIFFERS",
                        accepted ? "accepted: " + html_escaped(f.reason) : std::string("FINDING"),
                        html_escaped(f.fix.empty() ? f.message : f.message + "; fix: " + f.fix));
  }
  html += "</table>\n";
  return html;
}

// The images of a scene that differs, written into DIR: each PNG's expected,
// actual and diff (shown side by side), each differing SVG's expected and actual.
std::string differing_images(const fs::path& dir, const ReportEntry& e) {
  std::string html;
  for (const FileCheck& f : e.check.files) {
    if (f.kind != FileKind::png) continue;
    std::string expected, actual, diff;
    if (!f.expected.empty()) {
      expected = e.check.name + ".expected.png";
      io::write_file_atomically(dir / expected, f.expected);
    }
    actual = e.check.name + ".actual.png";
    io::write_file_atomically(dir / actual, f.actual);
    if (!f.diff_png.empty() && f.verdict != Verdict::match) {
      diff = e.check.name + ".diff.png";
      io::write_file_atomically(dir / diff, f.diff_png);
    }
    html += "<table><tr>" + image_cell(expected, "expected (golden)") + image_cell(actual, "actual") +
            image_cell(diff, "differing pixels in red") + "</tr></table>\n";
  }
  for (const FileCheck& f : e.check.files) {
    if (f.kind != FileKind::svg || f.verdict == Verdict::match) continue;
    if (!f.expected.empty()) io::write_file_atomically(dir / (e.check.name + ".expected.svg"), f.expected);
    io::write_file_atomically(dir / (e.check.name + ".actual.svg"), f.actual);
  }
  return html;
}

// One scene's section: its error, or its tables and, when it differs, its images.
std::string scene_section(const fs::path& dir, const ReportEntry& e) {
  std::string html = fmt::format("<h2 id=\"{0}\">{0}</h2>\n<p>{1}</p>\n", html_escaped(e.check.name),
                                 html_escaped(e.check.scene_path));
  if (!e.error.empty()) return html + "<p class=\"ERROR\">" + html_escaped(e.error) + "</p>\n";
  html += files_table(e);
  html += claims_table(e);
  html += lint_table(e);
  if (!e.check.matches()) html += differing_images(dir, e);
  return html;
}

// Refuses a report whose files would replace an input of the check.
void refuse_replacing_inputs(const fs::path& dir, const std::vector<ReportEntry>& entries,
                             const std::vector<fs::path>& inputs) {
  std::vector<fs::path> files{dir / "index.html"};
  for (const ReportEntry& e : entries) {
    if (!e.error.empty() || e.check.matches()) continue;
    for (const char* suffix : {".expected.png", ".actual.png", ".diff.png", ".expected.svg", ".actual.svg"}) {
      files.push_back(dir / (e.check.name + suffix));
    }
  }
  for (const fs::path& file : files) {
    for (const fs::path& input : inputs) {
      if (!io::same_file(file, input)) continue;
      throw GoldenError(
          fmt::format("the report's {} would replace {}, an input of this check: write the report "
                      "into another folder",
                      file.string(), input.string()));
    }
  }
}

}  // namespace

void write_report(const fs::path& dir, const std::vector<ReportEntry>& entries, const std::vector<fs::path>& inputs) {
  refuse_replacing_inputs(dir, entries, inputs);
  fs::create_directories(dir);
  std::string html = R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pita check report</title>
<style>
body { font-family: sans-serif; margin: 2em; }
table { border-collapse: collapse; margin-bottom: 1em; }
td, th { border: 1px solid #ccc; padding: 4px 8px; vertical-align: top; text-align: left; }
img { max-width: 420px; border: 1px solid #999; }
.match { color: #070; } .DIFFERS, .MISSING, .ERROR, .CLAIM, .LINT { color: #b00; font-weight: bold; }
</style></head><body>
<h1>pita check</h1>
)";
  html += summary_table(entries);
  for (const ReportEntry& e : entries) html += scene_section(dir, e);
  html += "</body></html>\n";
  io::write_file_atomically(dir / "index.html", html);
}

}  // namespace pita::golden
