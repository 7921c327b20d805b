#pragma once
// The order in which a simulation stores its particles. Large scenes are
// stored sorted by position (row-major cells), so that the grid's binning,
// the collisions and the moves walk memory roughly in the order they walk
// space instead of jumping at random through it. The user's index of every
// stored particle is kept: it decides ties (rules.md "Order") and the order
// of the output, so the results do not depend on the storage order.

#include "core/box.hpp"
#include "particlesim/particle.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

class StorageOrder {
public:
    // Makes room for `count` particles, so that sorting allocates nothing.
    void reserve(std::size_t count);

    // Sorts `particles` by cell, stably, and records their user indices.
    void sort_by_position(std::span<Particle> particles, const Box& box);

    // Puts `particles` back in the user's order.
    void restore_user_order(std::span<Particle> particles);

    [[nodiscard]] bool is_user_order() const { return user_order_; }

    // The user's index of the particle stored at each place, and the stored
    // place of each user index; both empty while the order is the user's.
    [[nodiscard]] std::span<const std::uint32_t> user_index() const { return in_use(user_index_); }
    [[nodiscard]] std::span<const std::uint32_t> stored_index() const { return in_use(stored_index_); }

    // Whether the two maps are permutations, each the inverse of the other
    // (always true while the order is the user's). A check, O(N).
    [[nodiscard]] bool is_permutation() const {
        const std::span<const std::uint32_t> user = user_index();
        const std::span<const std::uint32_t> stored = stored_index();
        if (user.size() != stored.size()) return false;
        for (std::size_t place = 0; place < user.size(); ++place) {
            if (user[place] >= stored.size() || stored[user[place]] != place) return false;
        }
        return true;
    }

private:
    [[nodiscard]] std::span<const std::uint32_t> in_use(const std::vector<std::uint32_t>& map) const {
        return user_order_ ? std::span<const std::uint32_t>{} : std::span<const std::uint32_t>{map};
    }

    // Moves the particle stored at i to stored_index_[i] (its destination),
    // for every i, and its user index with it; then makes stored_index_ the
    // inverse of user_index_.
    void permute(std::span<Particle> particles);
    // The same when no destination is a window or more ahead of its place
    // (a scene sorted again), then when any may be (the first sort, or back
    // to the user's order).
    void move_within_window(std::span<Particle> particles);
    void move_along_cycles(std::span<Particle> particles);

    // A particle displaced before its turn, and its user index.
    struct Waiting {
        Particle particle;
        std::uint32_t user_index = 0;
    };
    static constexpr std::size_t not_waiting = static_cast<std::size_t>(-1);

    bool user_order_ = true;
    std::vector<std::uint32_t> user_index_;
    std::vector<std::uint32_t> stored_index_;
    std::vector<std::uint32_t> cell_start_;
    std::vector<Waiting> window_;            // by place, modulo its length (a power of two)
    std::vector<std::size_t> window_place_;  // the place each slot holds, or not_waiting
};

}  // namespace particlesim
