// pita.methods() and pita.motion(method, keyframes, times, **options): a
// motion built by the motion stage from a scene the call makes, as if it were
// a file ({"method", "keyframes" or "poses", "options", ...}), so that it is
// checked by the same reader (errors name /keyframes/1/m) and evaluated by the
// same SceneMotion as `pita eval`.
#include <algorithm>
#include <array>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "core/chains/chain.hpp"
#include "core/methods.hpp"
#include "core/overloaded.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pose_method.hpp"
#include "core/pose_traits.hpp"
#include "motion/evaluation.hpp"
#include "python/bindings.hpp"
#include "python/chunks.hpp"
#include "python/held_scene.hpp"
#include "scene/arrow_json.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::python {

namespace {

using Json = nlohmann::ordered_json;

// A Python value (numbers, strings, lists, dicts) as JSON, through Python's
// own json module (a value it cannot write raises TypeError there).
Json to_json(const py::handle& value) {
  const std::string text =
      py::module_::import("json").attr("dumps")(value, py::arg("allow_nan") = false).cast<std::string>();
  return Json::parse(text);
}

Json pose_json(const Pose& pose) {
  return std::visit(
      [](const auto& A) {
        Json rows = Json::array();
        const auto n = A.b.size();
        for (Eigen::Index i = 0; i < n; ++i) {
          Json row = Json::array();
          for (Eigen::Index j = 0; j < n; ++j) row.push_back(A.L(i, j));
          row.push_back(A.b(i));
          rows.push_back(row);
        }
        return Json{{"matrix", rows}};
      },
      pose);
}

// Whether a keyframe is given as a pose: a pita.Pose, a scene file's
// {"matrix"}, {"triangle"} or {"tetrahedron"}, or a matrix of a pose.
bool given_as_pose(const py::handle& item) {
  if (py::isinstance<py::dict>(item)) {
    const py::dict d = py::reinterpret_borrow<py::dict>(item);
    return d.contains("matrix") || d.contains("triangle") || d.contains("tetrahedron");
  }
  if (py::isinstance<Arrow>(item)) return false;
  try {
    (void)read_pose(item, "keyframes[0]");
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// What pita.motion's scenes are called in its errors.
constexpr const char* kMotionFile = "<pita.motion>";

// The fields of a scene that pita.motion takes as keywords, beside the
// method options: those that shape the motion, of keyframes (a chain of
// more keyframes than the method takes) or of poses (the SAM's subdivisions);
// the figure's fields are pita.load_scene's.
constexpr std::array<std::string_view, 2> kKeyframeFields = {"chain", "timing"};
constexpr std::array<std::string_view, 2> kPoseFields = {"timing", "subdivisions"};

std::span<const std::string_view> motion_fields(bool poses) {
  return poses ? std::span<const std::string_view>(kPoseFields) : std::span<const std::string_view>(kKeyframeFields);
}

// Why a keyword is refused: the closest of the keywords pita.motion takes
// (scene/did_you_mean.hpp), and all of them.
std::string unknown_keyword(const std::string& field, bool poses) {
  constexpr auto options = method_option_names();
  const auto fields = motion_fields(poses);
  std::vector<std::string_view> known(options.begin(), options.end());
  known.emplace_back("options");
  known.insert(known.end(), fields.begin(), fields.end());
  const std::vector<std::string> close = scene::closest_names(field, known);
  return fmt::format(
      "unknown keyword \"{}\"{} (pita.motion takes the method options {}, or options={{...}}, "
      "and the scene fields {} of a motion of {})",
      field, scene::did_you_mean(close), fmt::join(options, ", "), fmt::join(fields, ", "),
      poses ? "poses" : "keyframes");
}

// The scene pita.motion evaluates.
Json motion_scene(const std::string& method, const py::sequence& keyframes, const py::object& times,
                  const py::kwargs& options) {
  // The kind of the keyframes: a pose method's name means poses; a name both
  // kinds share (the PITAs P4, P5, P6, P9) means poses when the keyframes
  // are given as poses.
  const MethodEntry* arrow = find_method_entry(method, is_method_of<Method>);
  const bool poses = arrow == nullptr ? find_method_entry(method) != nullptr
                                      : find_method_entry(method, is_method_of<PoseMethod>) != nullptr &&
                                            py::len(keyframes) > 0 && given_as_pose(keyframes[0]);
  // The count first, as the scene reader would refuse it, before a
  // keyframe is converted (a million of them would take seconds).
  if (const std::size_t count = py::len(keyframes);
      count > static_cast<std::size_t>(poses ? scene::kMaxPoses : scene::kMaxKeyframes)) {
    throw scene::SceneError(kMotionFile, poses ? "/poses" : "/keyframes",
                            fmt::format("at most {} {} (got {})", poses ? scene::kMaxPoses : scene::kMaxKeyframes,
                                        poses ? "poses" : "keyframes", count));
  }
  Json scene{{"method", method}};
  std::vector<double> knots;
  if (!times.is_none()) {
    const Times given = read_times(times, "times");
    if (given.scalar || given.shape.size() != 1)
      throw py::value_error("times: expected a list of knots, one per keyframe");
    knots = given.values;
    if (knots.size() != py::len(keyframes)) {
      throw py::value_error(fmt::format("times: {} knots for {} keyframes", knots.size(), py::len(keyframes)));
    }
  }
  Json items = Json::array();
  int dimension = 2;
  for (std::size_t i = 0; i < py::len(keyframes); ++i) {
    const py::object item = keyframes[i];  // owned: an array makes a new view for each item
    const std::string name = fmt::format("keyframes[{}]", i);
    Json key;
    if (py::isinstance<py::dict>(item) && (poses || !py::isinstance<Arrow>(item))) {
      key = to_json(item);  // as a scene file gives it: {"t", "p", "m", "w"} or {"t", "matrix"}
    } else if (poses) {
      const Pose pose = read_pose(item, name.c_str());
      if (std::visit([]<class P>(const P&) { return PoseTraits<P>::dimension; }, pose) == 3) dimension = 3;
      key = pose_json(pose);
    } else {
      key = scene::arrow_json(read_arrow(item, name.c_str()));
    }
    if (!knots.empty()) {
      Json timed{{"t", knots[i]}};
      for (auto& [field, value] : key.items()) {
        if (field != "t") timed[field] = value;
      }
      key = timed;
    } else if (!key.contains("t")) {
      throw py::value_error(
          fmt::format("times: give the keyframes' times (knots), or a \"t\" in each keyframe "
                      "(keyframes[{}] has none)",
                      i));
    }
    items.push_back(key);
  }
  if (dimension == 3) scene["dimension"] = 3;
  scene[poses ? "poses" : "keyframes"] = items;
  // Method options ("anchor", "path_mean", ...) go into "options"; the
  // fields of the scene that shape its motion ("chain", "timing",
  // "subdivisions": motion_fields) are fields of the scene; any other
  // keyword is refused.
  Json method_options = Json::object();
  for (const auto& [key, value] : options) {
    const std::string field = key.cast<std::string>();
    constexpr auto names = method_option_names();
    if (field == "options") {
      const Json given = to_json(value);
      if (!given.is_object()) throw py::type_error("options: expected a dict of method options");
      for (const auto& item : given.items()) method_options[item.key()] = item.value();
    } else if (std::find(names.begin(), names.end(), field) != names.end()) {
      method_options[field] = to_json(value);
    } else if (const auto fields = motion_fields(poses);
               std::find(fields.begin(), fields.end(), field) != fields.end()) {
      scene[field] = to_json(value);
    } else {
      throw scene::SceneError(kMotionFile, "/" + field, unknown_keyword(field, poses));
    }
  }
  if (!method_options.empty()) scene["options"] = method_options;
  return scene;
}

}  // namespace

std::shared_ptr<HeldMotion> hold_motion(scene::Scene scene, std::optional<int> panel) {
  auto held = std::make_shared<HeldMotion>();
  held->scene = std::move(scene);
  if (!scene::has_motion_keys(held->scene.keys)) {
    throw scene::SceneError(held->scene.path, "/poses", "the scene has no poses, so no motion");
  }
  try {
    held->evaluation = std::make_unique<motion::Evaluation>(held->scene, panel);
  } catch (const std::out_of_range& error) {
    throw py::value_error(fmt::format("panel: {}", error.what()));
  }
  return held;
}

py::object sample(const motion::SceneMotion& motion, const Times& times) {
  const std::size_t n = times.values.size();
  const std::vector<double>& t = times.values;
  return std::visit(
      overloaded{[&](const motion::ArrowTrack&) -> py::object {
                   if (times.scalar) return arrow_object(motion.arrow_at(t.front()));
                   py::array_t<double> p = new_array(times.shape, {2}), m = new_array(times.shape, {}),
                                       w = new_array(times.shape, {}), q = new_array(times.shape, {2});
                   double *pp = p.mutable_data(), *pm = m.mutable_data(), *pw = w.mutable_data(),
                          *pq = q.mutable_data();
                   for_each_chunk(n, [&](std::size_t begin, std::size_t end) {
                     for (std::size_t i = begin; i < end; ++i) {
                       const Arrow D = motion.arrow_at(t[i]);
                       const Point e = D.q();
                       pp[2 * i] = D.p.real(), pp[2 * i + 1] = D.p.imag(), pm[i] = D.m, pw[i] = D.w;
                       pq[2 * i] = e.real(), pq[2 * i + 1] = e.imag();
                     }
                     return true;
                   });
                   return arrow_samples_type()(p, m, w, q);
                 },
                 [&](const motion::PointTrack&) -> py::object {
                   if (times.scalar) {
                     const Point x = motion.point_at(t.front());
                     return py::make_tuple(x.real(), x.imag());
                   }
                   py::array_t<double> xy = new_array(times.shape, {2});
                   double* out = xy.mutable_data();
                   for_each_chunk(n, [&](std::size_t begin, std::size_t end) {
                     for (std::size_t i = begin; i < end; ++i) {
                       const Point x = motion.point_at(t[i]);
                       out[2 * i] = x.real(), out[2 * i + 1] = x.imag();
                     }
                     return true;
                   });
                   return xy;
                 },
                 [&]<class Pose>(const motion::PoseTrack<Pose>&) -> py::object {
                   // Poses of the plane (2 x 3 each) or of space (3 x 4 each).
                   constexpr int rows = PoseTraits<Pose>::dimension;
                   if (times.scalar) return pose_object(motion.pose_at<Pose>(t.front()));
                   py::array_t<double> out = new_array(times.shape, {py::ssize_t{rows}, py::ssize_t{rows + 1}});
                   double* data = out.mutable_data();
                   for_each_chunk(n, [&](std::size_t begin, std::size_t end) {
                     for (std::size_t i = begin; i < end; ++i) {
                       write_pose(motion.pose_at<Pose>(t[i]), data + rows * (rows + 1) * i);
                     }
                     return true;
                   });
                   return out;
                 }},
      motion.built());
}

void bind_motion(py::module_& m) {
  const py::object method_info =
      py::module_::import("collections")
          .attr("namedtuple")("MethodInfo", "id mnemonic title kind min_count max_count space");
  method_info.attr("__module__") = "pita";
  m.attr("MethodInfo") = method_info;
  m.def(
      "methods",
      [method_info]() {
        py::list all;
        for (const MethodEntry& entry : every_method()) {
          // The kind of keys the method takes, and whether it also moves space.
          const auto [kind, space] = std::visit(overloaded{[](Method) {
                                                             return std::pair{"arrows", false};
                                                           },
                                                           [](PoseMethod pose) {
                                                             return std::pair{"poses", info(pose).in_space};
                                                           }},
                                                entry.method);
          all.append(method_info(std::string(entry.id), std::string(entry.mnemonic), std::string(entry.title), kind,
                                 entry.min_count, entry.max_count, space));
        }
        return all;
      },
      R"(Every method pita evaluates, as MethodInfo(id, mnemonic, title, kind, min_count, max_count,
space): the PITAs P1-P10 and P5S, the SMA and the other arrow methods (kind "arrows": keyframes),
then the SAM family (kind "poses"; space is True for those that also move poses of space).
min_count and max_count bound the keyframes or poses the method takes; more keyframes than an
arrow method's own count make a chained track.)");

  py::class_<HeldMotion, std::shared_ptr<HeldMotion>>(m, "Motion", R"(A motion built once: call it with a time
or an array of times (scene times; outside the knots it extrapolates).

  arrows    motion(0.5) is a pita.Arrow; motion(times) is ArrowSamples(p, m, w, q) with p and q of
            shape times.shape + (2,), m and w of shape times.shape
  points    motion(0.5) is (x, y); motion(times) has shape times.shape + (2,)
  poses     motion(0.5) is a pita.Pose; motion(times) is [L | b] of shape times.shape + (2, 3),
            or + (3, 4) for poses of space

The frames are computed in C++ with the GIL released, exactly as `pita eval` computes them.
Raises pita.NoMotionError where the motion is undefined or not finite.)")
      .def(
          "__call__",
          [](const HeldMotion& held, const py::handle& t) {
            return sample(held.evaluation->motion(), read_times(t, "t"));
          },
          py::arg("t"))
      .def_property_readonly(
          "method", [](const HeldMotion& held) { return held.evaluation->motion().method_id(); },
          "The method's id: \"P6\", \"SAM\".")
      .def_property_readonly(
          "label", [](const HeldMotion& held) { return held.evaluation->motion().label(); },
          "The method as messages name it: \"P6 (La-LP)\".")
      .def_property_readonly(
          "kind", [](const HeldMotion& held) { return std::string(scene::kind_name(held.evaluation->panel().keys)); },
          "\"arrows\", \"points\", \"poses\" or \"poses3d\" (poses of space).")
      .def_property_readonly(
          "knots", [](const HeldMotion& held) { return py::tuple(py::cast(held.evaluation->motion().knots())); },
          "The keyframes' (or poses') times, increasing.")
      .def_property_readonly(
          "chain",
          [](const HeldMotion& held) -> py::object {
            const auto chain = held.evaluation->motion().chain();
            if (!chain) return py::none();
            return py::str(std::string(info(*chain).name));
          },
          "The chain of a track of more keyframes than the method takes (\"blend\", ...), else None.")
      .def("__repr__", [](const HeldMotion& held) {
        const motion::SceneMotion& motion = held.evaluation->motion();
        return fmt::format("<pita.Motion {} through {} {}, t in [{}, {}]>", motion.label(), motion.knots().size(),
                           motion.is<motion::ArrowTrack>()   ? "keyframes"
                           : motion.is<motion::PointTrack>() ? "points"
                                                             : "poses",
                           motion.first(), motion.last());
      });
  refuse_uninitialised<HeldMotion>();

  m.def(
      "motion",
      [](const std::string& method, const py::sequence& keyframes, const py::object& times, const py::kwargs& options) {
        const std::string text = motion_scene(method, keyframes, times, options).dump();
        return hold_motion(scene::parse_scene(text, kMotionFile));
      },
      py::arg("method"), py::arg("keyframes"), py::arg("times") = py::none(),
      R"(The motion of `method` through keyframes at times (knots, strictly increasing), built once.

  method     a method id or mnemonic of pita.methods(): "P6", "La-LP", "SMA", "SAM", "polySAM", ...
  keyframes  arrows (pita.Arrow, {"p", "m", "w"} or {"p", "q"} dicts, (p, m, w) tuples) for the
             PITAs and the SMA; poses (pita.Pose, 2x3 / 3x3 / 3x4 / 4x4 matrices) for the SAM family
  times      the knots, one per keyframe; may be left out when each keyframe dict has a "t"
  options    method options (anchor, path_mean, magnitude_mean, knots, permutation,
             symmetrize) and scene fields (chain and timing of keyframes, timing and
             subdivisions of poses), as a scene file spells them:
             motion("P2", arrows, [0, 1, 2], anchor="midpoint", chain="neville")

Raises pita.SceneError naming the JSON Pointer of the bad value in the scene the call makes
(e.pointer == "/keyframes/1/m"), and pita.NoMotionError when no such motion exists. Another
keyword is refused with a "did you mean" among those names (e.pointer == "/anchr"), and an
option the method does not read, with the methods that read it ("/options/anchor").)");
}

}  // namespace pita::python
