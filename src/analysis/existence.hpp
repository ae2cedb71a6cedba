// Where a SAM exists (SAM paper Sec. 5, SAM Eq. 4, Fig. 6): the linear parts
// L = R(a) diag(1/s, s), a rotation by a after a stretch by 1/s and s,
// classified by EAR's case selection (appendix A, Algorithm 1).
#pragma once

#include <vector>

namespace pita::analysis {

// Whether R(a) diag(1/s, s) has a real logarithm (a SAM): not case G3.
bool sam_exists(double a, double s);

// SAM Eq. 4: the boundary |a| = acos(-2s/(s^2 + 1)) of the existence region.
double existence_boundary(double s);

// The trapezoid |a| < (1 + s) pi / 2 that Sec. 5 shows inside the region.
double existence_trapezoid(double s);

// A grid of cells over a in [-pi, pi] (columns) and s in (0, 1] (rows),
// each classified at its centre; no_sam[row * columns + column].
struct ExistenceGrid {
  int columns = 0;
  int rows = 0;
  std::vector<bool> no_sam;
};
ExistenceGrid classify_existence(int columns, int rows);

}  // namespace pita::analysis
