#include "scene/pose_reader.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "scene/did_you_mean.hpp"
#include "scene/image_file.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 7> kShapeKinds = {"polygon", "polyline", "triangle", "outline",
                                                         "image",   "box",      "color"};
constexpr std::array<std::string_view, 4> kOutlineNames = {"F", "house", "square", "picture"};

}  // namespace

double bounded(const JsonReader& reader, const Json& value, const std::string& pointer) {
  const double x = reader.number(value, pointer);
  if (std::abs(x) > kMaxKeyframeValue) {
    reader.fail(pointer, fmt::format("must be within +-{:g} (got {})", kMaxKeyframeValue, number_text(x)));
  }
  return x;
}

// ---------------------------------------------------------------- the plane

Point PoseSpace<Affine2>::read_point(const JsonReader& reader, const Json& value, const std::string& pointer) {
  const Point p = reader.point(value, pointer);
  for (int axis = 0; axis < 2; ++axis) {
    const double x = axis == 0 ? p.real() : p.imag();
    if (std::abs(x) > kMaxKeyframeValue) {
      reader.fail(element_pointer(pointer, static_cast<std::size_t>(axis)),
                  fmt::format("must be within +-{:g} (got {})", kMaxKeyframeValue, number_text(x)));
    }
  }
  return p;
}

// A pose may reverse orientation (a mirrored shape); the SAM between two
// poses needs C o B^-1 to preserve it, which the motion checks. A pose must
// be invertible, numerically: |det| above kSingularPose (1e-16) of |L|_F^2, which is about
// the ratio of its singular values (|det| = |L|_F^2 / 2 for a similarity):
// a matrix singular but for rounding, such as [[0.1, 0.3], [0.2, 0.6]], is
// below; a stretch diag(1e7, 1e-7) (ratio 1e-14) is above.
void PoseSpace<Affine2>::refuse_singular(const JsonReader& reader, const std::string& pointer,
                                         const Traits::LinearPart&, double det, double) {
  reader.fail(pointer, fmt::format("the linear part [[a, b], [c, d]] has determinant {} (its "
                                   "singular values differ by more than 1e16): the pose is "
                                   "singular, it flattens the plane onto a line or a point",
                                   number_text(det)));
}

// ---------------------------------------------------------------- space

Eigen::Vector3d PoseSpace<Affine3>::read_point(const JsonReader& reader, const Json& value,
                                               const std::string& pointer) {
  if (!value.is_array() || value.size() != 3) {
    reader.fail(pointer, "must be a point [x, y, z] of space (got " + value_text(value) + ")");
  }
  Eigen::Vector3d p;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    p(static_cast<Eigen::Index>(axis)) = bounded(reader, value[axis], element_pointer(pointer, axis));
  }
  return p;
}

// Invertible, numerically: |det| above kSingularPose (1e-16) of |L|_F^3. A
// mirrored pose is allowed, as in the plane. The message says which: singular
// (a singular value is zero to rounding), or only ill-conditioned (a strong
// shear of determinant 1 fails the test too).
void PoseSpace<Affine3>::refuse_singular(const JsonReader& reader, const std::string& pointer,
                                         const Traits::LinearPart& L, double det, double scale) {
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(L).singularValues();
  if (!std::isfinite(det) || !(sigma(2) > kSingularValueRatio * sigma(0))) {
    reader.fail(pointer, fmt::format("the linear part [[a, b, c], [d, e, f], [g, h, i]] has determinant {}: the "
                                     "pose is singular, it flattens space onto a plane, a line or a point",
                                     number_text(det)));
  }
  reader.fail(pointer, fmt::format("the linear part [[a, b, c], [d, e, f], [g, h, i]] has determinant {}, below "
                                   "1e-16 of |L|_F^3 = {:.3g} (the test is relative to the matrix's norm): it is "
                                   "not singular, but too ill-conditioned to invert reliably (its singular values "
                                   "range from {:.3g} to {:.3g}: a shear or stretch this strong)",
                                   number_text(det), scale, sigma(2), sigma(0)));
}

