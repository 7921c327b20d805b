#pragma once
// An input named on the command line, "-" standing for stdin, that is a
// directory reads as empty or fails with EISDIR halfway: each app says
// "NAME: is a directory" instead, before reading.

#include <sys/stat.h>

#include <string>

namespace apps_common {

// Whether `path` ("-": stdin) is a directory.
inline bool names_a_directory(const std::string& path) {
    struct stat info {};
    const int found = path == "-" ? fstat(0, &info) : stat(path.c_str(), &info);
    return found == 0 && S_ISDIR(info.st_mode);
}

}  // namespace apps_common
