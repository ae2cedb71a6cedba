#include "sweep/manifest.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "io/input_file.hpp"

namespace pita::sweep {

namespace {

std::vector<std::string> split_outputs(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t at = text.find(';', start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) break;
    start = at + 1;
  }
  return out;
}

}  // namespace

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string manifest_header(const std::vector<std::string>& pointers) {
  std::string out = "index";
  for (const std::string& p : pointers) {
    out += ',';
    out += csv_field(p);
  }
  out += ",status,outputs,hash";
  for (const std::string_view m : kMetricColumns) out += fmt::format(",{}", m);
  out += '\n';
  return out;
}

void append_row(std::string& out, const Row& row) {
  out += std::to_string(row.index);
  const auto field = [&out](std::string_view text) {
    out += ',';
    out += csv_field(text);
  };
  for (const std::string& v : row.values) field(v);
  std::string outputs;
  for (const std::string& o : row.outputs) {
    if (!outputs.empty()) outputs += ';';
    outputs += o;
  }
  field(row.status);
  field(outputs);
  field(row.hash);
  for (const std::string& m : row.metrics) field(m);
  out += '\n';
}

std::string manifest_csv(const std::vector<std::string>& pointers, const std::vector<Row>& rows) {
  std::string out = manifest_header(pointers);
  for (const Row& row : rows) append_row(out, row);
  return out;
}

std::string manifest_csv(const std::vector<std::string>& pointers, const std::map<std::int64_t, Row>& rows) {
  std::string out = manifest_header(pointers);
  for (const auto& [index, row] : rows) append_row(out, row);
  return out;
}

std::optional<ManifestReader> ManifestReader::open(const std::filesystem::path& path,
                                                   const std::vector<std::string>& pointers, bool headless) {
  ManifestReader reader;
  // A regular file only: a FIFO or a device (a part linked to /dev/zero) is
  // refused at once, never waited on or read without end.
  try {
    const io::InputFile regular(path);
  } catch (const io::InputError& error) {
    std::error_code ignored;
    if (error.kind() == io::InputError::Kind::not_regular && std::filesystem::exists(path, ignored)) {
      throw std::runtime_error(fmt::format("{}: {}", path.string(), error.sentence("manifest")));
    }
  }
  reader.in_ = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*reader.in_) {
    // Missing is nullopt; there but unreadable (permissions, out of file
    // descriptors) is an error, never a manifest silently left out.
    const int saved = errno;
    std::error_code ignored;
    if (!std::filesystem::exists(path, ignored)) return std::nullopt;
    throw io::OutputError(fmt::format("{}: cannot read ({})", path.string(), std::strerror(saved)));
  }
  reader.path_ = path.string();
  reader.pointers_ = pointers.size();
  if (headless) return reader;
  std::vector<std::string> fields;
  const std::size_t width = 4 + pointers.size() + kMetricColumns.size();
  if (!reader.record(fields) || fields.size() != width || fields[0] != "index" ||
      !std::equal(pointers.begin(), pointers.end(), fields.begin() + 1)) {
    std::string expected = "index";
    for (const std::string& p : pointers) expected += "," + p;
    throw std::runtime_error(
        fmt::format("{}: not the manifest of this sweep (its header does not start with {}); "
                    "use another output folder, or remove it",
                    path.string(), expected));
  }
  return reader;
}

