// RankSelection in one process: random conflict graphs (many shared
// particles, exact ties, duplicate finds on one side only) split over random
// "ranks", the ranks' rounds run in lockstep with the messages handed over
// by hand; every particle must get the partner of the one-process greedy
// pass over the sorted candidates, and the counts must add up.

#include "check.hpp"

#include "core/collision.hpp"
#include "core/event_order.hpp"
#include "core/random.hpp"
#include "mpi/rank_selection.hpp"
#include "stepped/step_pipeline.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

using namespace particlesim;

namespace {

// One rank's view: its owned particles first, then its ghosts, by user index.
struct RankView {
    std::vector<std::uint32_t> user;  // by local index
    std::uint32_t owned = 0;
    std::vector<int> neighbours;  // other ranks, ascending
    std::vector<std::uint32_t> ghost_neighbour;
    std::vector<Collision> candidates;  // local indices
    RankSelection selection;
    std::vector<double> collision_time;
};

struct Outcome {
    std::vector<std::uint32_t> partner;  // by user index: a user index, no_collision or wall_collision
    StepCounts counts;
};

Outcome greedy(std::uint32_t particles, const std::vector<Collision>& candidates) {
    std::vector<Collision> sorted = candidates;
    std::sort(sorted.begin(), sorted.end(), [](const Collision& a, const Collision& b) { return comes_before(a, b); });
    Outcome out{std::vector<std::uint32_t>(particles, no_collision), {}};
    for (const Collision& c : sorted) {
        if (out.partner[c.i] != no_collision) continue;
        if (c.kind == CollisionKind::wall) {
            out.partner[c.i] = wall_collision;
            ++out.counts.wall_collisions;
        } else if (out.partner[c.j] == no_collision) {
            out.partner[c.i] = c.j;
            out.partner[c.j] = c.i;
            ++out.counts.particle_collisions;
        }
    }
    return out;
}

// Runs the ranks' rounds in lockstep; false if they did not end.
bool run_rounds(std::vector<RankView>& ranks, int& rounds) {
    const auto place_of = [&](int rank, int neighbour) {
        const std::vector<int>& list = ranks[static_cast<std::size_t>(rank)].neighbours;
        return static_cast<std::size_t>(std::find(list.begin(), list.end(), neighbour) - list.begin());
    };
    // Hands what each rank wrote for each neighbour to that neighbour.
    const auto deliver = [&](auto write) {
        std::vector<std::vector<std::vector<std::uint8_t>>> sent(ranks.size()), received(ranks.size());
        for (std::size_t r = 0; r < ranks.size(); ++r) {
            sent[r].resize(ranks[r].neighbours.size());
            for (std::size_t n = 0; n < sent[r].size(); ++n) write(ranks[r].selection, n, sent[r][n]);
        }
        for (std::size_t r = 0; r < ranks.size(); ++r) {
            received[r].resize(ranks[r].neighbours.size());
            for (std::size_t n = 0; n < received[r].size(); ++n) {
                const auto q = static_cast<std::size_t>(ranks[r].neighbours[n]);
                received[r][n] = sent[q][place_of(static_cast<int>(q), static_cast<int>(r))];
            }
        }
        return received;
    };
    std::size_t left_before = 0;
    for (rounds = 1; rounds < 10000; ++rounds) {
        for (RankView& rank : ranks) rank.selection.claim();
        const auto claims = deliver(
            [](const RankSelection& s, std::size_t n, std::vector<std::uint8_t>& out) { s.write_claims(n, out); });
        for (std::size_t r = 0; r < ranks.size(); ++r) ranks[r].selection.accept(claims[r]);
        const auto taken = deliver(
            [](const RankSelection& s, std::size_t n, std::vector<std::uint8_t>& out) { s.write_taken(n, out); });
        std::size_t undecided = 0;
        for (std::size_t r = 0; r < ranks.size(); ++r) undecided += ranks[r].selection.end_round(taken[r]);
        if (undecided == 0) return true;
        // Stalled: one rank decides the rest, as the distributed engine does.
        if (rounds > 1 && 2 * undecided > left_before) {
            std::vector<Collision> gathered;
            std::vector<std::uint32_t> taken_users;
            for (const RankView& rank : ranks) {
                const std::vector<Collision> mine = rank.selection.undecided_by_user();
                gathered.insert(gathered.end(), mine.begin(), mine.end());
                const std::vector<std::uint32_t> shared = rank.selection.taken_shared_by_user();
                taken_users.insert(taken_users.end(), shared.begin(), shared.end());
            }
            const std::vector<Collision> accepted = decide_in_order(gathered, taken_users);
            for (RankView& rank : ranks) rank.selection.take_accepted(accepted);
            return true;
        }
        left_before = undecided;
    }
    return false;
}

// One random conflict graph over `rank_count` ranks; true when every rank's
// particles get the greedy pass's partners. The first `piled` particles lie
// in a pile: every pair of them a candidate at t = 0; on rank 0, unless
// `pile_spread` (a pile across the cuts).
bool distributed_matches_greedy(SplitMix64& rng, std::uint32_t particles, int candidate_count, int rank_count,
                                int& rounds, std::uint32_t piled = 0, bool pile_spread = false) {
    std::vector<Collision> all;
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::uint32_t i = 0; i < piled; ++i) {
        for (std::uint32_t j = i + 1; j < piled; ++j) {
            pairs.insert({i, j});
            all.push_back(Collision::pair(0.0, i, j));
        }
    }
    for (int k = 0; k < candidate_count; ++k) {
        const double t = static_cast<double>(rng.next() % 6) / 6.0;  // many exact ties
        const auto i = static_cast<std::uint32_t>(rng.next() % particles);
        const auto j = static_cast<std::uint32_t>(rng.next() % particles);
        if (rng.next() % 4 == 0 || i == j) {
            if (std::none_of(all.begin(), all.end(),
                             [&](const Collision& c) { return c.kind == CollisionKind::wall && c.i == i; })) {
                all.push_back(Collision::wall(t, i));
            }
        } else if (pairs.insert(std::minmax(i, j)).second) {  // a pair has one candidate time
            all.push_back(Collision::pair(t, std::min(i, j), std::max(i, j)));
        }
    }
    std::vector<int> owner(particles);
    for (int& o : owner) o = static_cast<int>(rng.next() % static_cast<std::uint64_t>(rank_count));
    if (!pile_spread) std::fill(owner.begin(), owner.begin() + piled, 0);

