#include "compression_progress.hpp"

#include "common/duration_text.hpp"

#include <cstdio>

namespace simgen {

void CompressionProgress::update(double reached, double target) {
    if (!timing_.enabled()) return;
    const auto now = apps_common::ProgressTiming::Clock::now();
    if (!timing_.due(now)) return;
    std::fprintf(stderr, "%ssimgen: compressed: area fraction %.4f of %.4g, %s so far%s", timing_.line_start(), reached,
                 target, apps_common::duration_text(timing_.seconds_since_start(now)).c_str(), timing_.line_end());
    std::fflush(stderr);
}

}  // namespace simgen
