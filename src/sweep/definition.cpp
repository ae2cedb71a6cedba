#include "sweep/definition.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "sweep/index_page.hpp"
#include "sweep/sheet.hpp"
#include "sweep/sweep.hpp"

namespace pita::sweep {

namespace fs = std::filesystem;

std::string definition_json(const Definition& d) {
  Json j;
  j["scene"] = d.scene;
  j["name"] = d.name;
  j["axes"] = Json::array();
  for (std::size_t k = 0; k < d.axes.size(); ++k) {
    j["axes"].push_back(Json{{"pointer", d.axes[k].first}, {"spec", d.axes[k].second}, {"size", d.axis_sizes[k]}});
  }
  j["zip"] = d.zip;
  j["formats"] = d.formats;
  j["variants"] = d.variants;
  j["salt"] = d.salt;
  j["base"] = d.base;
  return j.dump(2) + "\n";
}

Definition read_definition(const fs::path& dir) {
  std::ifstream in(dir / kSweepFile, std::ios::binary);
  if (!in) {
    throw SweepUsageError(About{Input::merge, dir.string()},
                          fmt::format("no {} there: it is not the output folder of a pita sweep", kSweepFile));
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    const Json j = Json::parse(text.str());
    Definition d;
    d.scene = j.at("scene").get<std::string>();
    d.name = j.at("name").get<std::string>();
    for (const Json& a : j.at("axes")) {
      d.axes.emplace_back(a.at("pointer").get<std::string>(), a.at("spec").get<std::string>());
      d.axis_sizes.push_back(a.at("size").get<std::size_t>());
    }
    d.zip = j.at("zip").get<bool>();
    d.formats = j.at("formats").get<std::vector<std::string>>();
    d.variants = j.at("variants").get<std::int64_t>();
    d.salt = j.at("salt").get<std::string>();
    d.base = j.at("base");
    if (d.name.empty() || d.name.find('/') != std::string::npos) throw std::runtime_error("bad name");
    if (d.variants < 0 || d.variants > kMaxVariants) throw std::runtime_error("bad variant count");
    return d;
  } catch (const std::exception& error) {
    throw SweepUsageError(About{Input::merge, dir.string()},
                          fmt::format("{} is not a sweep definition ({})", (dir / kSweepFile).string(), error.what()));
  }
}

std::vector<std::string> pointers_of(const Definition& d) {
  std::vector<std::string> p;
  for (const auto& [pointer, spec] : d.axes) p.push_back(pointer);
  return p;
}

namespace {

SheetInput sheet_input(const fs::path& dir, const Definition& d) {
  SheetInput s;
  s.dir = dir;
  s.name = d.name;
  s.base_path = d.scene;
  s.pointers = pointers_of(d);
  s.axis_sizes = d.axis_sizes;
  s.zip = d.zip;
  s.variants = d.variants;
  for (const std::string& f : d.formats) s.figures = s.figures || f == "svg" || f == "png" || f == "pdf";
  return s;
}

}  // namespace

void write_reports(const fs::path& dir, const Definition& d, std::vector<std::string>& notes) {
  const SheetInput input = sheet_input(dir, d);
  if (std::string why = write_index_html(input); !why.empty()) notes.push_back(std::move(why));
  if (input.figures) {
    if (std::string why = write_contact_sheet(input); !why.empty()) notes.push_back(std::move(why));
  }
}

}  // namespace pita::sweep
