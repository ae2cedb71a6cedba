#include "core/sam_velocity_field.hpp"

namespace pita {

SamVelocityField::SamVelocityField(const Affine2& A)
    : powers_(A), generator_(powers_.log()), fixed_point_(pita::fixed_point(A)) {}

SamVelocityField SamVelocityField::between(const Affine2& B, const Affine2& C) {
  return SamVelocityField(compose(C, inverse(B)));
}

}  // namespace pita
