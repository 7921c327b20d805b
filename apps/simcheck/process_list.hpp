#pragma once
// The processes running now, as /proc lists them (not their threads).

#include <dirent.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
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

struct ProcessStat {
    char state = 0;
    pid_t parent = 0;
    pid_t group = 0;
};

// From /proc/PID/stat, after the command's closing parenthesis (the command
// may itself hold spaces and parentheses).
inline bool read_process_stat(const char* pid, ProcessStat& stat) {
    std::ifstream file(std::string("/proc/") + pid + "/stat");
    std::string line;
    if (!std::getline(file, line)) return false;
    const std::size_t name_end = line.rfind(')');
    if (name_end == std::string::npos) return false;
    long parent = 0, group = 0;
    if (std::sscanf(line.c_str() + name_end + 1, " %c %ld %ld", &stat.state, &parent, &group) != 3) return false;
    stat.parent = static_cast<pid_t>(parent);
    stat.group = static_cast<pid_t>(group);
    return true;
}

// visit(pid) for each process of a graded program: its user's, where it
// runs as a user of its own (`user` not 0), else its process group's.
template <typename Visit>
void for_each_program_process(uid_t user, pid_t group, Visit&& visit) {
    for_each_process([&](const char* pid) {
        if (user != 0) {
            if (process_owner(pid) != user) return;
        } else {
            ProcessStat stat;
            if (!read_process_stat(pid, stat) || stat.group != group) return;
        }
        visit(pid);
    });
}

}  // namespace simcheck
