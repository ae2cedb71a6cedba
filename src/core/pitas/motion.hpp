// The common interface of every interpolating motion: a prepared function of
// time. Preparation (twirls, control arrows, the -Pe constants) is done once
// per keyframe set; at(t) is then cheap and defined for every real t (values
// outside [a, c] extrapolate, Sec. 7.5).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "core/arrow.hpp"

namespace pita {

class Motion {
 public:
  virtual ~Motion() = default;
  // D(t). May throw MotionDomainError for isolated singular configurations.
  virtual Arrow at(double t) const = 0;
  // The global fixed point of a radially-perseverant motion (P7, PITA Eq. 35-36:
  // every point's acceleration is S (x - f)); nullopt for the other motions
  // and when f is at infinity (docs/paper-notes.md N40).
  virtual std::optional<Point> global_fixed_point() const { return std::nullopt; }
};

// Thrown when a motion does not exist for the given keyframes (for example the
// -Pe boundary-value problem with v_a + v_c = -2 v_b). The message says why.
class MotionDomainError : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

}  // namespace pita