void PoseSpace<Affine3>::refuse_other_simplex(const JsonReader& reader, const Json& item, const std::string& pointer) {
  if (JsonReader::member(item, "triangle") != nullptr) {
    reader.fail(pointer + "/triangle",
                "a triangle is a pose of the plane; a 3D scene (\"dimension\": 3) gives "
                "\"tetrahedron\": four points [x, y, z], or a 3x4 \"matrix\"");
  }
}

void PoseSpace<Affine3>::refuse_other_matrix(const JsonReader& reader, const Json& value, const std::string& pointer) {
  if (value.is_array() && value.size() == 2) {
    reader.fail(pointer, fmt::format("a 2x3 matrix is a pose of the plane; the poses of a 3D scene (\"dimension\": "
                                     "3) are 3x4 matrices {} (got {})",
                                     kMatrixShape, value_text(value)));
  }
}

// ---------------------------------------------------------------- both

template <class Pose>
typename PoseSpace<Pose>::Simplex read_simplex(const JsonReader& reader, const Json& value,
                                               const std::string& pointer) {
  using Space = PoseSpace<Pose>;
  typename Space::Simplex points;
  if (!value.is_array() || value.size() != points.size()) {
    reader.fail(pointer, fmt::format("must be an array of {} (got {})", Space::kSimplexPoints, value_text(value)));
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Space::read_point(reader, value[i], element_pointer(pointer, i));
  }
  return points;
}

template <class Pose>
Pose frame_of(const typename PoseSpace<Pose>::Simplex& p) {
  using Space = PoseSpace<Pose>;
  Pose A;
  for (int i = 0; i < PoseTraits<Pose>::dimension; ++i) {
    A.L.col(i) = Space::vector_of(p[static_cast<std::size_t>(i) + 1]) - Space::vector_of(p[0]);
  }
  A.b = Space::vector_of(p[0]);
  return A;
}

template <class Pose>
bool degenerate(const typename PoseSpace<Pose>::Simplex& p) {
  const Pose frame = frame_of<Pose>(p);
  const double volume = frame.L.determinant();
  double edges = 1.0;
  for (int i = 0; i < PoseTraits<Pose>::dimension; ++i) edges *= frame.L.col(i).norm();
  return !(std::abs(volume) > kDegenerateSimplex * edges) || !std::isfinite(volume);
}

template <class Pose>
Pose read_matrix(const JsonReader& reader, const Json& value, const std::string& pointer) {
  using Space = PoseSpace<Pose>;
  constexpr std::size_t n = PoseTraits<Pose>::dimension;
  const auto shape_error = [&] {
    Space::refuse_other_matrix(reader, value, pointer);
    reader.fail(pointer,
                fmt::format("must be a {}x{} matrix {} (x -> {} x + {}; got {})", n, n + 1, Space::kMatrixShape,
                            Space::kLinearShape, Space::kTranslationShape, value_text(value)));
  };
  if (!value.is_array() || value.size() != n) shape_error();
  Pose A;
  for (std::size_t row = 0; row < n; ++row) {
    if (!value[row].is_array() || value[row].size() != n + 1) shape_error();
    const std::string at = element_pointer(pointer, row);
    for (std::size_t column = 0; column <= n; ++column) {
      const double x = bounded(reader, value[row][column], element_pointer(at, column));
      const auto r = static_cast<Eigen::Index>(row);
      if (column < n) {
        A.L(r, static_cast<Eigen::Index>(column)) = x;
      } else {
        A.b(r) = x;
      }
    }
  }
  const double det = A.L.determinant();
  const double scale = Space::singular_scale(A.L);
  if (!(std::abs(det) > kSingularPose * scale) || !std::isfinite(det)) {
    Space::refuse_singular(reader, pointer, A.L, det, scale);
  }
  return A;
}

