#pragma once
// PARTICLESIM_ASSERT(condition, message): an invariant the code relies on,
// checked at the seams between stages in a validating build
// (-DPARTICLESIM_VALIDATE=ON, the `validate` preset; the sanitized test pass
// too) and free otherwise: the condition is then not evaluated, only compiled.
// A broken invariant aborts at once with the file, line, condition and
// message, instead of showing up later as a wrong byte three files away.
//
// Checks that cost a pass of their own (a recomputation, a permutation
// check) go inside `if constexpr (particlesim::validating)`.

#ifndef PARTICLESIM_VALIDATE
#define PARTICLESIM_VALIDATE 0
#endif

namespace particlesim {

inline constexpr bool validating = PARTICLESIM_VALIDATE != 0;

[[noreturn]] void invariant_broken(const char* condition, const char* message, const char* file, int line) noexcept;

}  // namespace particlesim

#if PARTICLESIM_VALIDATE
#define PARTICLESIM_ASSERT(condition, message) \
    ((condition) ? void(0) : ::particlesim::invariant_broken(#condition, message, __FILE__, __LINE__))
#else
#define PARTICLESIM_ASSERT(condition, message) static_cast<void>(sizeof(static_cast<bool>(condition)))
#endif
