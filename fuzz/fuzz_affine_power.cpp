// Bytes -> a 2D affinity A = [L | b] (six doubles) and a time t -> EAR
// (core/affine_power.hpp): the case selection, log, exp, A^t, the fixed point.
// The first byte chooses how the numbers are read: raw doubles (NaN, inf,
// subnormals, 1e+-300), a grid of multiples of 1/64 (exact eigenvalues 1 and
// -1, double eigenvalues, rotations by pi), or such a grid times 10^k,
// |k| <= 200 (the scales of C o B^-1 for poses at the scene limits).
//
// Must hold for any input: no crash and no UB; an affinity with a non-finite
// entry, or whose case is G3, is refused with NoRealLogarithm, and any other
// is accepted. On "tame" inputs (entries within 2^+-10, eigenvalue ratio at
// most about 1e6, |t| <= 4), where nothing can overflow, A^t, log A and the
// fixed point are finite, A^0 = I and A^1 = A. exp(log A) = A (to 1e-6; EAR's
// error is about 1e-14 there: docs/explanation/performance.md "Steady Affine Morphs: EAR against
// Eigen") only while log A is moderate (entries <= 64): near the S2 boundary
// (L = -rI plus an off-diagonal entry of 1e-260) G1's log is exactly right
// and of size 1e130, and exp(), Eigen's scaling and squaring, overflows to NaN
// on it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <Eigen/Core>

#include "core/affine_power.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace pita;
using Eigen::Matrix2d;
using Eigen::Vector2d;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  double raw() {
    std::array<std::uint8_t, 8> bytes{};
    for (std::uint8_t& b : bytes) b = byte();
    double x = 0.0;
    std::memcpy(&x, bytes.data(), sizeof x);
    return x;
  }
  double grid() {
    const auto high = byte(), low = byte();
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(high << 8 | low)) / 64.0;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

double max_abs(const Matrix2d& M) { return M.cwiseAbs().maxCoeff(); }

bool finite(const Affine2& X) { return X.L.allFinite() && X.b.allFinite(); }

// |X - Y| (entries) relative to Y's size.
double distance(const Affine2& X, const Affine2& Y) {
  const double size = 1.0 + max_abs(Y.L) + Y.b.cwiseAbs().maxCoeff();
  return std::max(max_abs(X.L - Y.L), (X.b - Y.b).cwiseAbs().maxCoeff()) / size;
}

bool tame(const Affine2& A, double t) {
  if (!finite(A) || !std::isfinite(t) || std::abs(t) > 4.0) return false;
  const double largest = max_abs(A.L);
  if (largest < 0x1p-10 || largest > 0x1p10 || A.b.cwiseAbs().maxCoeff() > 0x1p10) return false;
  return A.L.determinant() >= 1e-6 * largest * largest;  // eigenvalue ratio <= ~1e6
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  const int mode = in.byte() % 3;
  const int exponent = static_cast<int>(in.byte() % 201) - 100;  // mode 2: 10^(2 exponent)
  std::array<double, 7> x{};
  for (double& value : x) {
    value = mode == 0 ? in.raw() : in.grid();
    if (mode == 2) value *= std::pow(10.0, 2 * exponent);
  }
  Affine2 A;
  A.L << x[0], x[1], x[2], x[3];
  A.b << x[4], x[5];
  const double t = mode == 2 ? x[6] / std::pow(10.0, 2 * exponent) : x[6];

  const RootCase kase = select_case(A.L);
  PITA_FUZZ_CHECK(!name(kase).empty() && !description(kase).empty());
  if (A.L.allFinite()) {
    const Eigenvalues e = eigenvalues(A.L);
    (void)e;
    (void)fixed_point(A);
  }
  (void)linear_exp(A.L, t);

  const bool refused_case = !finite(A) || kase == RootCase::G3;
  try {
    const AffinePowers powers(A);
    PITA_FUZZ_CHECK(!refused_case);
    PITA_FUZZ_CHECK(powers.root_case() == kase);
    const Affine2 power = powers.at(t);
    const Affine2 with_b = powers.power_with_translation(t, A.b);
    const Affine2 generator = log(A);
    const Affine2 back = exp(generator);
    const Matrix2d log_L = linear_log(A.L);
    const Matrix2d power_L = linear_power(A.L, t);
    const Vector2d log_b = powers.log_translation(A.b);
    if (tame(A, t)) {
      PITA_FUZZ_CHECK(finite(power) && finite(with_b) && finite(generator));
      PITA_FUZZ_CHECK(log_L.allFinite() && power_L.allFinite() && log_b.allFinite());
      PITA_FUZZ_CHECK(distance(powers.at(0.0), Affine2::identity()) <= 1e-12);
      PITA_FUZZ_CHECK(distance(powers.at(1.0), A) <= 1e-6);
      PITA_FUZZ_CHECK(distance(power, with_b) <= 1e-6);
      if (max_abs(generator.L) <= 64.0 && generator.b.cwiseAbs().maxCoeff() <= 64.0) {
        PITA_FUZZ_CHECK(finite(back) && distance(back, A) <= 1e-6);
      }
    }
  } catch (const NoRealLogarithm& error) {
    PITA_FUZZ_CHECK(refused_case);
    PITA_FUZZ_CHECK(error.root_case() == RootCase::G3);
    PITA_FUZZ_CHECK(error.what()[0] != '\0');
  }
  return 0;
}