template <class Pose>
typename PoseSpace<Pose>::Simplex read_reference(const JsonReader& reader, const Json& value,
                                                 const std::string& pointer) {
  using Space = PoseSpace<Pose>;
  const typename Space::Simplex points = read_simplex<Pose>(reader, value, pointer);
  if (degenerate<Pose>(points)) {
    reader.fail(pointer,
                fmt::format("the reference {} is degenerate (its points are {})", Space::kSimplex, Space::kFlat));
  }
  return points;
}

std::string pose_count_reason(PoseMethod method, std::size_t count) {
  const PoseMethodInfo& about = info(method);
  const int most = std::min(about.max_poses, kMaxPoses);
  const std::string wanted = about.min_poses == most ? fmt::format("exactly {}", about.min_poses)
                                                     : fmt::format("{} to {}", about.min_poses, most);
  return fmt::format("method {} takes {} poses (got {})", about.id, wanted, count);
}

PoseMethod read_pose_method(const JsonReader& reader, const Json& value, const std::string& pointer) {
  std::vector<std::string_view> ids;
  for (const PoseMethodInfo& entry : all_pose_methods()) ids.push_back(entry.id);
  if (!value.is_string()) {
    reader.fail(pointer, "must be a pose method: " + quoted_choices(ids) + " (got " + value_text(value) + ")");
  }
  const std::string name = value.get<std::string>();
  if (const PoseMethod* found = find_method_of<PoseMethod>(name)) return *found;
  reader.fail(pointer, unknown_scene_method_reason(name, is_method_of<PoseMethod>));
}

template <class Pose>
PoseMethod read_pose_method_of(const JsonReader& reader, const Json& value, const std::string& pointer) {
  const PoseMethod method = read_pose_method(reader, value, pointer);
  if (in_space_v<Pose> && !info(method).in_space) {
    std::vector<std::string_view> ids;
    for (const PoseMethodInfo& entry : all_pose_methods()) {
      if (entry.in_space) ids.push_back(entry.id);
    }
    reader.fail(pointer, fmt::format("method {} moves poses of the plane only; 3D scenes take {}", info(method).id,
                                     quoted_choices(ids)));
  }
  return method;
}

template <class Pose>
std::string missing_poses_reason() {
  using Space = PoseSpace<Pose>;
  if constexpr (in_space_v<Pose>) {
    return fmt::format("missing required field (an array of poses {{\"t\": ..., \"matrix\": {}}})",
                       Space::kMatrixShape);
  } else {
    return fmt::format(
        "missing required field (an array of poses {{\"t\": ..., \"matrix\": {}}} or {{\"t\": ..., "
        "\"{}\": {}}})",
        Space::kMatrixShape, Space::kSimplex, Space::kPointsShape);
  }
}

