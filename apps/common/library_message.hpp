#pragma once
// The library's exceptions name the function or class that refused
// ("particlesim::make_family_scene: the area fraction must be ..."), which
// helps a program that calls it. A user of the apps never called it: each
// app prints the message without those names.

#include <cctype>
#include <string>
#include <string_view>

namespace apps_common {

// `message` with every "particlesim::Name: " (Name may hold "::") taken out.
inline std::string without_library_names(std::string_view message) {
    static constexpr std::string_view marker = "particlesim::";
    std::string result;
    result.reserve(message.size());
    std::size_t copied = 0;
    for (std::size_t at = message.find(marker); at != std::string_view::npos; at = message.find(marker, at + 1)) {
        std::size_t end = at + marker.size();
        while (end < message.size() &&
               (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '_' || message[end] == ':')) {
            ++end;
        }
        // The name ends at ": "; the loop above took its colon too.
        if (end < message.size() && message[end] == ' ' && message[end - 1] == ':' && end - 1 > at + marker.size()) {
            result.append(message.substr(copied, at - copied));
            copied = end + 1;
        }
    }
    result.append(message.substr(copied));
    return result;
}

}  // namespace apps_common
