// pita.scenes_dir() and pita.example(name): pita's own scenes (scenes/ of the
// repository, the figures of the papers) from any working directory. An
// installed module finds them where cmake --install puts them,
// PREFIX/share/pita/scenes (the Debian package pita: /usr/share/pita/scenes),
// by the path from its own folder that the build bakes in; the module of a
// build folder finds them in the source folder it was built from.
#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "python/bindings.hpp"
#include "scene/did_you_mean.hpp"

#if !defined(PITA_SOURCE_SCENES) || !defined(PITA_BUILD_MODULE_DIR) || !defined(PITA_SCENES_FROM_MODULE)
#error "PITA_SOURCE_SCENES, PITA_BUILD_MODULE_DIR and PITA_SCENES_FROM_MODULE are defined by src/python/CMakeLists.txt"
#endif

namespace pita::python {

namespace {

namespace fs = std::filesystem;

// A path made absolute and free of "..", as far as it exists.
fs::path resolved(const fs::path& path) {
  std::error_code error;
  fs::path result = fs::weakly_canonical(path, error);
  return error ? fs::absolute(path).lexically_normal() : result;
}

[[noreturn]] void raise_not_found(const std::string& message) {
  PyErr_SetString(PyExc_FileNotFoundError, message.c_str());
  throw py::error_already_set();
}

// The folder of pita's scenes for this module.
fs::path scenes_folder() {
  const py::object module = py::module_::import("sys").attr("modules")["pita"];
  const fs::path here = resolved(fs::path(module.attr("__file__").cast<std::string>()).parent_path());
  if (here == resolved(PITA_BUILD_MODULE_DIR)) {  // the module of a build folder
    const fs::path source = PITA_SOURCE_SCENES;
    if (fs::is_directory(source)) return source;
    raise_not_found(fmt::format("pita's scenes: this module was built from {}, which has no scenes/ folder now",
                                source.parent_path().string()));
  }
  const fs::path installed = resolved(here / PITA_SCENES_FROM_MODULE);
  if (fs::is_directory(installed)) return installed;
  raise_not_found(
      fmt::format("pita's scenes: no folder {} beside this module ({}); cmake --install puts them in "
                  "PREFIX/share/pita/scenes, and the Debian package pita in /usr/share/pita/scenes",
                  installed.string(), here.string()));
}

py::object as_path(const fs::path& path) { return py::module_::import("pathlib").attr("Path")(path.string()); }

py::object example(const std::string& given) {
  std::string name = given;
  if (name.size() > 5 && name.ends_with(".json")) name.resize(name.size() - 5);
  if (name.empty() || name.find('/') != std::string::npos || name.starts_with(".")) {
    throw py::value_error(fmt::format(
        "example: \"{}\" is not the name of a scene (a file name without its folder: \"fig01-eight-pitas\")", given));
  }
  const fs::path folder = scenes_folder();
  const fs::path file = folder / (name + ".json");
  if (fs::is_regular_file(file)) return as_path(file);
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  const std::vector<std::string_view> known(names.begin(), names.end());
  std::vector<std::string> close = scene::closest_names(name, known);
  if (close.empty()) {  // "fig01": the scenes whose names begin so
    for (const std::string& candidate : names) {
      if (candidate.starts_with(name)) close.push_back(candidate);
    }
    if (close.size() > 5) close.clear();
  }
  throw py::value_error(fmt::format("example: no scene \"{}\" in {}{} (pita.scenes_dir() holds {} scenes)", name,
                                    folder.string(), scene::did_you_mean(close), names.size()));
}

}  // namespace

void bind_examples(py::module_& m) {
  m.def(
      "scenes_dir", []() { return as_path(scenes_folder()); },
      R"(The folder of pita's own scenes (the repository's scenes/: the papers' figures), as a
pathlib.Path, from any working directory: PREFIX/share/pita/scenes for an installed module
(/usr/share/pita/scenes with the Debian package pita), the source folder's scenes/ for the
module of a build folder. Raises FileNotFoundError when they are not there.)");
  m.def("example", &example, py::arg("name"),
        R"(The path (a pathlib.Path) of one of pita's own scenes, by its name without folder or
".json": pita.load_scene(pita.example("fig01-eight-pitas")) from any folder. Raises
ValueError, with a "did you mean", for a name it does not have.)");
}

}  // namespace pita::python
