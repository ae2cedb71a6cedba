// Uses pita::core from an installed pita: the P6 (La-LP) motion through three
// timed keyframes (the PITA paper's Fig. 1), and a real power A^t of an
// affinity by the EAR algorithm (the SAM paper, appendix A).
#include <cstdio>
#include <vector>

#include <pita/core/affine_power.hpp>
#include <pita/core/pitas/registry.hpp>

int main() {
  // The keyframes A, B, C at the knots 0, 0.5, 1: start point p, magnitude m, winding w.
  const std::vector<pita::Keyframe> keyframes = {
      {0.0, {pita::make_point(0, 0), 1.0, 0.4}},
      {0.5, {pita::make_point(3, 1.5), 0.6, 2.0}},
      {1.0, {pita::make_point(6, 0), 1.2, 3.5}},
  };
  const auto motion = pita::make_motion(pita::Method::P6, keyframes);
  for (const double t : {0.25, 0.5}) {
    const pita::Arrow frame = motion->at(t);
    std::printf("P6 t=%.17g p=(%.17g, %.17g) m=%.17g w=%.17g\n", t, frame.p.real(), frame.p.imag(), frame.m,
                frame.w);
  }

  // A: x -> 4 R(90 degrees) (x - c) + c, c = (1, 2): a rotation by a quarter turn with scaling 4 about c.
  pita::Affine2 A;
  A.L << 0, -4, 4, 0;
  const Eigen::Vector2d c(1, 2);
  A.b = c - A.L * c;
  const double t = 0.5;
  const pita::Affine2 root = pita::affine_power(A, t);
  std::printf("A^%g L=[[%.17g, %.17g], [%.17g, %.17g]] b=[%.17g, %.17g]\n", t, root.L(0, 0), root.L(0, 1),
              root.L(1, 0), root.L(1, 1), root.b(0), root.b(1));
  return 0;
}
