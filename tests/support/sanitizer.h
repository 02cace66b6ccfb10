// Whether this build runs under AddressSanitizer, as g++ (__SANITIZE_ADDRESS__) and clang
// (__has_feature) each say it.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define POOL_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define POOL_UNDER_ASAN 1
#endif
#endif
#ifndef POOL_UNDER_ASAN
#define POOL_UNDER_ASAN 0
#endif
