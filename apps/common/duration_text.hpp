#pragma once
// A duration in a person's units, for the apps' progress lines.

#include <cstdio>
#include <string>

namespace apps_common {

// "42 s", "17 min", "3.5 h", "12 days", "2.9e+11 years".
inline std::string duration_text(double seconds) {
    char text[48];
    if (seconds < 120.0) {
        std::snprintf(text, sizeof text, "%.0f s", seconds);
    } else if (seconds < 7200.0) {
        std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
    } else if (seconds < 172800.0) {
        std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
    } else if (seconds < 3.16e7) {
        std::snprintf(text, sizeof text, "%.0f days", seconds / 86400.0);
    } else {
        std::snprintf(text, sizeof text, "%.3g years", seconds / 3.156e7);
    }
    return text;
}

}  // namespace apps_common
