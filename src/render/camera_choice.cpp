#include "render/camera_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/canvas_geometry.hpp"
#include "render/solid_faces.hpp"

namespace pita::render {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The area vectors of every face of every solid at every pose, one list per
// posed solid (the faces do not change as the camera turns).
std::vector<std::vector<Eigen::Vector3d>> posed_faces(const std::vector<scene::Solid>& solids,
                                                      const std::vector<Affine3>& poses) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (const Affine3& pose : poses) {
    for (const scene::Solid& solid : solids) {
      std::vector<Eigen::Vector3d>& faces = out.emplace_back();
      for (const std::vector<int>& face : solid.faces) {
        std::vector<Eigen::Vector3d> points;
        for (const int k : face) points.push_back(apply(pose, solid.vertices[static_cast<std::size_t>(k)]));
        faces.push_back(area_vector(points));
      }
    }
  }
  return out;
}

// The poses without repeats (a sample at a pose's knot is that pose).
std::vector<Affine3> distinct_poses(const std::vector<Affine3>& poses) {
  std::vector<Affine3> out;
  for (const Affine3& pose : poses) {
    const double scale = 1.0 + pose.L.norm() + pose.b.norm();
    const bool repeat = std::any_of(out.begin(), out.end(), [&](const Affine3& o) {
      return (o.L - pose.L).norm() + (o.b - pose.b).norm() <= 1e-9 * scale;
    });
    if (!repeat) out.push_back(pose);
  }
  return out;
}

double openness_of(const std::vector<Eigen::Vector3d>& faces, const Eigen::Vector3d& d) {
  double seen = 0.0, total = 0.0;
  for (const Eigen::Vector3d& a : faces) {
    seen += std::abs(a.dot(d));
    total += a.norm();
  }
  return total > 0.0 ? seen / total : 0.0;
}

}  // namespace

