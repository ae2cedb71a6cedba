#include "sweep/index_page.hpp"

#include <cctype>
#include <filesystem>
#include <memory>
#include <optional>
#include <regex>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "io/output_file.hpp"
#include "sweep/folder.hpp"
#include "sweep/index_script.hpp"
#include "sweep/manifest.hpp"
#include "text/html.hpp"

namespace pita::sweep {

namespace {

namespace fs = std::filesystem;

// Data files written in one pass over the manifest, at most (each holds a
// buffer and a slot of io::InFlightReservation); more columns take more passes.
constexpr std::size_t kColumnsPerPass = 16;
// A column file's write buffer: small, since kColumnsPerPass are open at once.
constexpr std::size_t kColumnBuffer = std::size_t{64} << 10;

// The first output of the row with one of `extensions`, in that order of preference.
std::string output_with(const Row& row, std::initializer_list<std::string_view> extensions) {
  for (const std::string_view ext : extensions) {
    for (const std::string& f : row.outputs) {
      const std::size_t dot = f.rfind('.');
      if (dot != std::string::npos && std::string_view(f).substr(dot + 1) == ext && !f.ends_with(".scene.json")) {
        return f;
      }
    }
  }
  return "";
}

// A manifest field as a JavaScript literal: a number as printed when it is a
// JSON number (sorted as a number), else a string; null when empty (sorted last).
void append_value(std::string& out, const std::string& text) {
  static const std::regex kNumber(R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  if (text.empty()) {
    out += "null";
  } else if (text.size() < 40 && std::regex_match(text, kNumber)) {
    out += text;
  } else {
    out += nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
}

// The sortable columns: key (the data file's name) and heading.
struct Column {
  std::string key;
  std::string name;
};

std::vector<Column> columns_of(const SheetInput& input) {
  std::vector<Column> columns;
  for (std::size_t k = 0; k < input.pointers.size(); ++k) columns.push_back({fmt::format("v{}", k), input.pointers[k]});
  columns.push_back({"status", "status"});
  for (std::size_t m = 0; m < kMetricColumns.size(); ++m) {
    columns.push_back({fmt::format("m{}", m), std::string(kMetricColumns[m])});
  }
  return columns;
}

const std::string& field_of(const Row& row, const Column& column) {
  if (column.key == "status") return row.status;
  const std::size_t k = std::stoul(column.key.substr(1));
  return column.key[0] == 'v' ? row.values.at(k) : row.metrics.at(k);
}

// The data files of a larger earlier run, and temporaries a killed run left in index/.
void remove_stale(const fs::path& dir, std::int64_t row_files, const std::vector<Column>& columns) {
  static const std::regex kRows(R"(rows-([0-9]{1,12})\.js)"), kColumn(R"(column-(.*)\.js)");
  remove_stale_temporaries(dir, [](const std::string&) { return true; });
  std::error_code error;
  std::vector<fs::path> stale;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, kRows)) {
      if (std::stoll(m[1].str()) >= row_files) stale.push_back(entry.path());
    } else if (std::regex_match(name, m, kColumn)) {
      bool known = false;
      for (const Column& c : columns) known = known || c.key == m[1].str();
      if (!known) stale.push_back(entry.path());
    }
  }
  for (const fs::path& p : stale) fs::remove(p, error);
}

// What the pass over the manifest counted: its rows, and those that failed.
struct RowCounts {
  std::int64_t rows = 0;
  std::int64_t failed = 0;
};

// DIR/index/rows-K.js, written one after the other as the rows come: each
// "pitaRows(K,[...]);" with kIndexRowsPerFile rows, a row being [index,
// status, thumbnail, full figure, each column as the manifest prints it].
class RowsFiles {
 public:
  RowsFiles(const fs::path& data, const std::vector<Column>& columns) : data_(data), columns_(columns) {}

