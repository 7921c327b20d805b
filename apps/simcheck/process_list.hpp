#pragma once
// The processes running now, as /proc lists them (not their threads).

#include <dirent.h>

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

}  // namespace simcheck
