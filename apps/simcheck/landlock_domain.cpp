#include "landlock_domain.hpp"

#include "scratch_places.hpp"

#include <fcntl.h>
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
struct [[gnu::packed]] PathBeneath {
    std::uint64_t allowed_access = 0;
    std::int32_t parent_fd = -1;
};
constexpr unsigned create_ruleset_version = 1U << 0;  // LANDLOCK_CREATE_RULESET_VERSION
constexpr int rule_path_beneath = 1;                  // LANDLOCK_RULE_PATH_BENEATH
constexpr std::uint64_t write_file = 1U << 1;
constexpr std::uint64_t truncate = 1U << 14;
// Every right to change a file or a directory's entries (LANDLOCK_ACCESS_FS_
// WRITE_FILE, REMOVE_DIR, REMOVE_FILE, MAKE_CHAR ... MAKE_SYM, REFER,
// TRUNCATE): reading and executing are not handled, so stay allowed.
constexpr std::uint64_t all_writes = write_file | (1U << 4) | (1U << 5) | (1U << 6) | (1U << 7) | (1U << 8) |
                                     (1U << 9) | (1U << 10) | (1U << 11) | (1U << 12) | (1U << 13) | truncate;
constexpr std::uint64_t scope_abstract_unix_socket = 1U << 0;
constexpr std::uint64_t scope_signal = 1U << 1;
constexpr long first_abi_with_truncate = 3;
constexpr long first_abi_with_scopes = 6;

long landlock_abi() {
#ifdef SYS_landlock_create_ruleset
    static const long abi = syscall(SYS_landlock_create_ruleset, nullptr, 0, create_ruleset_version);
    return abi;
#else
    return -1;
#endif
}

#if defined(SYS_landlock_create_ruleset) && defined(SYS_landlock_add_rule) && defined(SYS_landlock_restrict_self)
// Lets the domain do `access` beneath `path` (async-signal-safe).
bool allow_beneath(int ruleset, const char* path, std::uint64_t access) {
    const int directory = open(path, O_PATH | O_CLOEXEC | O_DIRECTORY);
    if (directory < 0) return true;  // not there: nothing to allow
    const PathBeneath rule{access, directory};
    const bool added = syscall(SYS_landlock_add_rule, ruleset, rule_path_beneath, &rule, 0) == 0;
    close(directory);
    return added;
}
#endif

}  // namespace

bool landlock_scopes_signals() { return landlock_abi() >= first_abi_with_scopes; }

bool landlock_limits_writes() { return landlock_abi() >= first_abi_with_truncate; }

LandlockDomain::LandlockDomain() : writable_(scratch_places()), abi_(landlock_abi()) {}

bool LandlockDomain::enter() const {
#if defined(SYS_landlock_create_ruleset) && defined(SYS_landlock_add_rule) && defined(SYS_landlock_restrict_self)
    RulesetAttributes attributes;
    if (abi_ >= first_abi_with_truncate) attributes.handled_access_fs = all_writes;
    if (abi_ >= first_abi_with_scopes) attributes.scoped = scope_signal | scope_abstract_unix_socket;
    if (attributes.handled_access_fs == 0 && attributes.scoped == 0) return true;
    const int ruleset = static_cast<int>(syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0));
    if (ruleset < 0) return false;
    bool ready = true;
    if (attributes.handled_access_fs != 0) {
        // c_str() only reads: nothing is allocated here.
        for (const std::string& place : writable_) ready = ready && allow_beneath(ruleset, place.c_str(), all_writes);
        ready = ready && allow_beneath(ruleset, "/dev", write_file | truncate) &&
                allow_beneath(ruleset, "/proc", write_file | truncate);
    }
    ready =
        ready && prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && syscall(SYS_landlock_restrict_self, ruleset, 0) == 0;
    close(ruleset);
    return ready;
#else
    return true;
#endif
}

}  // namespace simcheck
