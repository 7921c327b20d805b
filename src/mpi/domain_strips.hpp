#pragma once
// The box cut into strips along x, one per rank: rank k owns the particles
// whose centres lie in [lower(k), upper(k)); the first strip reaches down to
// -infinity and the last up to +infinity, so every centre has one owner
// whatever rounding does near a cut. The cuts may move (to balance counts);
// a strip may be empty.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

namespace particlesim {

class DomainStrips {
public:
    DomainStrips() = default;
    // `ranks` - 1 ascending inner cuts.
    explicit DomainStrips(std::vector<double> inner_cuts) : inner_(std::move(inner_cuts)) {
        if (!std::is_sorted(inner_.begin(), inner_.end())) throw std::logic_error("DomainStrips: cuts out of order");
    }

    [[nodiscard]] int ranks() const { return static_cast<int>(inner_.size()) + 1; }
    [[nodiscard]] std::span<const double> inner_cuts() const { return inner_; }
    [[nodiscard]] double lower(int rank) const {
        return rank == 0 ? -std::numeric_limits<double>::infinity() : inner_[static_cast<std::size_t>(rank) - 1];
    }
    [[nodiscard]] double upper(int rank) const {
        return rank + 1 == ranks() ? std::numeric_limits<double>::infinity() : inner_[static_cast<std::size_t>(rank)];
    }
    [[nodiscard]] int owner_of(double x) const {
        return static_cast<int>(std::upper_bound(inner_.begin(), inner_.end(), x) - inner_.begin());
    }

    // Whether x comes within `reach` of rank's strip (inside it too).
    // Written as differences so that the relation between two strips below
    // is implied by it under rounding (subtraction rounds monotonically).
    [[nodiscard]] bool near(double x, int rank, double reach) const {
        return lower(rank) - x <= reach && x - upper(rank) <= reach;
    }
    // Whether two ranks' strips come within `reach` of each other: the
    // ranks that exchange ghosts and migrants. Symmetric in a and b.
    [[nodiscard]] bool strips_near(int a, int b, double reach) const {
        return lower(a) - upper(b) <= reach && lower(b) - upper(a) <= reach;
    }
    // Every other rank whose strip comes within `reach` of `rank`'s, ascending.
    [[nodiscard]] std::vector<int> neighbours_of(int rank, double reach) const {
        std::vector<int> near_ranks;
        for (int other = 0; other < ranks(); ++other) {
            if (other != rank && strips_near(rank, other, reach)) near_ranks.push_back(other);
        }
        return near_ranks;
    }

private:
    std::vector<double> inner_;
};

// Inner cuts that give each of `ranks` strips about the same number of
// centres, from a histogram of the centres' x over equal bins of [0, length].
[[nodiscard]] inline std::vector<double> balanced_cuts(std::span<const std::uint64_t> histogram, double length,
                                                       int ranks) {
    std::uint64_t total = 0;
    for (const std::uint64_t count : histogram) total += count;
    std::vector<double> cuts;
    const double bin_width = length / static_cast<double>(histogram.size());
    std::uint64_t below = 0;
    std::size_t bin = 0;
    for (int k = 1; k < ranks; ++k) {
        // The first bin edge with at least k / ranks of the centres below it.
        const std::uint64_t wanted = (total * static_cast<std::uint64_t>(k) + static_cast<std::uint64_t>(ranks) - 1) /
                                     static_cast<std::uint64_t>(ranks);
        while (bin < histogram.size() && below < wanted) below += histogram[bin++];
        cuts.push_back(bin_width * static_cast<double>(bin));
    }
    return cuts;
}

}  // namespace particlesim