Eigen::Vector3d towards_eye(double azimuth, double elevation) {
  const double a = azimuth * kDegree, e = elevation * kDegree;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

double openness(const scene::Solid& solid, const Affine3& pose, const Eigen::Vector3d& d) {
  return openness_of(posed_faces({solid}, {pose}).front(), d);
}

scene::Camera chosen_camera(const scene::Camera& given, const std::vector<scene::Solid>& solids,
                            const std::vector<Affine3>& poses) {
  const std::vector<std::vector<Eigen::Vector3d>> faces = posed_faces(solids, poses);
  if (faces.empty()) return given;
  struct Tried {
    double azimuth, elevation, score;
  };
  const auto score = [&faces](const Eigen::Vector3d& d) {
    double least = std::numeric_limits<double>::infinity();
    for (const auto& solid : faces) least = std::min(least, openness_of(solid, d));
    return least;
  };
  std::vector<Tried> tried;
  double best = -1.0;
  for (double elevation = kLowestElevation; elevation <= kHighestElevation + 1e-9; elevation += kAzimuthStep) {
    for (double azimuth = -180.0; azimuth < 180.0 - 1e-9; azimuth += kAzimuthStep) {
      const double least = score(towards_eye(azimuth, elevation));
      tried.push_back({azimuth, elevation, least});
      best = std::max(best, least);
    }
  }
  const Eigen::Vector3d wanted = towards_eye(given.azimuth, given.elevation);
  const std::vector<Affine3> distinct = distinct_poses(poses);
  if (score(wanted) >= kNearBest * best && most_hidden(solids, distinct, wanted) <= kMostHidden) return given;
  // The good enough directions, nearest the given one first.
  std::vector<std::pair<double, const Tried*>> good;
  for (const Tried& t : tried) {
    if (t.score >= kNearBest * best) good.emplace_back(towards_eye(t.azimuth, t.elevation).dot(wanted), &t);
  }
  std::stable_sort(good.begin(), good.end(), [](const auto& a, const auto& b) { return a.first > b.first + 1e-12; });
  const Tried* chosen = nullptr;
  double least_hidden = std::numeric_limits<double>::infinity();
  for (const auto& [cosine, t] : good) {
    const double hidden = most_hidden(solids, distinct, towards_eye(t->azimuth, t->elevation));
    if (hidden < least_hidden) {
      least_hidden = hidden;
      chosen = t;
    }
    if (hidden <= kMostHidden) break;
  }
  scene::Camera camera = given;
  if (chosen != nullptr) {
    camera.azimuth = chosen->azimuth;
    camera.elevation = chosen->elevation;
  }
  return camera;
}

double most_hidden(const std::vector<scene::Solid>& solids, const std::vector<Affine3>& poses,
                   const Eigen::Vector3d& d) {
  // An image plane across d (z is never along d: the elevations tried stop short of 90).
  Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(d);
  if (right.norm() < 1e-12) right = Eigen::Vector3d::UnitX().cross(d);
  right.normalize();
  const Eigen::Vector3d up = d.cross(right);
  struct Body {
    double depth = 0.0;  // the mean of x . d over its vertices: larger is nearer the eye
    std::vector<std::vector<Point>> faces;
  };
  std::vector<Body> bodies;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Affine3& pose : distinct_poses(poses)) {
    for (const scene::Solid& solid : solids) {
      Body& body = bodies.emplace_back();
      for (const Eigen::Vector3d& v : solid.vertices) body.depth += apply(pose, v).dot(d);
      body.depth /= static_cast<double>(std::max<std::size_t>(solid.vertices.size(), 1));
      for (const std::vector<int>& face : solid.faces) {
        std::vector<Point>& image = body.faces.emplace_back();
        for (const int k : face) {
          const Eigen::Vector3d x = apply(pose, solid.vertices[static_cast<std::size_t>(k)]);
          image.emplace_back(x.dot(right), x.dot(up));
          x0 = std::min(x0, image.back().real()), x1 = std::max(x1, image.back().real());
          y0 = std::min(y0, image.back().imag()), y1 = std::max(y1, image.back().imag());
        }
      }
    }
  }
  if (bodies.size() < 2 || !(x1 > x0) || !(y1 > y0)) return 0.0;
  std::stable_sort(bodies.begin(), bodies.end(), [](const Body& a, const Body& b) { return a.depth < b.depth; });
  const double cell = std::max(x1 - x0, y1 - y0) / kHiddenRaster;
  const int columns = static_cast<int>(std::ceil((x1 - x0) / cell)) + 1;
  const int rows = static_cast<int>(std::ceil((y1 - y0) / cell)) + 1;
  const std::size_t cells = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
  std::vector<int> owner(cells, -1), mark(cells, -1);
  std::vector<int> painted(bodies.size(), 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int id = static_cast<int>(b);
    for (const std::vector<Point>& face : bodies[b].faces) {
      double fx0 = face.front().real(), fx1 = fx0, fy0 = face.front().imag(), fy1 = fy0;
      for (const Point p : face) {
        fx0 = std::min(fx0, p.real()), fx1 = std::max(fx1, p.real());
        fy0 = std::min(fy0, p.imag()), fy1 = std::max(fy1, p.imag());
      }
      const int c0 = static_cast<int>(std::floor((fx0 - x0) / cell)),
                c1 = static_cast<int>(std::floor((fx1 - x0) / cell));
      const int r0 = static_cast<int>(std::floor((fy0 - y0) / cell)),
                r1 = static_cast<int>(std::floor((fy1 - y0) / cell));
      for (int r = std::max(r0, 0); r <= std::min(r1, rows - 1); ++r) {
        for (int c = std::max(c0, 0); c <= std::min(c1, columns - 1); ++c) {
          if (!inside(face, Point(x0 + (c + 0.5) * cell, y0 + (r + 0.5) * cell))) continue;
          const std::size_t at =
              static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c);
          if (mark[at] != id) {
            mark[at] = id;
            ++painted[b];
          }
          owner[at] = id;
        }
      }
    }
  }
  std::vector<int> seen(bodies.size(), 0);
  for (const int id : owner) {
    if (id >= 0) ++seen[static_cast<std::size_t>(id)];
  }
  double most = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (painted[b] > 0) most = std::max(most, 1.0 - static_cast<double>(seen[b]) / painted[b]);
  }
  return most;
}

}  // namespace pita::render