template <class Pose>
std::vector<TimedPoseOf<Pose>> read_poses(const JsonReader& reader, const Json& value, const std::string& pointer,
                                          const typename PoseSpace<Pose>::Simplex& reference, PoseMethod method) {
  using Space = PoseSpace<Pose>;
  const std::string simplex = Space::kSimplex;
  if (!value.is_array()) {
    reader.fail(pointer, fmt::format("must be an array of poses {{\"t\": ..., \"matrix\": {}}} or {{\"t\": ..., "
                                     "\"{}\": {}}} (got {})",
                                     Space::kMatrixShape, simplex, Space::kPointsShape, value_text(value)));
  }
  const PoseMethodInfo& about = info(method);
  if (value.size() < static_cast<std::size_t>(about.min_poses) ||
      value.size() > static_cast<std::size_t>(std::min(about.max_poses, kMaxPoses))) {
    reader.fail(pointer, pose_count_reason(method, value.size()));
  }
  const std::array<std::string_view, 3> fields = {"t", "matrix", Space::kSimplex};
  const Pose reference_frame = frame_of<Pose>(reference);
  std::vector<TimedPoseOf<Pose>> poses;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = element_pointer(pointer, i);
    const Json& item = value[i];
    reader.object(item, at, "a pose");
    Space::refuse_other_simplex(reader, item, at);
    reader.check_fields(item, at, fields);
    const Json* t = JsonReader::member(item, "t");
    if (t == nullptr) reader.fail(at + "/t", "missing required field (the pose's time)");
    TimedPoseOf<Pose> pose;
    pose.t = bounded(reader, *t, at + "/t");
    if (!poses.empty() && !(pose.t > poses.back().t)) {
      reader.fail(at + "/t", fmt::format("times must increase strictly: {} follows {}", number_text(pose.t),
                                         number_text(poses.back().t)));
    }
    const Json* matrix = JsonReader::member(item, "matrix");
    const Json* points = JsonReader::member(item, simplex);
    if (matrix != nullptr && points != nullptr) {
      reader.fail(at + "/" + simplex, fmt::format("give either \"matrix\" or \"{}\", not both", simplex));
    }
    if (matrix != nullptr) {
      pose.pose = read_matrix<Pose>(reader, *matrix, at + "/matrix");
    } else if (points != nullptr) {
      const typename Space::Simplex given = read_simplex<Pose>(reader, *points, at + "/" + simplex);
      if (degenerate<Pose>(given)) {
        reader.fail(at + "/" + simplex, fmt::format("the {} is degenerate (its points are {})", simplex, Space::kFlat));
      }
      pose.pose = compose(frame_of<Pose>(given), inverse(reference_frame));
    } else {
      reader.fail(at, fmt::format("a pose needs \"matrix\": {} or \"{}\": {} (the images of the reference {}'s "
                                  "points)",
                                  Space::kMatrixShape, simplex, Space::kPointsShape, simplex));
    }
    poses.push_back(pose);
  }
  return poses;
}

// The two dimensions.
#define PITA_POSE_READERS(Pose)                                                                                \
  template PoseSpace<Pose>::Simplex read_simplex<Pose>(const JsonReader&, const Json&, const std::string&);    \
  template Pose frame_of<Pose>(const PoseSpace<Pose>::Simplex&);                                               \
  template bool degenerate<Pose>(const PoseSpace<Pose>::Simplex&);                                             \
  template Pose read_matrix<Pose>(const JsonReader&, const Json&, const std::string&);                         \
  template PoseSpace<Pose>::Simplex read_reference<Pose>(const JsonReader&, const Json&, const std::string&);  \
  template std::vector<TimedPoseOf<Pose>> read_poses<Pose>(const JsonReader&, const Json&, const std::string&, \
                                                           const PoseSpace<Pose>::Simplex&, PoseMethod);       \
  template std::string missing_poses_reason<Pose>();                                                           \
  template PoseMethod read_pose_method_of<Pose>(const JsonReader&, const Json&, const std::string&);
PITA_POSE_READERS(Affine2)
PITA_POSE_READERS(Affine3)
#undef PITA_POSE_READERS

