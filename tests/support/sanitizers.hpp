// Whether the tests run under AddressSanitizer (scripts/test.sh --sanitize):
// there the slowest random samples are smaller, so that CI stays within its
// time (docs/explanation/build-time.md), and what ASan cannot do (a ulimit
// -v) is skipped. Every test still runs.
#pragma once

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

}  // namespace pita::test
