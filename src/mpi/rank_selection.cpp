#include "mpi/rank_selection.hpp"

#include "core/assert.hpp"
#include "core/event_order.hpp"

#include <algorithm>
#include <tuple>

namespace particlesim {

void RankSelection::begin(std::span<const Collision> candidates, std::uint32_t owned_count,
                          std::span<const std::uint32_t> user_index, std::span<const std::uint32_t> ghost_neighbour,
                          std::size_t neighbours, std::span<double> collision_time) {
    candidates_ = candidates;
    user_index_ = user_index;
    owned_ = owned_count;
    const std::size_t local = user_index.size();
    // Counts grow a little from step to step: room for more at once, rather
    // than a move at every step.
    if (taken_.capacity() < local) {
        for (auto* by_particle : {&earliest_, &partner_}) by_particle->reserve(local + local / 64);
        taken_.reserve(local + local / 64);
    }
    undecided_.resize(candidates.size());
    for (std::uint32_t k = 0; k < candidates.size(); ++k) undecided_[k] = k;
    earliest_.assign(owned_count, no_collision);
    other_side_claimed_.assign(candidates.size(), 0);
    taken_.assign(local, 0);
    partner_.assign(local, no_collision);
    collision_time_ = collision_time;
    accepted_ = {};
    shared_.resize(neighbours);
    for (std::vector<Shared>& list : shared_) list.clear();
    for (std::uint32_t k = 0; k < candidates.size(); ++k) {
        const Collision& c = candidates[k];
        PARTICLESIM_ASSERT(owned(c.i) || (c.kind == CollisionKind::pair && owned(c.j)),
                           "a rank's candidate has a particle it owns");
        if (c.kind == CollisionKind::wall || (owned(c.i) && owned(c.j))) continue;
        const std::uint32_t mine = owned(c.i) ? c.i : c.j;
        const std::uint32_t ghost = owned(c.i) ? c.j : c.i;
        const auto [low, high] = std::minmax(user_index[c.i], user_index[c.j]);
        shared_[ghost_neighbour[ghost - owned_count]].push_back({k, mine, ghost, low, high});
    }
    // Both ranks of a shared candidate list it at the same place: by its
    // particles' user indices. A candidate found twice is listed once, by its
    // first copy, the one claim() prefers among equals.
    for (std::vector<Shared>& list : shared_) {
        std::sort(list.begin(), list.end(), [](const Shared& a, const Shared& b) {
            return std::tie(a.user_low, a.user_high, a.candidate) < std::tie(b.user_low, b.user_high, b.candidate);
        });
        list.erase(std::unique(list.begin(), list.end(),
                               [](const Shared& a, const Shared& b) {
                                   return a.user_low == b.user_low && a.user_high == b.user_high;
                               }),
                   list.end());
    }
}

void RankSelection::claim() {
    const CandidateOrder order(user_index_);
    for (const std::uint32_t k : undecided_) {
        const Collision& c = candidates_[k];
        for (const std::uint32_t p : {c.i, c.j}) {
            if (!owned(p)) continue;
            std::uint32_t& first = earliest_[p];
            // Strictly before: of two equal copies, the first keeps the claim.
            if (first == no_collision || order.before(c, candidates_[first])) first = k;
            if (c.kind == CollisionKind::wall) break;
        }
    }
}

void RankSelection::write_claims(std::size_t n, std::vector<std::uint8_t>& out) const {
    out.resize(shared_[n].size());
    for (std::size_t e = 0; e < shared_[n].size(); ++e) {
        const Shared& s = shared_[n][e];
        out[e] = static_cast<std::uint8_t>(!taken_[s.owned] && !taken_[s.ghost] && earliest_[s.owned] == s.candidate);
    }
}

void RankSelection::take(std::uint32_t local, std::uint32_t partner, double time) {
    PARTICLESIM_ASSERT(!taken_[local], "no particle has two collisions selected");
    taken_[local] = 1;
    partner_[local] = partner;
    collision_time_[local] = time;
}

void RankSelection::accept(std::span<const std::vector<std::uint8_t>> claims) {
    for (std::size_t n = 0; n < shared_.size(); ++n) {
        PARTICLESIM_ASSERT(claims[n].size() == shared_[n].size(), "both sides list the same shared candidates");
        for (std::size_t e = 0; e < shared_[n].size(); ++e) other_side_claimed_[shared_[n][e].candidate] = claims[n][e];
    }
    for (const std::uint32_t k : undecided_) {
        const Collision& c = candidates_[k];
        if (c.kind == CollisionKind::wall) {
            if (earliest_[c.i] != k) continue;
            take(c.i, wall_collision, c.time);
            ++accepted_.wall_collisions;
            continue;
        }
        const bool i_claims = owned(c.i) ? earliest_[c.i] == k : other_side_claimed_[k] != 0;
        const bool j_claims = owned(c.j) ? earliest_[c.j] == k : other_side_claimed_[k] != 0;
        if (!i_claims || !j_claims) continue;
        take(c.i, c.j, c.time);
        take(c.j, c.i, c.time);
        const bool counted_here =
            (owned(c.i) && owned(c.j)) || user_index_[owned(c.i) ? c.i : c.j] < user_index_[owned(c.i) ? c.j : c.i];
        if (counted_here) ++accepted_.particle_collisions;
    }
}

void RankSelection::write_taken(std::size_t n, std::vector<std::uint8_t>& out) const {
    out.resize(shared_[n].size());
    for (std::size_t e = 0; e < shared_[n].size(); ++e) out[e] = taken_[shared_[n][e].owned];
}

std::size_t RankSelection::end_round(std::span<const std::vector<std::uint8_t>> taken) {
    for (std::size_t n = 0; n < shared_.size(); ++n) {
        PARTICLESIM_ASSERT(taken[n].size() == shared_[n].size(), "both sides list the same shared candidates");
        for (std::size_t e = 0; e < shared_[n].size(); ++e) {
            // Taken by a collision on its own rank, or decided here already.
            if (taken[n][e] != 0) taken_[shared_[n][e].ghost] = 1;
        }
    }
    const std::size_t before = undecided_.size();
    std::size_t kept = drop_ruled_out();
    std::fill(earliest_.begin(), earliest_.end(), no_collision);
    // Stalled: the rest are decided here, as far as this rank can alone.
    if (selection_stalled(before, kept)) kept = decide_alone();
    return kept;
}

std::size_t RankSelection::decide_alone() {
    const CandidateOrder order(user_index_);
    std::sort(undecided_.begin(), undecided_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return order.before(candidates_[a], candidates_[b]); });
    // The greedy pass over this rank's candidates in the order, except that
    // a candidate with a ghost stays undecided (its other side decides it
    // with this one), and so does every later candidate of its particles:
    // they wait on it. Any other is decided as the greedy pass decides it,
    // since every earlier candidate of its particles is decided.
    waiting_.assign(taken_.size(), 0);
    for (const std::uint32_t k : undecided_) {
        const Collision& c = candidates_[k];
        if (!free(c)) continue;  // ruled out by one accepted before it
        const bool pair = c.kind == CollisionKind::pair;
        const bool alone = !pair || (owned(c.i) && owned(c.j));
        if (alone && !waiting_[c.i] && (!pair || !waiting_[c.j])) {
            if (pair) {
                take(c.i, c.j, c.time);
                take(c.j, c.i, c.time);
                ++accepted_.particle_collisions;
            } else {
                take(c.i, wall_collision, c.time);
                ++accepted_.wall_collisions;
            }
            continue;
        }
        waiting_[c.i] = 1;
        if (pair) waiting_[c.j] = 1;
    }
    // The rest in ascending order again: claim() keeps the first of equal copies.
    const std::size_t kept = drop_ruled_out();
    std::sort(undecided_.begin(), undecided_.end());
    return kept;
}

