#include "render/camera_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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
  if (score(wanted) >= kNearBest * best) return given;
  scene::Camera camera = given;
  double nearest = -2.0;  // the largest cosine to the given direction
  for (const Tried& t : tried) {
    if (t.score < kNearBest * best) continue;
    const double cosine = towards_eye(t.azimuth, t.elevation).dot(wanted);
    if (cosine > nearest + 1e-12) {
      nearest = cosine;
      camera.azimuth = t.azimuth;
      camera.elevation = t.elevation;
    }
  }
  return camera;
}

}  // namespace pita::render
