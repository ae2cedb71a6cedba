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

// A file name as a relative URL: percent-encoded but for unreserved characters.
std::string url(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += c;
    } else {
      out += fmt::format("%{:02X}", u);
    }
  }
  return out;
}

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

// The page's script: the table, its pages and sorting, the data files loaded
// with <script> elements as needed. Text is set as text (no markup from data).
constexpr std::string_view kScript = R"JS(<script>
"use strict";
const $ = id => document.getElementById(id);
const arrived = new Map(), files = new Map(), columns = new Map();
window.pitaRows = (k, rows) => arrived.set(k, rows);
window.pitaColumn = (key, values) => columns.set(key, values);
let order = null, page = 0, shown = 0, sorted = 0;
const say = text => { $("status").textContent = text; };
const nameOf = key => key === "index" ? "index" : sweep.columns.find(c => c.key === key).name;
function load(src) {
  return new Promise((resolve, reject) => {
    const s = document.createElement("script");
    s.src = src;
    s.onload = () => { s.remove(); resolve(); };
    s.onerror = () => { s.remove(); reject(new Error("cannot load " + src + " (is the index/ folder beside index.html?)")); };
    document.head.appendChild(s);
  });
}
// The rows of index/rows-K.js; the last 64 files used are kept (a Map in order of use).
async function rowsFile(k) {
  let rows = files.get(k);
  if (rows) {
    files.delete(k);
  } else {
    await load(`index/rows-${k}.js`);
    rows = arrived.get(k);
    arrived.delete(k);
  }
  files.set(k, rows);
  while (files.size > 64) files.delete(files.keys().next().value);
  return rows;
}
const pageRows = () => Number($("size").value);
const pages = () => Math.max(1, Math.ceil(sweep.count / pageRows()));
function compare(values, desc) {
  return (a, b) => {
    const x = values[a], y = values[b];
    if (x === null || y === null) return (x === null) - (y === null) || a - b;
    const c = typeof x === "number" && typeof y === "number" ? x - y : (String(x) < String(y) ? -1 : String(x) > String(y) ? 1 : 0);
    return (desc ? -c : c) || a - b;
  };
}
// The order of the rows for the menus' column and direction; a later call wins.
async function sortBy() {
  const ticket = ++sorted, key = $("sort").value, desc = $("order").value === "desc";
  if (key === "index") {
    order = desc ? Uint32Array.from({length: sweep.count}, (_, i) => sweep.count - 1 - i) : null;
    return;
  }
  let values = columns.get(key);
  if (!values) {
    say(`loading the column ${nameOf(key)}…`);
    await load(`index/column-${key}.js`);
    values = columns.get(key);
    for (const other of [...columns.keys()]) if (other !== key) columns.delete(other);
  }
  say(`sorting ${sweep.count} rows…`);
  await new Promise(r => setTimeout(r));
  if (ticket !== sorted) return;
  const positions = new Uint32Array(sweep.count);
  for (let i = 0; i < positions.length; ++i) positions[i] = i;
  order = positions.sort(compare(values, desc));
}
function cell(tr, text, className) {
  const td = tr.insertCell();
  td.textContent = text ?? "";
  if (className) td.className = className;
  return td;
}
function rowElement(row) {
  const [index, status, thumb, full] = row;
  const tr = document.createElement("tr");
  tr.className = status === "ok" ? "ok" : "failed";
  tr.dataset.index = index;
  cell(tr, `#${index}`);
  if (sweep.figures) {
    const td = cell(tr, "");
    if (thumb || full) {
      const a = document.createElement("a");
      a.href = full || thumb;
      if (thumb) {
        const img = document.createElement("img");
        img.loading = "lazy"; img.src = thumb; img.alt = `variant ${index}`;
        a.appendChild(img);
      } else {
        a.textContent = "figure";
      }
      td.appendChild(a);
    }
  }
  sweep.columns.forEach((c, i) => cell(tr, row[4 + i], c.key === "status" || c.key.startsWith("v") ? "text" : ""));
  return tr;
}
async function show() {
  const ticket = ++shown, size = pageRows();
  document.body.dataset.busy = "yes";
  page = Math.min(Math.max(page, 0), pages() - 1);
  const first = page * size, last = Math.min(sweep.count, first + size);
  const positions = [];
  for (let i = first; i < last; ++i) positions.push(order ? order[i] : i);
  const needed = [...new Set(positions.map(p => Math.floor(p / sweep.perFile)))];
  if (needed.some(k => !files.has(k))) say("loading…");
  const got = new Map(await Promise.all(needed.map(async k => [k, await rowsFile(k)])));
  if (ticket !== shown) return;
  const body = document.createElement("tbody");
  body.id = "rows";
  for (const p of positions) body.appendChild(rowElement(got.get(Math.floor(p / sweep.perFile))[p % sweep.perFile]));
  $("rows").replaceWith(body);
  $("page").value = page + 1;
  $("page").max = pages();
  $("pages").textContent = `of ${pages()} (rows ${last > first ? first + 1 : 0}–${last} of ${sweep.count})`;
  $("first").disabled = $("prev").disabled = page === 0;
  $("next").disabled = $("last").disabled = page >= pages() - 1;
  const wanted = new URLSearchParams({sort: nameOf($("sort").value), order: $("order").value, page: page + 1, rows: size});
  history.replaceState(null, "", "#" + wanted);
  say("");
  document.body.dataset.busy = "";
  document.body.dataset.shown = wanted.toString();
}
async function resort() {
  page = 0;
  const ticket = sorted + 1;
  await sortBy();
  if (ticket === sorted) await show();  // else a later sort shows its own
}
const run = action => action().catch(e => { say(e.message); document.body.dataset.busy = ""; });
function start() {
  const head = $("head");
  const th = (text, key) => {
    const h = document.createElement("th");
    h.textContent = text;
    if (key) {
      h.title = `sort by ${text}`;
      h.onclick = () => {
        if ($("sort").value === key) $("order").value = $("order").value === "asc" ? "desc" : "asc";
        else { $("sort").value = key; $("order").value = "asc"; }
        run(resort);
      };
    }
    head.appendChild(h);
  };
  th("#", "index");
  if (sweep.figures) th("figure");
  for (const c of sweep.columns) {
    th(c.name, c.key);
    const o = document.createElement("option");
    o.value = c.key; o.textContent = c.name;
    $("sort").appendChild(o);
  }
  // The address names the sort, the order, the page and its rows: #sort=NAME&order=desc&page=3&rows=100.
  const follow = () => {
    const wanted = new URLSearchParams(location.hash.slice(1));
    const option = Array.from($("sort").options).find(o => o.textContent === wanted.get("sort"));
    $("sort").value = option ? option.value : "index";
    $("order").value = wanted.get("order") === "desc" ? "desc" : "asc";
    $("size").value = ["50", "100", "500"].includes(wanted.get("rows")) ? wanted.get("rows") : "100";
    page = Math.max(0, (Number(wanted.get("page")) || 1) - 1);
  };
  follow();
  window.addEventListener("hashchange", () => { follow(); run(async () => { await sortBy(); await show(); }); });
  $("sort").onchange = $("order").onchange = () => run(resort);
  $("size").onchange = () => { page = 0; run(show); };
  $("first").onclick = () => { page = 0; run(show); };
  $("prev").onclick = () => { page -= 1; run(show); };
  $("next").onclick = () => { page += 1; run(show); };
  $("last").onclick = () => { page = pages() - 1; run(show); };
  $("page").onchange = () => { page = (Math.floor(Number($("page").value)) || 1) - 1; run(show); };
  run(async () => { await sortBy(); await show(); });
}
start();
</script>
)JS";

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

}  // namespace

