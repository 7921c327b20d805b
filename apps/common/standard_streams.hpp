#pragma once
// Started with descriptor 0, 1 or 2 closed (`>&-`, as some batch systems
// start jobs), a program's next open() takes that number: a trajectory
// file opened as descriptor 1 then receives what is printed to stdout, and
// a pipe made for a child is closed when the child's streams are moved
// into place. Each app first opens /dev/null on any of the three that is
// closed, so that nothing else can take their numbers: for reading where
// it would write and for writing where it would read (as gnulib's
// stdopen), so that using a closed stream still fails as it did (a write
// to a closed stdout is still a write error), instead of going nowhere.

#include <fcntl.h>
#include <unistd.h>

namespace apps_common {

// False if one was closed and /dev/null could not take its place.
inline bool open_closed_standard_streams() {
    for (int fd = 0; fd < 3; ++fd) {
        if (fcntl(fd, F_GETFD) < 0 && open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY) != fd) return false;
    }
    return true;
}

}  // namespace apps_common