  // The row at `position` of the manifest.
  void add(std::int64_t position, const Row& row) {
    const std::int64_t file = position / kIndexRowsPerFile;
    if (position % kIndexRowsPerFile == 0) {
      finish();
      file_.emplace(data_ / fmt::format("rows-{}.js", file), kColumnBuffer);
      file_->write(fmt::format("pitaRows({},[\n", file));
    }
    text_.clear();
    text_ += fmt::format("{}[{},", position % kIndexRowsPerFile == 0 ? "" : ",\n", row.index);
    append_value(text_, row.status);
    const std::string thumb = output_with(row, {"png", "svg"}), full = output_with(row, {"svg", "png", "pdf"});
    text_ += fmt::format(",\"{}\",\"{}\"", text::relative_url(thumb), text::relative_url(full));
    for (const Column& c : columns_) {  // shown as the manifest prints them
      text_ += ',';
      text_ += nlohmann::json(field_of(row, c)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    text_ += ']';
    file_->write(text_);
  }

  // Commits the file being written, if any.
  void finish() {
    if (!file_) return;
    file_->write("]);\n");
    file_->commit();
    file_.reset();
  }

 private:
  fs::path data_;
  const std::vector<Column>& columns_;
  std::optional<io::StreamingOutput> file_;
  std::string text_;
};

// One pass over the manifest: writes DIR/index/column-C.js for the columns
// [from, to) ("pitaColumn("C",[...]);", a value per row) and, in the first
// pass (from 0), the rows files, and counts the rows.
RowCounts write_pass(const SheetInput& input, const fs::path& data, const std::vector<Column>& columns,
                     std::size_t from, std::size_t to) {
  std::vector<std::unique_ptr<io::StreamingOutput>> outs;
  for (std::size_t c = from; c < to; ++c) {
    outs.push_back(
        std::make_unique<io::StreamingOutput>(data / fmt::format("column-{}.js", columns[c].key), kColumnBuffer));
    outs.back()->write(fmt::format("pitaColumn(\"{}\",[", columns[c].key));
  }
  RowCounts counts;
  RowsFiles rows_files(data, columns);
  std::int64_t position = 0;
  std::string text;
  std::optional<ManifestReader> reader = ManifestReader::open(input.dir / "manifest.csv", input.pointers);
  Row row;
  while (reader && reader->next(row)) {
    for (std::size_t c = from; c < to; ++c) {
      text.clear();
      if (position > 0) text += ',';
      append_value(text, field_of(row, columns[c]));
      outs[c - from]->write(text);
    }
    if (from == 0) {
      ++counts.rows;
      counts.failed += row.ok() ? 0 : 1;
      rows_files.add(position, row);
    }
    ++position;
  }
  rows_files.finish();
  for (auto& out : outs) {
    out->write("]);\n");
    out->commit();
  }
  return counts;
}

// DIR/index/: the rows and column files, in passes of kColumnsPerPass
// columns; the data files of a larger earlier run removed.
RowCounts write_data_files(const SheetInput& input, const std::vector<Column>& columns) {
  const fs::path data = input.dir / "index";
  std::error_code error;
  check_own_subfolder(data);  // claim_folder checked it before the run; --merge comes here alone
  fs::create_directories(data, error);
  if (error) {
    throw io::OutputError(fmt::format("{}: cannot create the folder ({})", data.string(), error.message()));
  }
  RowCounts counts;
  for (std::size_t from = 0; from < columns.size(); from += kColumnsPerPass) {
    const RowCounts pass = write_pass(input, data, columns, from, std::min(columns.size(), from + kColumnsPerPass));
    if (from == 0) counts = pass;
  }
  remove_stale(data, (counts.rows + kIndexRowsPerFile - 1) / kIndexRowsPerFile, columns);
  return counts;
}

// The page's `sweep` object (rows, rows per file, figures, columns) as the
// text of a <script>: every "<" as \u003c (no "</script>", no "<!--" can
// end or bend it).
std::string sweep_object(const SheetInput& input, const std::vector<Column>& columns, std::int64_t count) {
  nlohmann::json meta = {{"count", count},
                         {"perFile", kIndexRowsPerFile},
                         {"figures", input.figures},
                         {"columns", nlohmann::json::array()}};
  for (const Column& c : columns) meta["columns"].push_back({{"key", c.key}, {"name", c.name}});
  std::string meta_text;
  for (const char c : meta.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)) {
    meta_text += c == '<' ? std::string_view("\\u003c") : std::string_view(&c, 1);
  }
  return meta_text;
}

// The page down to its table: the title, what was swept, the controls.
std::string page_top(const SheetInput& input, const RowCounts& counts) {
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>pita sweep: {0}</title>\n"
      "<style>body{{font-family:sans-serif;margin:1em}} table{{border-collapse:collapse;font-size:13px}} "
      "th,td{{border:1px solid #ccc;padding:2px 6px;text-align:right;white-space:nowrap}} "
      "th{{background:#eee;position:sticky;top:0}} th[title]{{cursor:pointer}} "
      "td.text{{text-align:left;white-space:normal;max-width:30em;word-break:break-all}} "
      "tr.failed td{{background:#fee}} "
      "td img{{height:80px;width:auto;background:#fff;display:block}} #page{{width:6em}}</style></head>\n"
      "<body>\n<h1>pita sweep of {0}</h1>\n",
      text::html_escaped(input.name));
  out += fmt::format("<p>{} of {} variants ({} failed) of <code>{}</code>; the values at ", counts.rows, input.variants,
                     counts.failed, text::html_escaped(input.base_path));
  for (std::size_t k = 0; k < input.pointers.size(); ++k) {
    out += fmt::format("{}<code>{}</code>", k == 0 ? "" : ", ", text::html_escaped(input.pointers[k]));
  }
  out += ". Every row is in <a href=\"manifest.csv\">manifest.csv</a>; click a heading to sort.</p>\n";
  out +=
      "<p><label>Sort by <select id=\"sort\"><option value=\"index\">index</option></select></label> "
      "<select id=\"order\"><option value=\"asc\">ascending</option><option value=\"desc\">descending</option>"
      "</select> <button id=\"first\">« first</button> <button id=\"prev\">‹ previous</button> "
      "<label>page <input id=\"page\" type=\"number\" min=\"1\" value=\"1\"></label> <span id=\"pages\"></span> "
      "<button id=\"next\">next ›</button> <button id=\"last\">last »</button> "
      "<label>rows <select id=\"size\"><option>50</option><option selected>100</option><option>500</option>"
      "</select></label> <span id=\"status\" role=\"status\"></span></p>\n";
  return out;
}

}  // namespace

std::string write_index_html(const SheetInput& input) {
  const std::vector<Column> columns = columns_of(input);
  const RowCounts counts = write_data_files(input, columns);
  std::string out = page_top(input, counts);
  out += "<table><thead><tr id=\"head\"></tr></thead><tbody id=\"rows\"></tbody></table>\n";
  out += fmt::format("<script>const sweep = {};</script>\n", sweep_object(input, columns, counts.rows));
  out += "<script>\n";
  out += index_script();
  out += "</script>\n";
  out += "</body></html>\n";
  io::write_file_atomically(input.dir / "index.html", out);
  return "";
}

}  // namespace pita::sweep
