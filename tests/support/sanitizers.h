#pragma once
// Whether this test binary runs under AddressSanitizer (scripts/test-sanitizers.sh) or
// ThreadSanitizer (scripts/test-tsan.sh), several times slower than Release: long runs there check
// the same code paths with fewer steps or bodies.

namespace test_support {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace test_support