std::vector<ShapeOutline> builtin_outline(std::string_view name) {
  const auto closed = [](std::vector<Point> points) { return ShapeOutline{std::move(points), true, {}, {}}; };
  const auto open = [](std::vector<Point> points) { return ShapeOutline{std::move(points), false, {}, {}}; };
  if (name == "F") {
    return {closed({{0.0, 0.0},
                    {0.25, 0.0},
                    {0.25, 0.4},
                    {0.6, 0.4},
                    {0.6, 0.6},
                    {0.25, 0.6},
                    {0.25, 0.8},
                    {0.75, 0.8},
                    {0.75, 1.0},
                    {0.0, 1.0}})};
  }
  if (name == "house") return {closed({{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.6}, {0.5, 1.0}, {0.0, 0.6}})};
  if (name == "picture") {
    // A small framed picture (the "textured quad" of the SAM paper's Fig. 2,
    // as line art): frame, ground, a house with a door, a tree and the sun.
    std::vector<Point> sun;
    for (int i = 0; i < 24; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / 24.0;
      sun.push_back(Point{0.8, 0.58} + 0.08 * Point{std::cos(angle), std::sin(angle)});
    }
    return {closed({{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.75}, {0.0, 0.75}}),
            open({{0.0, 0.15}, {1.0, 0.15}}),
            closed({{0.12, 0.15}, {0.42, 0.15}, {0.42, 0.38}, {0.27, 0.52}, {0.12, 0.38}}),
            open({{0.24, 0.15}, {0.24, 0.28}, {0.3, 0.28}, {0.3, 0.15}}),
            open({{0.62, 0.15}, {0.62, 0.27}}),
            closed({{0.53, 0.27}, {0.71, 0.27}, {0.62, 0.46}}),
            closed(std::move(sun))};
  }
  return {closed({{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})};  // square
}

namespace {

// The shape kinds, in the order a shape's fields are looked at: a shape is one of them.
constexpr std::array<std::string_view, 5> kShapeKindFields{"polygon", "polyline", "triangle", "outline", "image"};

// The images of one list of shapes so far: how many, and their pixels in all.
struct ShapeImages {
  int count = 0;
  double pixels = 0.0;
};

// {"polygon": [[x, y], ...]} or {"polyline": ...}: 2 to kMaxShapePoints points.
void read_shape_points(const JsonReader& reader, const Json& given, const std::string& where, bool closed,
                       ShapeOutline& shape) {
  if (!given.is_array() || given.size() < 2 || given.size() > static_cast<std::size_t>(kMaxShapePoints)) {
    reader.fail(where,
                fmt::format("must be an array of 2 to {} points [x, y] (got {})", kMaxShapePoints, value_text(given)));
  }
  for (std::size_t j = 0; j < given.size(); ++j) {
    shape.points.push_back(PoseSpace<Affine2>::read_point(reader, given[j], element_pointer(where, j)));
  }
  shape.closed = closed;
}

// {"triangle": "reference"}: the reference triangle itself.
void read_shape_triangle(const JsonReader& reader, const Json& given, const std::string& where,
                         const std::array<Point, 3>& reference, ShapeOutline& shape) {
  if (!given.is_string() || given.get<std::string>() != "reference") {
    reader.fail(where, "must be \"reference\" (the reference triangle; got " + value_text(given) + ")");
  }
  shape.points.assign(reference.begin(), reference.end());
}

// {"outline": "F" | "house" | "square" | "picture"}: a builtin outline. Its
// parts after the first, in the shape's color, are returned: they follow the shape.
std::vector<ShapeOutline> read_shape_outline(const JsonReader& reader, const Json& given, const std::string& where,
                                             ShapeOutline& shape) {
  std::vector<ShapeOutline> parts = builtin_outline(reader.choice(given, where, kOutlineNames, kOutlineNames));
  shape.points = std::move(parts.front().points);
  shape.closed = parts.front().closed;
  std::vector<ShapeOutline> extra;
  for (std::size_t part = 1; part < parts.size(); ++part) {
    parts[part].color = shape.color;
    extra.push_back(std::move(parts[part]));
  }
  return extra;
}

// {"image": "picture.png", "box": [[x0, y0], [x1, y1]]} (PITA Sec. 7.1): the
// image file, within the limits of kMaxImages and kMaxImagePixels for the
// list, and the box it fills.
void read_shape_image(const JsonReader& reader, const Json& item, const Json& given, const std::string& at,
                      ShapeImages& images, ShapeOutline& shape) {
  const std::string where = at + "/image";
  if (++images.count > kMaxImages) {
    reader.fail(where, fmt::format("at most {} images in a scene", kMaxImages));
  }
  const std::string file = reader.string(given, where);
  try {
    shape.image = check_image_file(reader.file(), file, reader.options());
  } catch (const std::invalid_argument& error) {
    reader.fail(where, error.what());
  }
  shape.image->pointer = where;
  images.pixels += static_cast<double>(shape.image->width) * shape.image->height;
  if (images.pixels > kMaxImagePixels) {
    reader.fail(where, fmt::format("the images of these shapes have {:.0f} pixels in all, more than the limit of "
                                   "{:.0f} (8192 x 8192: each is decoded in memory, 4 bytes a pixel, once per "
                                   "drawing thread)",
                                   images.pixels, kMaxImagePixels));
  }
  const Json* box = JsonReader::member(item, "box");
  if (box == nullptr) {
    reader.fail(at + "/box",
                "missing required field (where the image goes: [[x0, y0], [x1, y1]], its "
                "lower-left and upper-right corners)");
  }
  if (!box->is_array() || box->size() != 2) {
    reader.fail(at + "/box", "must be [[x0, y0], [x1, y1]] (got " + value_text(*box) + ")");
  }
  const Point low = PoseSpace<Affine2>::read_point(reader, (*box)[0], at + "/box/0");
  const Point high = PoseSpace<Affine2>::read_point(reader, (*box)[1], at + "/box/1");
  if (!(low.real() < high.real() && low.imag() < high.imag())) {
    reader.fail(at + "/box", "the box must have x0 < x1 and y0 < y1 (got " + value_text(*box) + ")");
  }
  shape.points = {low, Point{high.real(), low.imag()}, high, Point{low.real(), high.imag()}};
  shape.closed = true;
}

// One shape of the list at `at`, by the one kind it gives; the parts of a
// builtin outline after its first go into `extra`.
ShapeOutline read_shape(const JsonReader& reader, const Json& item, const std::string& at,
                        const std::array<Point, 3>& reference, ShapeImages& images, std::vector<ShapeOutline>& extra) {
  reader.object(item, at, "a shape");
  reader.check_fields(item, at, kShapeKinds);
  ShapeOutline shape;
  if (const Json* color = JsonReader::member(item, "color")) {
    shape.color = reader.color(*color, at + "/color");
  }
  if (const Json* box = JsonReader::member(item, "box");
      box != nullptr && JsonReader::member(item, "image") == nullptr) {
    reader.fail(at + "/box", "\"box\" places an \"image\"; this shape has none");
  }
  int kinds = 0;
  for (const std::string_view kind : kShapeKindFields) {
    const Json* given = JsonReader::member(item, std::string(kind));
    if (given == nullptr) continue;
    const std::string where = at + "/" + std::string(kind);
    if (++kinds > 1) {
      reader.fail(where,
                  "a shape is one of \"polygon\", \"polyline\", \"triangle\", "
                  "\"outline\" or \"image\"; give only one");
    }
    if (kind == "image") {
      read_shape_image(reader, item, *given, at, images, shape);
    } else if (kind == "polygon" || kind == "polyline") {
      read_shape_points(reader, *given, where, kind == "polygon", shape);
    } else if (kind == "triangle") {
      read_shape_triangle(reader, *given, where, reference, shape);
    } else {
      extra = read_shape_outline(reader, *given, where, shape);
    }
  }
  if (kinds == 0) {
    reader.fail(at,
                "a shape needs \"polygon\", \"polyline\", \"triangle\": \"reference\", "
                "\"outline\": \"F\" | \"house\" | \"square\" | \"picture\", or \"image\" and \"box\"");
  }
  return shape;
}

}  // namespace

std::vector<ShapeOutline> read_shapes(const JsonReader& reader, const Json& value, const std::string& pointer,
                                      const std::array<Point, 3>& reference) {
  if (!value.is_array() || value.empty() || value.size() > static_cast<std::size_t>(kMaxShapes)) {
    reader.fail(pointer, fmt::format("must be an array of 1 to {} shapes (got {})", kMaxShapes, value_text(value)));
  }
  std::vector<ShapeOutline> shapes;
  ShapeImages images;
  for (std::size_t i = 0; i < value.size(); ++i) {
    std::vector<ShapeOutline> extra;
    shapes.push_back(read_shape(reader, value[i], element_pointer(pointer, i), reference, images, extra));
    for (ShapeOutline& part : extra) shapes.push_back(std::move(part));
  }
  return shapes;
}

}  // namespace pita::scene::detail
