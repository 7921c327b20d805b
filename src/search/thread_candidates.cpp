#include "search/pair_search.hpp"

#include <unistd.h>

#include <algorithm>
#include <new>

namespace particlesim {

void ThreadCandidates::grow() {
    const std::size_t most = (most_bytes != 0 ? most_bytes : most_candidate_bytes()) / sizeof(Collision);
    if (found.capacity() >= most) throw std::bad_alloc();
    found.reserve(std::min(most, std::max<std::size_t>(1024, 2 * found.capacity())));
}

std::size_t ThreadCandidates::most_candidate_bytes() {
    static const std::size_t most = [] {
        const long pages = sysconf(_SC_PHYS_PAGES);
        const long page_size = sysconf(_SC_PAGE_SIZE);
        // Unknown: no limit of ours (the allocator's own failure remains).
        if (pages <= 0 || page_size <= 0) return static_cast<std::size_t>(-1);
        return static_cast<std::size_t>(pages) / 8 * static_cast<std::size_t>(page_size);
    }();
    return most;
}

}  // namespace particlesim
