#include "render/solid_faces.hpp"

#include <algorithm>
#include <utility>

#include <Eigen/LU>

namespace pita::render {

namespace {

using Eigen::Vector3d;

// The unit normal of a polygon of space, or zero.
Vector3d newell_normal(const std::vector<Vector3d>& points) {
  const Vector3d n = area_vector(points);
  const double length = n.norm();
  return length > 0.0 ? Vector3d(n / length) : Vector3d::Zero();
}

Color shaded(Color c, double shade) { return Color{c.r * shade, c.g * shade, c.b * shade, c.a}; }

}  // namespace

Vector3d area_vector(const std::vector<Vector3d>& points) {
  Vector3d n = Vector3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vector3d& a = points[i];
    const Vector3d& b = points[(i + 1) % points.size()];
    n += Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                  (a.x() - b.x()) * (a.y() + b.y()));
  }
  return 0.5 * n;  // Newell's sum is twice the area vector
}

void add_solid_faces(const PosePanel<Affine3>& panel, const scene::Solid& solid, const Affine3& pose,
                     const std::optional<Color>& fill, const LineStyle& line, double opacity, int index,
                     std::vector<Face>& out) {
  const Projection& projection = panel.view();
  const bool mirrored = pose.L.determinant() < 0.0;
  double solid_depth = 0.0;
  for (const Vector3d& v : solid.vertices) solid_depth += projection.depth(apply(pose, v));
  solid_depth /= static_cast<double>(solid.vertices.size());
  const int body = out.empty() ? 0 : out.back().body + 1;
  for (const std::vector<int>& face : solid.faces) {
    std::vector<Vector3d> points;
    std::vector<Point> image;
    double depth = 0.0;
    for (const int k : face) {
      const Vector3d x = apply(pose, solid.vertices[static_cast<std::size_t>(k)]);
      points.push_back(x);
      image.push_back(panel.image(x));
      depth += projection.depth(x);
    }
    depth /= static_cast<double>(face.size());
    LineStyle edge = line;
    edge.opacity *= opacity;
    Face& drawn = out.emplace_back();
    drawn.solid_depth = solid_depth;
    drawn.depth = depth;
    drawn.index = index;
    drawn.body = body;
    drawn.opacity = opacity;
    if (fill) {
      Vector3d normal = newell_normal(points);
      if (mirrored) normal = -normal;
      const Color color = shaded(*fill, face_shade(normal, projection));
      drawn.shape = FilledPath{{std::move(image)}, color, opacity, edge};
    } else {
      drawn.shape = Polyline{std::move(image), true, edge};
    }
    drawn.world = std::move(points);
  }
}

void paint_faces(PosePanel<Affine3>& panel, std::vector<Face> faces, bool moving) {
  if (panel.figure().camera.shadow) {
    for (std::size_t i = 0; i < faces.size();) {
      std::size_t end = i;
      std::vector<std::vector<Vector3d>> body;
      for (; end < faces.size() && faces[end].body == faces[i].body; ++end) body.push_back(faces[end].world);
      panel.cast_shadow(faces[i].index, std::move(body), faces[i].opacity, moving);
      i = end;
    }
  }
  std::stable_sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
    return a.solid_depth != b.solid_depth ? a.solid_depth > b.solid_depth : a.depth > b.depth;
  });
  for (Face& face : faces) panel.push(face.index, std::move(face.shape), moving);
}

}  // namespace pita::render
