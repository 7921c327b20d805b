#pragma once
// What simcli says of a failure while running, on one process or on a rank:
// the exception's own words, or, for a failed allocation, what may have
// taken the memory.

#include "common/library_message.hpp"

#include <exception>
#include <new>
#include <string>

namespace simcli {

inline constexpr const char* out_of_memory_words =
    "out of memory while running (the scene's arrays, or a step's pair candidates, which may take an eighth of "
    "this machine's memory on each thread)";

inline std::string failure_words(const std::exception& failure) {
    if (dynamic_cast<const std::bad_alloc*>(&failure) != nullptr) return out_of_memory_words;
    return apps_common::without_library_names(failure.what());
}

}  // namespace simcli