std::string write_index_html(const SheetInput& input) {
  const fs::path data = input.dir / "index";
  std::error_code error;
  fs::create_directories(data, error);
  if (error) {
    throw io::OutputError(fmt::format("{}: cannot create the folder ({})", data.string(), error.message()));
  }
  const std::vector<Column> columns = columns_of(input);
  std::int64_t count = 0, failed = 0;
  // Pass p writes the columns [p * kColumnsPerPass, ...), the first also the rows files.
  for (std::size_t from = 0; from < columns.size(); from += kColumnsPerPass) {
    const std::size_t to = std::min(columns.size(), from + kColumnsPerPass);
    std::vector<std::unique_ptr<io::StreamingOutput>> outs;
    for (std::size_t c = from; c < to; ++c) {
      outs.push_back(std::make_unique<io::StreamingOutput>(data / fmt::format("column-{}.js", columns[c].key),
                                                               kColumnBuffer));
      outs.back()->write(fmt::format("pitaColumn(\"{}\",[", columns[c].key));
    }
    std::optional<io::StreamingOutput> rows_file;
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
        ++count;
        failed += row.ok() ? 0 : 1;
        const std::int64_t file = position / kIndexRowsPerFile;
        if (position % kIndexRowsPerFile == 0) {
          if (rows_file) {
            rows_file->write("]);\n");
            rows_file->commit();
          }
          rows_file.emplace(data / fmt::format("rows-{}.js", file), kColumnBuffer);
          rows_file->write(fmt::format("pitaRows({},[\n", file));
        }
        text.clear();
        text += fmt::format("{}[{},", position % kIndexRowsPerFile == 0 ? "" : ",\n", row.index);
        append_value(text, row.status);
        const std::string thumb = output_with(row, {"png", "svg"}), full = output_with(row, {"svg", "png", "pdf"});
        text += fmt::format(",\"{}\",\"{}\"", url(thumb), url(full));
        for (const Column& c : columns) {  // shown as the manifest prints them
          text += ',';
          text += nlohmann::json(field_of(row, c)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        }
        text += ']';
        rows_file->write(text);
      }
      ++position;
    }
    if (rows_file) {
      rows_file->write("]);\n");
      rows_file->commit();
    }
    for (auto& out : outs) {
      out->write("]);\n");
      out->commit();
    }
  }
  remove_stale(data, (count + kIndexRowsPerFile - 1) / kIndexRowsPerFile, columns);

  nlohmann::json meta = {{"count", count},
                         {"perFile", kIndexRowsPerFile},
                         {"figures", input.figures},
                         {"columns", nlohmann::json::array()}};
  for (const Column& c : columns) meta["columns"].push_back({{"key", c.key}, {"name", c.name}});
  // Inside <script>: every "<" as \u003c (no "</script>", no "<!--" can end or bend it).
  std::string meta_text;
  for (const char c : meta.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)) {
    meta_text += c == '<' ? std::string_view("\\u003c") : std::string_view(&c, 1);
  }
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
  out += fmt::format("<p>{} of {} variants ({} failed) of <code>{}</code>; the values at ", count, input.variants,
                     failed, text::html_escaped(input.base_path));
  for (std::size_t k = 0; k < input.pointers.size(); ++k) {
    out += fmt::format("{}<code>{}</code>", k == 0 ? "" : ", ", text::html_escaped(input.pointers[k]));
  }
  out += ". Every row is in <a href=\"manifest.csv\">manifest.csv</a>; click a heading to sort.</p>\n";
  out += "<p><label>Sort by <select id=\"sort\"><option value=\"index\">index</option></select></label> "
         "<select id=\"order\"><option value=\"asc\">ascending</option><option value=\"desc\">descending</option>"
         "</select> <button id=\"first\">« first</button> <button id=\"prev\">‹ previous</button> "
         "<label>page <input id=\"page\" type=\"number\" min=\"1\" value=\"1\"></label> <span id=\"pages\"></span> "
         "<button id=\"next\">next ›</button> <button id=\"last\">last »</button> "
         "<label>rows <select id=\"size\"><option>50</option><option selected>100</option><option>500</option>"
         "</select></label> <span id=\"status\" role=\"status\"></span></p>\n"
         "<table><thead><tr id=\"head\"></tr></thead><tbody id=\"rows\"></tbody></table>\n";
  out += fmt::format("<script>const sweep = {};</script>\n", meta_text);
  out += kScript;
  out += "</body></html>\n";
  io::write_file_atomically(input.dir / "index.html", out);
  return "";
}

}  // namespace pita::sweep
