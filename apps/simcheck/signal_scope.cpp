#include "signal_scope.hpp"

#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdint>

namespace simcheck {

namespace {

// Landlock's interface (linux/landlock.h), written out: Debian 12's kernel
// headers predate the scopes.
struct RulesetAttributes {
    std::uint64_t handled_access_fs = 0;
    std::uint64_t handled_access_net = 0;
    std::uint64_t scoped = 0;
};
constexpr unsigned create_ruleset_version = 1U << 0;  // LANDLOCK_CREATE_RULESET_VERSION
constexpr std::uint64_t scope_abstract_unix_socket = 1U << 0;
constexpr std::uint64_t scope_signal = 1U << 1;
constexpr long first_abi_with_scopes = 6;

long landlock_abi() {
#ifdef SYS_landlock_create_ruleset
    return syscall(SYS_landlock_create_ruleset, nullptr, 0, create_ruleset_version);
#else
    return -1;
#endif
}

}  // namespace

bool can_confine_signals() {
    static const bool can = landlock_abi() >= first_abi_with_scopes;
    return can;
}

bool confine_signals() {
#if defined(SYS_landlock_create_ruleset) && defined(SYS_landlock_restrict_self)
    RulesetAttributes attributes;
    attributes.scoped = scope_signal | scope_abstract_unix_socket;
    const long ruleset = syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0);
    if (ruleset < 0) return false;
    const bool confined = prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 &&
                          syscall(SYS_landlock_restrict_self, static_cast<int>(ruleset), 0) == 0;
    close(static_cast<int>(ruleset));
    return confined;
#else
    return false;
#endif
}

}  // namespace simcheck
