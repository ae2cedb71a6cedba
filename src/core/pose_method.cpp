#include "core/pose_method.hpp"

#include <array>

namespace pita {

namespace {

constexpr std::array<PoseMethodInfo, 14> kPoseMethods = {{
    {PoseMethod::sam, "SAM", "Steady Affine Morph", 2, 2, true},
    {PoseMethod::poly_sam, "polySAM", "polySAM (a SAM per span)", 2, 1000, true},
    {PoseMethod::bezier_sam, "bezier-SAM", "Bezier SAM", 3, 4, true},
    {PoseMethod::biarc_sam, "biarc-SAM", "SAM bi-arc retrofit", 3, 3, true},
    {PoseMethod::linear, "linear", "linear interpolation of the matrices", 2, 1000, true},
    {PoseMethod::four_point, "four-point-SAM", "polySAM of the four-point subdivision", 3, 1000, true},
    {PoseMethod::p4, "P4", "Bezier of steady affine morphs (the BiSAM of affine poses)", 3, 1000, true, "Be-LP"},
    {PoseMethod::p5, "P5", "Lagrange blend of the poses' logs about the centroid of their origins", 3, 1000, true,
     "He-LP"},
    {PoseMethod::p6, "P6", "Lagrange form with steady affine morphs and transports", 3, 1000, true, "La-LP"},
    {PoseMethod::p9, "P9", "Neville form: a steady affine morph of two steady affine morphs", 3, 1000, true, "Ne-LP"},
    {PoseMethod::rarap, "rARAP", "ARAP with the barycentre moved on a line (Fig. 2b)", 2, 2, false},
    {PoseMethod::asap, "ASAP", "log spiral with a linear residue (Fig. 2c)", 2, 2, false},
    {PoseMethod::tsb, "TSB", "blend of the triangle sides' log spirals (Fig. 2d)", 2, 2, false},
    {PoseMethod::alexa, "Alexa", "Alexa's log-matrix blend e^((1-u) log B + u log C) (Figs. 4, 5)", 2, 2, false},
}};

}  // namespace

std::span<const PoseMethodInfo> all_pose_methods() { return kPoseMethods; }

const PoseMethodInfo& info(PoseMethod method) {
  for (const PoseMethodInfo& entry : kPoseMethods) {
    if (entry.method == method) return entry;
  }
  return kPoseMethods[0];
}

}  // namespace pita