bool ManifestReader::record(std::vector<std::string>& fields) {
  fields.clear();
  std::istream& in = *in_;
  if (in.peek() == std::char_traits<char>::eof()) return false;
  std::string field;
  bool quoted = false;
  char c = 0;
  bool ended = false;
  while (in.get(c)) {
    if (quoted) {
      if (c == '"') {
        if (in.peek() == '"') {
          field += '"';
          in.get(c);
        } else {
          quoted = false;
        }
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.push_back(std::move(field));
      field.clear();
    } else if (c == '\n') {
      ended = true;
      break;
    } else if (c != '\r') {
      field += c;
    }
    if (field.size() > kMaxRecordBytes) {
      throw std::runtime_error(fmt::format("{}: line {} is longer than the limit of {} MiB (not a manifest pita wrote)",
                                           path_, line_ + 1, kMaxRecordBytes >> 20));
    }
  }
  fields.push_back(std::move(field));
  complete_ = ended;
  ++line_;
  return true;
}

bool ManifestReader::is_sorted(const std::filesystem::path& path, const std::vector<std::string>& pointers) {
  std::optional<ManifestReader> reader = open(path, pointers);
  if (!reader) return true;
  Row row;
  std::int64_t last = -1;
  while (reader->next(row)) {
    if (row.index <= last) return false;
    last = row.index;
  }
  return true;
}

std::optional<ManifestReader> ManifestReader::open_sorted(const std::filesystem::path& path,
                                                          const std::vector<std::string>& pointers) {
  std::optional<ManifestReader> reader = open(path, pointers);
  if (!reader) return std::nullopt;
  Row row;
  while (reader->read_row(row)) reader->held_.emplace_back(reader->line_, std::move(row));
  std::stable_sort(reader->held_.begin(), reader->held_.end(),
                   [](const auto& a, const auto& b) { return a.second.index < b.second.index; });
  for (std::size_t i = 1; i < reader->held_.size(); ++i) {
    if (reader->held_[i].second.index == reader->held_[i - 1].second.index) {
      throw std::runtime_error(fmt::format("{}: variant {} appears twice, on lines {} and {}", path.string(),
                                           reader->held_[i].second.index, reader->held_[i - 1].first,
                                           reader->held_[i].first));
    }
  }
  reader->holding_ = true;
  return reader;
}

std::string ManifestReader::where() const { return fmt::format("{}:{}", path_, row_line_); }

bool ManifestReader::next(Row& row) {
  if (!holding_) {
    const bool found = read_row(row);
    row_line_ = line_;
    return found;
  }
  if (at_ >= held_.size()) return false;
  row_line_ = held_[at_].first;
  row = std::move(held_[at_].second);
  ++at_;
  return true;
}

bool ManifestReader::read_row(Row& row) {
  std::vector<std::string> fields;
  const std::size_t width = 4 + pointers_ + kMetricColumns.size();
  while (record(fields)) {
    if (fields.size() == 1 && fields[0].empty()) continue;
    // Every row ends with a line break: a last line without one was cut short
    // by a killed process (a journal), and is not a row.
    if (!complete_) return false;
    if (fields.size() != width) {
      throw std::runtime_error(fmt::format("{}:{}: {} fields, expected {}", path_, line_, fields.size(), width));
    }
    row = Row{};
    try {
      row.index = std::stoll(fields[0]);
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("{}:{}: the index \"{}\" is not a number", path_, line_, fields[0]));
    }
    std::size_t k = 1;
    for (std::size_t i = 0; i < pointers_; ++i) row.values.push_back(fields[k++]);
    row.status = fields[k++];
    row.outputs = split_outputs(fields[k++]);
    row.hash = fields[k++];
    for (std::string& m : row.metrics) m = fields[k++];
    return true;
  }
  return false;
}

std::optional<std::vector<Row>> read_manifest(const std::filesystem::path& path,
                                              const std::vector<std::string>& pointers) {
  std::optional<ManifestReader> reader = ManifestReader::open(path, pointers);
  if (!reader) return std::nullopt;
  std::vector<Row> rows;
  Row row;
  while (reader->next(row)) rows.push_back(std::move(row));
  return rows;
}

std::string variant_file(const std::string& name, std::int64_t index, std::int64_t variants,
                         const std::string& extension) {
  (void)variants;
  return fmt::format("{}-{}.{}", name, index, extension);
}

std::string manifest_name(std::optional<std::pair<int, int>> shard) {
  return shard ? fmt::format("manifest.{}-of-{}.csv", shard->first, shard->second) : "manifest.csv";
}

}  // namespace pita::sweep
