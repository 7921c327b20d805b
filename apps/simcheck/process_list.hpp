#pragma once
// The processes running now, as /proc lists them (not their threads).

#include <dirent.h>
#include <sys/stat.h>

#include <optional>
#include <string>

namespace simcheck {

// visit(pid) for each process, `pid` its directory's name in /proc.
template <typename Visit>
void for_each_process(Visit&& visit) {
    DIR* proc = opendir("/proc");
    if (!proc) return;
    while (const dirent* entry = readdir(proc)) {
        if (entry->d_name[0] >= '0' && entry->d_name[0] <= '9') visit(entry->d_name);
    }
    closedir(proc);
}

// The user process `pid` (its /proc directory's name) runs as, if it is
// still there.
inline std::optional<uid_t> process_owner(const char* pid) {
    struct stat info {};
    if (stat((std::string("/proc/") + pid).c_str(), &info) != 0) return std::nullopt;
    return info.st_uid;
}

}  // namespace simcheck