    std::vector<RankView> ranks(static_cast<std::size_t>(rank_count));
    for (int r = 0; r < rank_count; ++r) {
        RankView& view = ranks[static_cast<std::size_t>(r)];
        std::vector<std::uint32_t> mine, ghosts;
        std::set<int> near;
        for (std::uint32_t u = 0; u < particles; ++u) {
            if (owner[u] == r) mine.push_back(u);
        }
        std::set<std::uint32_t> ghost_set;
        for (const Collision& c : all) {
            if (c.kind != CollisionKind::pair) continue;
            if (owner[c.i] == r && owner[c.j] != r) ghost_set.insert(c.j);
            if (owner[c.j] == r && owner[c.i] != r) ghost_set.insert(c.i);
        }
        ghosts.assign(ghost_set.begin(), ghost_set.end());
        // Local orders at random: neither side's order may matter.
        for (std::vector<std::uint32_t>* list : {&mine, &ghosts}) {
            for (std::size_t k = list->size(); k > 1; --k) std::swap((*list)[k - 1], (*list)[rng.next() % k]);
        }
        for (const std::uint32_t g : ghosts) near.insert(owner[g]);
        view.neighbours.assign(near.begin(), near.end());
        view.owned = static_cast<std::uint32_t>(mine.size());
        view.user = mine;
        view.user.insert(view.user.end(), ghosts.begin(), ghosts.end());
        std::map<std::uint32_t, std::uint32_t> local_of;
        for (std::uint32_t l = 0; l < view.user.size(); ++l) local_of[view.user[l]] = l;
        for (const std::uint32_t g : ghosts) {
            view.ghost_neighbour.push_back(static_cast<std::uint32_t>(
                std::find(view.neighbours.begin(), view.neighbours.end(), owner[g]) - view.neighbours.begin()));
        }
        for (const Collision& c : all) {
            const bool has_mine = owner[c.i] == r || (c.kind == CollisionKind::pair && owner[c.j] == r);
            if (!has_mine) continue;
            Collision local = c;
            local.i = local_of[c.i];
            if (c.kind == CollisionKind::pair) {
                local.j = local_of[c.j];
                if (rng.next() % 2 == 0) std::swap(local.i, local.j);  // stored out of the user's order
            }
            view.candidates.push_back(local);
            // A search may find a pair twice, on one side only.
            if (c.kind == CollisionKind::pair && rng.next() % 5 == 0) view.candidates.push_back(local);
        }
        for (std::size_t k = view.candidates.size(); k > 1; --k) {
            std::swap(view.candidates[k - 1], view.candidates[rng.next() % k]);
        }
    }
    // Neighbours are mutual only where both sides share a candidate; a rank
    // whose ghosts come from q is q's neighbour too (q holds that candidate).
    for (RankView& view : ranks) {
        view.collision_time.assign(view.user.size(), 0.0);
        view.selection.begin(view.candidates, view.owned, view.user, view.ghost_neighbour, view.neighbours.size(),
                             view.collision_time);
    }
    if (!run_rounds(ranks, rounds)) return false;

    const Outcome expected = greedy(particles, all);
    StepCounts counts;
    for (const RankView& view : ranks) {
        counts.particle_collisions += view.selection.accepted().particle_collisions;
        counts.wall_collisions += view.selection.accepted().wall_collisions;
        for (std::uint32_t l = 0; l < view.owned; ++l) {
            const std::uint32_t partner = view.selection.partner()[l];
            const std::uint32_t as_user = partner >= wall_collision ? partner : view.user[partner];
            if (as_user != expected.partner[view.user[l]]) return false;
        }
    }
    return counts.particle_collisions == expected.counts.particle_collisions &&
           counts.wall_collisions == expected.counts.wall_collisions;
}

