#include "own_user.hpp"

#include "process_list.hpp"
#include "scratch_places.hpp"

#include <grp.h>
#include <linux/capability.h>
#include <pwd.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace simcheck {

namespace {

// Where the ids are taken from: a block that no distribution hands out
// (Debian leaves ids from 65536 on to local use; systemd's container
// ranges end below 0x70000000), or, where only the first 65536 ids are
// mapped (a container with a user namespace), Debian's reserved 65000 to
// 65533.
constexpr uid_t first_wide_id = 0x70000000;
constexpr uid_t first_narrow_id = 65000;
constexpr uid_t ids_in_block = 534;

// Whether every id of [first, first + count) is mapped in /proc/self/MAP.
bool ids_mapped(const char* map, uid_t first, uid_t count) {
    std::ifstream in(std::string("/proc/self/") + map);
    unsigned long inside = 0, outside = 0, length = 0;
    while (in >> inside >> outside >> length) {
        if (inside <= first && first + static_cast<unsigned long>(count) <= inside + length) return true;
    }
    return false;
}

std::optional<uid_t> first_own_id() {
    static const std::optional<uid_t> first = []() -> std::optional<uid_t> {
        for (const uid_t candidate : {first_wide_id, first_narrow_id}) {
            if (ids_mapped("uid_map", candidate, ids_in_block) && ids_mapped("gid_map", candidate, ids_in_block))
                return candidate;
        }
        return std::nullopt;
    }();
    return first;
}

bool has_effective_capabilities(std::initializer_list<int> capabilities) {
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2]{};
    if (syscall(SYS_capget, &header, data) != 0) return false;
    for (const int capability : capabilities) {
        if (((data[capability / 32].effective >> (capability % 32)) & 1U) == 0) return false;
    }
    return true;
}

bool named_in_passwd_or_group(uid_t id) {
    std::vector<char> buffer(1 << 16);
    passwd user{};
    passwd* found_user = nullptr;
    group group_entry{};
    group* found_group = nullptr;
    getpwuid_r(id, &user, buffer.data(), buffer.size(), &found_user);
    if (found_user) return true;
    getgrgid_r(id, &group_entry, buffer.data(), buffer.size(), &found_group);
    return found_group != nullptr;
}

std::set<uid_t> users_with_processes() {
    std::set<uid_t> users;
    for_each_process([&](const char* pid) {
        if (const std::optional<uid_t> owner = process_owner(pid)) users.insert(*owner);
    });
    return users;
}

std::mutex claimed_mutex;
std::set<uid_t> claimed;

}  // namespace

int kept_capability() {
    static const int capability =
        has_effective_capabilities({CAP_DAC_READ_SEARCH}) ? CAP_DAC_READ_SEARCH : CAP_DAC_OVERRIDE;
    return capability;
}

bool can_run_as_own_users() {
    if (geteuid() != 0 || !first_own_id()) return false;
    if (prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_IS_SET, CAP_DAC_READ_SEARCH, 0, 0) < 0) return false;
    return has_effective_capabilities({CAP_SETUID, CAP_SETGID, CAP_CHOWN, kept_capability()});
}

std::optional<uid_t> claim_own_user() {
    const std::optional<uid_t> first = first_own_id();
    if (!first) return std::nullopt;
    const std::set<uid_t> busy = users_with_processes();
    const std::lock_guard<std::mutex> lock(claimed_mutex);
    for (uid_t id = *first; id < *first + ids_in_block; ++id) {
        if (claimed.count(id) != 0 || busy.count(id) != 0 || named_in_passwd_or_group(id)) continue;
        claimed.insert(id);
        return id;
    }
    return std::nullopt;
}

void release_own_user(uid_t user) {
    if (users_with_processes().count(user) != 0) return;
    const std::lock_guard<std::mutex> lock(claimed_mutex);
    claimed.erase(user);
}

int remove_files_of(uid_t user, const std::string& keep) {
    namespace fs = std::filesystem;
    struct stat keep_info {};
    const bool keeping = stat(keep.c_str(), &keep_info) == 0;
    int removed = 0;
    // A link is removed itself, never followed.
    for_each_entry_owned_by(user, [&](const fs::path& entry, const struct stat& info) {
        if (keeping && info.st_dev == keep_info.st_dev && info.st_ino == keep_info.st_ino) return;
        std::error_code ignored;
        fs::remove_all(entry, ignored);
        ++removed;
    });
    return removed;
}

bool become_own_user(uid_t user, int capability) {
    // Raw system calls: they change this thread alone, which in a child
    // after fork is the whole process (glibc's wrappers would signal the
    // parent's other threads, which the child does not have).
    if (prctl(PR_SET_KEEPCAPS, 1, 0, 0, 0) != 0) return false;
    if (syscall(SYS_setgroups, 0, nullptr) != 0) return false;
    if (syscall(SYS_setresgid, user, user, user) != 0) return false;
    if (syscall(SYS_setresuid, user, user, user) != 0) return false;
    // The effective set was emptied with the user; permitted kept (KEEPCAPS).
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2]{};
    static_assert(CAP_DAC_READ_SEARCH < 32 && CAP_DAC_OVERRIDE < 32);
    const unsigned kept = 1U << static_cast<unsigned>(capability);
    data[0].effective = data[0].permitted = data[0].inheritable = kept;
    if (syscall(SYS_capset, &header, data) != 0) return false;
    if (prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_RAISE, capability, 0, 0) != 0) return false;
    return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0;
}

}  // namespace simcheck
