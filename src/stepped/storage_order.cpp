#include "stepped/storage_order.hpp"

#include "core/prefetch.hpp"
#include "core/uniform_grid.hpp"
#include "stepped/stepped_tuning.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <utility>

namespace particlesim {

using namespace stepped_tuning;

namespace {

UniformGrid sorting_grid(double box_size, std::size_t count) {
    const double wanted = std::sqrt(static_cast<double>(count) / sort_particles_per_cell);
    return UniformGrid(box_size, UniformGrid::cells_per_side(box_size, 0.0, wanted));
}

}  // namespace

void StorageOrder::reserve(std::size_t count) {
    user_index_.reserve(count);
    stored_index_.reserve(count);
    cell_start_.reserve(sorting_grid(1.0, count).cell_count() + 1);
    const std::size_t window = std::bit_ceil(std::min(count, sort_window));
    window_.resize(window);
    window_place_.resize(window);
}

void StorageOrder::sort_by_position(std::span<Particle> particles, const Box& box) {
    const std::size_t count = particles.size();
    if (user_order_) {
        user_index_.resize(count);
        std::iota(user_index_.begin(), user_index_.end(), 0U);
    }
    const UniformGrid grid = sorting_grid(box.side, count);
    // Counting sort: stored_index_ holds each particle's cell, then its destination.
    cell_start_.assign(grid.cell_count() + 1, 0U);
    stored_index_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        stored_index_[i] = grid.cell_of(particles[i].position);
        ++cell_start_[stored_index_[i] + 1];
    }
    std::partial_sum(cell_start_.begin(), cell_start_.end(), cell_start_.begin());
    for (std::uint32_t& place : stored_index_) place = cell_start_[place]++;
    permute(particles);
    user_order_ = false;
}

void StorageOrder::restore_user_order(std::span<Particle> particles) {
    if (user_order_) return;
    stored_index_.assign(user_index_.begin(), user_index_.end());
    permute(particles);
    user_order_ = true;
}

void StorageOrder::permute(std::span<Particle> particles) {
    std::size_t reach = 0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        if (stored_index_[i] > i) reach = std::max<std::size_t>(reach, stored_index_[i] - i);
    }
    if (reach < window_.size()) {
        move_within_window(particles);
    } else {
        move_along_cycles(particles);
    }
    for (std::size_t i = 0; i < particles.size(); ++i) stored_index_[user_index_[i]] = static_cast<std::uint32_t>(i);
}

void StorageOrder::move_within_window(std::span<Particle> particles) {
    // In one pass, in place: each particle is put at its destination, and a
    // particle it displaces from further ahead waits in the window until its
    // own turn. Every destination lies less than a window ahead, so a slot
    // is free again by the time a later place needs it.
    const std::size_t mask = window_.size() - 1;
    std::fill(window_place_.begin(), window_place_.end(), not_waiting);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const std::size_t slot = i & mask;
        const bool waiting = window_place_[slot] == i;
        const Particle mine = waiting ? window_[slot].particle : particles[i];
        const std::uint32_t mine_user = waiting ? window_[slot].user_index : user_index_[i];
        const std::uint32_t to = stored_index_[i];
        if (to > i) {
            const std::size_t to_slot = to & mask;
            window_[to_slot] = {particles[to], user_index_[to]};
            window_place_[to_slot] = to;
        }
        particles[to] = mine;
        user_index_[to] = mine_user;
    }
}

void StorageOrder::move_along_cycles(std::span<Particle> particles) {
    // In place, cycle by cycle: the particle in hand displaces the one at its
    // destination, which is carried on. The places ahead on the cycle are
    // fetched early: every place is a cache miss, and the chain of
    // destinations is the only dependent load.
    std::vector<std::uint32_t>& destination = stored_index_;
    for (std::size_t start = 0; start < particles.size(); ++start) {
        if (destination[start] == start) continue;
        Particle carried = particles[start];
        std::uint32_t carried_user = user_index_[start];
        std::uint32_t ahead = destination[start];
        for (int hop = 0; hop < sort_fetch_ahead; ++hop) ahead = destination[ahead];
        std::uint32_t at = destination[start];
        while (at != start) {
            prefetch_for_write(&particles[ahead]);
            prefetch_for_write(&user_index_[ahead]);
            ahead = destination[ahead];
            std::swap(carried, particles[at]);
            std::swap(carried_user, user_index_[at]);
            const std::uint32_t next = destination[at];
            destination[at] = at;
            at = next;
        }
        particles[start] = carried;
        user_index_[start] = carried_user;
        destination[start] = static_cast<std::uint32_t>(start);
    }
}

}  // namespace particlesim
