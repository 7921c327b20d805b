#include "ipc_objects.hpp"

#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace simcheck {
namespace {

// visit(value) for each object in one /proc/sysvipc table whose owner
// ("uid") or maker ("cuid") is `user`, where value(name) is the object's
// number in the column of that name (0 where the table has no such
// column). Columns are found by their header's names, which every kernel
// since 2.6 writes.
template <typename Visit>
void for_each_object_of(const char* table, uid_t user, Visit&& visit) {
    std::ifstream in(table);
    std::string line;
    if (!std::getline(in, line)) return;
    std::vector<std::string> header;
    std::istringstream names(line);
    for (std::string name; names >> name;) header.push_back(name);
    const auto column = [&](const std::string& name) {
        for (std::size_t k = 0; k < header.size(); ++k)
            if (header[k] == name) return static_cast<int>(k);
        return -1;
    };
    const int owner_at = column("uid"), maker_at = column("cuid");
    if (owner_at < 0 || maker_at < 0) return;
    const std::string name = std::to_string(user);
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::istringstream values(line);
        for (std::string value; values >> value;) fields.push_back(value);
        if (fields.size() < header.size()) continue;
        if (fields[static_cast<std::size_t>(owner_at)] != name && fields[static_cast<std::size_t>(maker_at)] != name)
            continue;
        visit([&](const std::string& column_name) -> std::int64_t {
            const int at = column(column_name);
            return at < 0 ? 0 : std::strtoll(fields[static_cast<std::size_t>(at)].c_str(), nullptr, 10);
        });
    }
}

// The ids of `user`'s objects in one table; `id_column` is "shmid", "semid" or "msqid".
std::vector<int> ids_of(const char* table, const std::string& id_column, uid_t user) {
    std::vector<int> ids;
    for_each_object_of(table, user, [&](const auto& value) { ids.push_back(static_cast<int>(value(id_column))); });
    return ids;
}

}  // namespace

int remove_ipc_objects_of(uid_t user) {
    const std::vector<int> segments = ids_of("/proc/sysvipc/shm", "shmid", user);
    const std::vector<int> semaphores = ids_of("/proc/sysvipc/sem", "semid", user);
    const std::vector<int> queues = ids_of("/proc/sysvipc/msg", "msqid", user);
    if (segments.empty() && semaphores.empty() && queues.empty()) return 0;
    // Removed by their owner: root without CAP_SYS_ADMIN (a container) may
    // not remove another user's. A child becomes the user (raw system
    // calls and no allocation: the grader may have other threads).
    const pid_t child = fork();
    if (child == 0) {
        if (syscall(SYS_setresuid, user, user, user) != 0) _exit(0);
        int removed = 0;
        for (const int id : segments) removed += shmctl(id, IPC_RMID, nullptr) == 0;
        for (const int id : semaphores) removed += semctl(id, 0, IPC_RMID) == 0;
        for (const int id : queues) removed += msgctl(id, IPC_RMID, nullptr) == 0;
        _exit(std::min(removed, 255));
    }
    int status = 0;
    if (child < 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status)) return 0;
    return WEXITSTATUS(status);
}

std::int64_t ipc_bytes_of(uid_t user) {
    std::int64_t bytes = 0;
    for_each_object_of("/proc/sysvipc/shm", user, [&](const auto& value) { bytes += value("rss") + value("swap"); });
    for_each_object_of("/proc/sysvipc/msg", user, [&](const auto& value) { bytes += value("cbytes"); });
    return bytes;
}

}  // namespace simcheck
