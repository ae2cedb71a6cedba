// Whether the tests run under AddressSanitizer (scripts/test.sh --sanitize):
// there the slowest random samples are smaller, so that CI stays within its
// time (docs/explanation/build-time.md), and what ASan cannot do (a ulimit
// -v) is skipped. Every test still runs.
#pragma once

#include <cstddef>

namespace pita::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif
#else
inline constexpr bool kUnderSanitizers = false;
#endif

// `release` random cases, or `sanitized` under the sanitizers.
inline constexpr int sample_size(int release, int sanitized) { return kUnderSanitizers ? sanitized : release; }

// Of the items of a list in order, whether item `i` is tested: every one, or
// under the sanitizers every `stride`-th (the first, then every stride-th
// after it), for tests that go through every scene of scenes/ (the goldens'
// tests draw each one under the sanitizers already).
inline constexpr bool in_sample(std::size_t i, std::size_t stride) { return !kUnderSanitizers || i % stride == 0; }

}  // namespace pita::test