std::size_t RankSelection::drop_ruled_out() {
    std::size_t kept = 0;
    for (const std::uint32_t k : undecided_) {
        if (free(candidates_[k])) undecided_[kept++] = k;
    }
    undecided_.resize(kept);
    return kept;
}

std::vector<Collision> RankSelection::undecided_by_user() const {
    std::vector<Collision> out;
    out.reserve(undecided_.size());
    for (const std::uint32_t k : undecided_) {
        Collision c = candidates_[k];
        c.i = user_index_[c.i];
        if (c.kind == CollisionKind::pair) {
            c.j = user_index_[c.j];
            if (c.i > c.j) std::swap(c.i, c.j);
        } else {
            c.j = 0;
        }
        out.push_back(c);
    }
    return out;
}

void RankSelection::take_accepted(std::span<const Collision> accepted) {
    take_of_this_rank(accepted);
    undecided_.clear();
}

std::size_t RankSelection::take_decided_first(std::span<const Collision> accepted) {
    take_of_this_rank(accepted);
    return drop_ruled_out();
}

LocalByUser::LocalByUser(std::span<const std::uint32_t> user_index) : by_user_(user_index.size()) {
    for (std::uint32_t l = 0; l < user_index.size(); ++l) by_user_[l] = {user_index[l], l};
    std::sort(by_user_.begin(), by_user_.end());
}