void random_graphs_on_random_ranks() {
    SplitMix64 rng(77);
    int wrong = 0, most_rounds = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const auto particles = static_cast<std::uint32_t>(1 + rng.next() % 40);
        const int candidates = static_cast<int>(rng.next() % 120);
        const int ranks = 1 + static_cast<int>(rng.next() % 8);
        int rounds = 0;
        if (!distributed_matches_greedy(rng, particles, candidates, ranks, rounds)) ++wrong;
        most_rounds = std::max(most_rounds, rounds);
    }
    CHECK_EQ(wrong, 0);
    CHECK(most_rounds > 2);  // chains of conflicts were there to cross ranks
}

// A chain of conflicts through every rank (a Newton's cradle laid over the
// cuts): times fall along the chain, so each link waits on the next.
void a_chain_across_every_rank() {
    for (const int rank_count : {2, 3, 5, 8}) {
        const check::Context context("ranks " + std::to_string(rank_count));
        const std::uint32_t particles = 40;
        std::vector<Collision> chain;
        for (std::uint32_t i = 0; i + 1 < particles; ++i) {
            chain.push_back(Collision::pair(1.0 - i / 64.0, i, i + 1));
        }
        std::vector<RankView> ranks(static_cast<std::size_t>(rank_count));
        const auto owner = [&](std::uint32_t u) { return static_cast<int>(u * rank_count / particles); };
        for (int r = 0; r < rank_count; ++r) {
            RankView& view = ranks[static_cast<std::size_t>(r)];
            for (std::uint32_t u = 0; u < particles; ++u) {
                if (owner(u) == r) view.user.push_back(u);
            }
            view.owned = static_cast<std::uint32_t>(view.user.size());
            const std::uint32_t first = view.user.front(), last = view.user.back();
            if (r > 0) {
                view.neighbours.push_back(r - 1);
                view.user.push_back(first - 1);
                view.ghost_neighbour.push_back(0);
            }
            if (r + 1 < rank_count) {
                view.neighbours.push_back(r + 1);
                view.user.push_back(last + 1);
                view.ghost_neighbour.push_back(r > 0 ? 1U : 0U);
            }
            const auto local = [&](std::uint32_t u) {
                return static_cast<std::uint32_t>(std::find(view.user.begin(), view.user.end(), u) - view.user.begin());
            };
            for (const Collision& c : chain) {
                if (owner(c.i) == r || owner(c.j) == r)
                    view.candidates.push_back(Collision::pair(c.time, local(c.i), local(c.j)));
            }
        }
        for (RankView& view : ranks) {
            view.collision_time.assign(view.user.size(), 0.0);
            view.selection.begin(view.candidates, view.owned, view.user, view.ghost_neighbour, view.neighbours.size(),
                                 view.collision_time);
        }
        int rounds = 0;
        CHECK(run_rounds(ranks, rounds));
        // The greedy pass takes the latest link first (it comes first), then every other one.
        const Outcome expected = greedy(particles, chain);
        std::uint64_t accepted = 0;
        for (const RankView& view : ranks) {
            accepted += view.selection.accepted().particle_collisions;
            for (std::uint32_t l = 0; l < view.owned; ++l) {
                const std::uint32_t partner = view.selection.partner()[l];
                CHECK_EQ(partner >= wall_collision ? partner : view.user[partner], expected.partner[view.user[l]]);
            }
        }
        CHECK_EQ(accepted, expected.counts.particle_collisions);
        // Not a link a round: each rank decides its own links alone once its neighbour's is known, and where
        // that leaves more than half of what the round before left, one rank decides the rest.
        CHECK(rounds <= rank_count);
    }
}

}  // namespace

// A pile's pairs are taken in index order, one a round. On one rank, the
// rank decides them alone once a round leaves more than half of its
// candidates; across the cuts, once the rounds stall, one rank decides
// what is left. Either way the rounds stay few (piles of 100 to 300 took up
// to 131).
void a_pile_on_one_rank_or_across_the_cuts() {
    for (const bool spread : {false, true}) {
        check::Context context(spread ? "across the cuts" : "on one rank");
        SplitMix64 rng(spread ? 79 : 78);
        int wrong = 0, most_rounds = 0;
        for (int trial = 0; trial < 20; ++trial) {
            const auto piled = static_cast<std::uint32_t>(100 + rng.next() % 200);
            const auto particles = piled + static_cast<std::uint32_t>(rng.next() % 60);
            int rounds = 0;
            if (!distributed_matches_greedy(rng, particles, static_cast<int>(rng.next() % 400),
                                            2 + static_cast<int>(rng.next() % 3), rounds, piled, spread))
                ++wrong;
            most_rounds = std::max(most_rounds, rounds);
        }
        CHECK_EQ(wrong, 0);
        CHECK(most_rounds <= 12);
    }
}

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_rank_selection",
                      {{"random conflict graphs on random ranks give the greedy pass", random_graphs_on_random_ranks},
                       {"a chain across every rank", a_chain_across_every_rank},
                       {"a pile on one rank or across the cuts", a_pile_on_one_rank_or_across_the_cuts}});
}
