#include "search/path_search.hpp"

#include "parallel/parallel.hpp"
#include "stepped/stepped_tuning.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

namespace particlesim {

namespace {

constexpr std::int64_t lines_made_afresh_every = 1024;  // micro-steps

}  // namespace

bool PathSearch::find_pairs(const PairSearchInput& in, std::span<ThreadCandidates> out, std::size_t watch_limit) {
    // Grown, never shrunk: a step may use fewer threads than the one before.
    if (thread_watches_.size() < out.size()) thread_watches_.resize(out.size());
    const bool afresh = make_lines(in);
    const double reach = contact_reach(in.box);
    const auto new_count = static_cast<std::int64_t>(new_lines_.size());
    const std::int64_t tests = new_count * static_cast<std::int64_t>(in.particles.size());
    int workers = worker_count(out.size(), tests, stepped_tuning::paths_line_tests_per_thread);
    // Lines made afresh (all N^2 / 2 tests) are a region that the steps
    // around it may not share: its second thread would then spin on beside
    // them (for milliseconds, libgomp's wait), slowing the first. So they are
    // shared only as the steps between are; at the start, from a larger
    // count a thread.
    if (afresh) {
        workers = steady_workers_ == 0
                      ? worker_count(out.size(), tests, stepped_tuning::paths_afresh_line_tests_per_thread)
                      : std::min(workers, steady_workers_);
    } else {
        steady_workers_ = workers;
    }
    // New lines in blocks: PathLines reads each group of lines once for the block.
    // Each thread stops once the watches it found would pass the limit with
    // those kept: at most a block's more each, whatever the scene.
    constexpr std::int64_t block = PathLines::max_block;
    std::atomic<bool> crowded{false};
    parallel_for_dynamic(workers, (new_count + block - 1) / block, 1, [&](std::int64_t b, std::size_t thread) {
        if (crowded.load(std::memory_order_relaxed)) return;
        const auto first = static_cast<std::size_t>(b * block);
        const std::size_t count = std::min<std::size_t>(block, new_lines_.size() - first);
        watch_near(in, first, count, reach, thread_watches_[thread]);
        if (watches_.size() + thread_watches_[thread].found.size() > watch_limit)
            crowded.store(true, std::memory_order_relaxed);
    });
    std::size_t watched = watches_.size();
    for (const ThreadWatches& thread : thread_watches_) watched += thread.found.size();
    if (crowded.load() || watched > watch_limit) {
        release();
        return false;
    }
    for (ThreadWatches& thread : thread_watches_) {
        watches_.insert(watches_.end(), thread.found.begin(), thread.found.end());
        thread.found.clear();
    }
    // Each watched pair in the micro-steps of its interval, then dropped when
    // its interval has passed or a line has changed.
    const auto now = static_cast<double>(micro_steps_);
    ThreadCandidates& found = out[0];
    std::size_t kept = 0;
    for (const Watch& w : watches_) {
        if (w.serial_i != serial_[w.i] || w.serial_j != serial_[w.j] || w.until < now) continue;
        if (w.from <= now + 1.0) test_pair(in, std::min(w.i, w.j), std::max(w.i, w.j), found);
        if (w.until >= now + 1.0) watches_[kept++] = w;
    }
    watches_.resize(kept);
    ++micro_steps_;
    return true;
}

void PathSearch::release() {
    std::vector<Watch>().swap(watches_);
    std::vector<ThreadWatches>().swap(thread_watches_);
    lines_made_ = false;
}

// Every line through the particles' positions now; new lines for the
// particles that collided since theirs was made (their collision count
// moved), for all at the start and every lines_made_afresh_every micro-steps.
bool PathSearch::make_lines(const PairSearchInput& in) {
    const std::size_t count = in.particles.size();
    for (const std::uint32_t i : new_lines_) new_line_[i] = 0;
    new_lines_.clear();
    const bool afresh =
        !lines_made_ || collisions_.size() != count || micro_steps_ - lines_made_at_ >= lines_made_afresh_every;
    if (afresh) {
        collisions_.assign(count, 0);
        serial_.resize(count, 0);
        new_line_.assign(count, 0);
        watches_.clear();
        // Room for a busy micro-step from the start, so that steps rarely grow them.
        watches_.reserve(2 * count + 64);
        for (ThreadWatches& thread : thread_watches_) {
            for (std::vector<std::uint32_t>& near : thread.near) near.reserve(count);
            thread.found.reserve(count + 64);
        }
        lines_made_ = true;
        lines_made_at_ = micro_steps_;
        lines_.assign(in.particles, in.box);  // the scales
    }
    // Every line through its particle's position now: the old lines moved
    // along, the new ones (a collision since) made.
    lines_.arrange_changed(in.particles, collisions_, afresh, new_lines_);
    for (const std::uint32_t i : new_lines_) {
        ++serial_[i];
        new_line_[i] = 1;
    }
    return afresh;
}

// The pairs of a block of new lines, new_lines_[first] on (at most
// PathLines::max_block), each line's near ones found in one pass over the
// lines.
void PathSearch::watch_near(const PairSearchInput& in, std::size_t first, std::size_t count, double reach,
                            ThreadWatches& out) const {
    std::array<std::vector<std::uint32_t>*, PathLines::max_block> nears{};
    for (std::size_t k = 0; k < count; ++k) {
        nears[k] = &out.near[k];
        nears[k]->clear();
    }
    lines_.gather_new_block(first, std::span(nears).first(count));
    for (std::size_t k = 0; k < count; ++k) watch_pairs(in, new_lines_[first + k], out.near[k], reach, out);
}

// Watches every pair of i's new line with a line of `near` that comes within
// `reach` of it from now on; a pair of two new lines once: from the lower
// index where both found it (PathLines::gather_new_block()).
void PathSearch::watch_pairs(const PairSearchInput& in, std::uint32_t i, std::span<const std::uint32_t> near,
                             double reach, ThreadWatches& out) const {
    const auto now = static_cast<double>(micro_steps_);
    const Particle& a = in.particles[i];
    const double reach_sq = reach * reach;
    for (const std::uint32_t j : near) {
        if (new_line_[j] != 0 && j < i) continue;
        const Particle& b = in.particles[j];
        // The interval in which |dp + dv t| <= reach, in micro-steps from now,
        // as contact_time() solves it (Lagrange's identity for the discriminant).
        const Vec2 dp = b.position - a.position;
        const Vec2 dv = (b.velocity - a.velocity) * in.duration;
        const double c = dp.dot(dp) - reach_sq;
        double from = 0.0;
        double until = never;
        if (dv.x() != 0.0 || dv.y() != 0.0) {
            const double speed_sq = dv.dot(dv);
            const double half_b = dp.dot(dv);
            const double cross = dp.x() * dv.y() - dp.y() * dv.x();
            const double quarter_disc = reach_sq * speed_sq - cross * cross;
            // Apart now, and receding or passing wide: never within reach.
            if (c > 0.0 && (half_b >= 0.0 || quarter_disc < 0.0)) continue;
            const double root = std::sqrt(std::max(quarter_disc, 0.0));
            if (c > 0.0) from = c / (root - half_b);
            // A relative speed whose square underflows: watched until a line changes.
            until = speed_sq > 0.0 ? std::max(root - half_b, 0.0) / speed_sq : never;
        } else if (c > 0.0) {
            continue;
        }
        // Rounding in the interval's ends: widened by far more than it.
        from = now + from * (1.0 - 0x1p-20) - 0x1p-20;
        until = now + until * (1.0 + 0x1p-20) + 0x1p-20;
        if (until < now) continue;
        out.found.push_back({from, until, i, j, serial_[i], serial_[j]});
    }
}

}  // namespace particlesim