std::uint32_t LocalByUser::operator()(std::uint32_t user) const {
    const auto at = std::lower_bound(by_user_.begin(), by_user_.end(), std::pair{user, 0U});
    return at != by_user_.end() && at->first == user ? at->second : no_collision;
}

void RankSelection::take_of_this_rank(std::span<const Collision> accepted) {
    const LocalByUser local(user_index_);
    for (const Collision& c : accepted) {
        const std::uint32_t i = local(c.i);
        if (c.kind == CollisionKind::wall) {
            if (i == no_collision || !owned(i)) continue;
            take(i, wall_collision, c.time);
            ++accepted_.wall_collisions;
            continue;
        }
        const std::uint32_t j = local(c.j);
        if (i == no_collision || j == no_collision || (!owned(i) && !owned(j))) continue;
        take(i, j, c.time);
        take(j, i, c.time);
        // Counted once over all ranks: where both are owned, or on the rank of the lower user index.
        if (owned(i)) ++accepted_.particle_collisions;
    }
}

std::vector<Collision> decide_in_order(std::vector<Collision> candidates, std::vector<std::uint32_t> taken_users) {
    std::sort(candidates.begin(), candidates.end(),
              [](const Collision& a, const Collision& b) { return comes_before(a, b); });
    // Every particle named, densely numbered.
    std::vector<std::uint32_t> users = taken_users;
    for (const Collision& c : candidates) {
        users.push_back(c.i);
        if (c.kind == CollisionKind::pair) users.push_back(c.j);
    }
    std::sort(users.begin(), users.end());
    users.erase(std::unique(users.begin(), users.end()), users.end());
    const auto place = [&](std::uint32_t user) {
        return static_cast<std::size_t>(std::lower_bound(users.begin(), users.end(), user) - users.begin());
    };
    std::vector<std::uint8_t> taken(users.size(), 0);
    for (const std::uint32_t user : taken_users) taken[place(user)] = 1;
    std::vector<Collision> accepted;
    for (const Collision& c : candidates) {
        const std::size_t i = place(c.i);
        const std::size_t j = c.kind == CollisionKind::pair ? place(c.j) : i;
        if (taken[i] || taken[j]) continue;
        taken[i] = taken[j] = 1;
        accepted.push_back(c);
    }
    return accepted;
}

std::vector<std::uint32_t> RankSelection::taken_shared_by_user() const {
    std::vector<std::uint32_t> out;
    for (const std::vector<Shared>& list : shared_) {
        for (const Shared& s : list) {
            if (taken_[s.owned]) out.push_back(user_index_[s.owned]);
        }
    }
    return out;
}

}  // namespace particlesim
