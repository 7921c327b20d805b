#pragma once
// Whether this build's apps offer their large blocks to transparent huge
// pages (large_blocks.cpp replaces operator new): on Linux, and not under a
// sanitizer, whose own operators stay.

#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define PARTICLESIM_SANITIZED_OPERATORS
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PARTICLESIM_SANITIZED_OPERATORS
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE) && !defined(PARTICLESIM_SANITIZED_OPERATORS)
#define PARTICLESIM_LARGE_BLOCKS_OFFERED 1
#else
#define PARTICLESIM_LARGE_BLOCKS_OFFERED 0
#endif
