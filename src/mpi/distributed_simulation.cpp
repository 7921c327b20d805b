#include "particlesim/distributed_simulation.hpp"

#include "core/assert.hpp"
#include "core/box.hpp"
#include "core/collision.hpp"
#include "core/uniform_grid.hpp"
#include "input/scene_checks.hpp"
#include "input/stepped_options_check.hpp"
#include "mpi/domain_strips.hpp"
#include "mpi/neighbour_exchange.hpp"
#include "mpi/rank_selection.hpp"
#include "parallel/parallel.hpp"
#include "search/brute_force_search.hpp"
#include "search/grid_search.hpp"
#include "stepped/immediate_selection.hpp"
#include "stepped/step_pipeline.hpp"
#include "stepped/stepped_state.hpp"
#include "stepped/stepped_tuning.hpp"

#include <algorithm>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace particlesim {

namespace {

// Thrown by a rank's grid search whose first slice crowds its cells with
// disks meeting at t = 0 (GridSearch::crowded()), before it tests their
// pairs: the ranks decide those pairs together first.
struct CrowdedFirstSlice : std::exception {
    [[nodiscard]] const char* what() const noexcept override { return "a crowded first slice"; }
};

// What a rank's grid search is told of the disks decided before it: none
// while probing (a crowded first slice then stops it), the pairs at t = 0
// decided on rank 0 when it searches again, which it leaves out. The rounds
// decide the rest: no stage decides anything here.
class DecidedAtZero final : public SliceDecisions {
public:
    // `left_out`: by local disk, no_collision or not (empty while probing).
    DecidedAtZero(std::span<std::uint32_t> left_out, bool probing) : SliceDecisions(left_out), probing_(probing) {}
    void decide_before(double, std::span<ThreadCandidates>, int) override {}
    void decide_pairs_at_zero() override {
        if (probing_) throw CrowdedFirstSlice();
    }

private:
    bool probing_;
};

// A particle on its way to another rank (a ghost or a migrant), with its
// index in the scene; plain numbers, sent as bytes.
struct Travelling {
    double x, y, vx, vy;
    std::uint64_t particle_collisions, wall_collisions;
    std::uint64_t user_index;

    Travelling() = default;
    Travelling(const Particle& p, std::uint64_t user)
        : x(p.position.x()),
          y(p.position.y()),
          vx(p.velocity.x()),
          vy(p.velocity.y()),
          particle_collisions(p.particle_collisions),
          wall_collisions(p.wall_collisions),
          user_index(user) {}

    [[nodiscard]] Particle particle() const { return {Vec2(x, y), Vec2(vx, vy), particle_collisions, wall_collisions}; }
};

// Message tags: each exchange uses its tag and the next.
constexpr int tag_ghosts = 10;
constexpr int tag_claims = 20;
constexpr int tag_taken = 30;
constexpr int tag_migrants = 40;

constexpr int root = 0;
// Bins of the histogram of x the cuts are placed by.
constexpr std::size_t cut_bins = 16384;
// Steps between checks of the balance, and the excess over the mean count
// that moves the cuts.
constexpr std::int64_t balance_every = 16;
// Steps between sorts of a rank's particles by position. Sparser than the
// one-process engine's 8: a rank sorts in place along the permutation's
// cycles (no second copy of its particles), which costs more per sort.
constexpr int sort_every_steps = 32;
constexpr double allowed_imbalance = 1.1;

// How far apart two centres can be and still meet within `duration`: both
// move at most `max_speed` * duration. Widened so that no rounding of this
// or of a centre's distance to a cut can leave a partner out; a wider
// halo only adds ghosts.
double halo_reach(const World& world, double max_speed, double duration) {
    return (2.0 * world.radius + 2.0 * max_speed * duration) * (1.0 + 1e-9) + 1e-300;
}

// Every rank throws the refusal `from` found (empty: none), so that all
// leave a collective construction together.
void agree_on_refusal(MPI_Comm comm, std::string refusal, int from = root) {
    std::uint64_t length = refusal.size();
    MPI_Bcast(&length, 1, MPI_UINT64_T, from, comm);
    if (length == 0) return;
    refusal.resize(length);
    MPI_Bcast(refusal.data(), static_cast<int>(length), MPI_CHAR, from, comm);
    throw std::invalid_argument(refusal);
}

// Every rank checks its own options and every rank throws the refusal of
// the lowest rank that has one: ranks given different options still leave
// together.
const SteppedOptions& agreed_options(MPI_Comm comm, const SteppedOptions& options) {
    std::string refusal;
    try {
        require_valid_stepped_options(options);
    } catch (const std::invalid_argument& e) {
        refusal = e.what();
    }
    int rank = 0;
    int ranks = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &ranks);
    int first_refusing = refusal.empty() ? ranks : rank;
    MPI_Allreduce(MPI_IN_PLACE, &first_refusing, 1, MPI_INT, MPI_MIN, comm);
    if (first_refusing < ranks) agree_on_refusal(comm, refusal, first_refusing);
    return options;
}

}  // namespace

class DistributedSimulation::Implementation {
public:
    Implementation(MPI_Comm comm, const World& world, const SteppedOptions& options)
        : world_(world), box_(Box::of(world)), options_(options) {
        require_mpi(MPI_Comm_dup(comm, &comm_), "duplicating the communicator");
        MPI_Comm_rank(comm_, &rank_);
        MPI_Comm_size(comm_, &ranks_);
        exchange_ = NeighbourExchange(comm_, &counts_);
        threads_ = options_.threads.value_or(default_thread_count());
        search_ = options_.pair_search == PairSearch::brute_force ? PairSearch::brute_force : PairSearch::grid;
        strips_ = DomainStrips(std::vector<double>(static_cast<std::size_t>(ranks_ - 1), 0.0));
    }
    ~Implementation() {
        if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
    }
    Implementation(const Implementation&) = delete;
    Implementation& operator=(const Implementation&) = delete;

    // Rank 0's particles, checked there and handed out in parts by strip.
    void distribute(std::vector<Particle> particles, std::int64_t steps_done, const StepCounts& totals) {
        std::string refusal;
        if (rank_ == root) {
            try {
                require_valid_scene("particlesim::DistributedSimulation", world_, particles);
            } catch (const std::invalid_argument& e) {
                refusal = e.what();
            }
        }
        agree_on_refusal(comm_, refusal);
        std::uint64_t header[2] = {particles.size(), static_cast<std::uint64_t>(steps_done)};
        MPI_Bcast(header, 2, MPI_UINT64_T, root, comm_);
        count_ = header[0];
        steps_done_ = static_cast<std::int64_t>(header[1]);
        std::uint64_t sums[3] = {totals.particle_collisions, totals.wall_collisions, totals.pair_tests};
        MPI_Bcast(sums, 3, MPI_UINT64_T, root, comm_);
        totals_ = {sums[0], sums[1], sums[2]};
        if (options_.pair_search == PairSearch::automatic) {
            search_ = count_ < stepped_tuning::brute_force_below ? PairSearch::brute_force : PairSearch::grid;
        }
        // The cuts from rank 0's histogram, then each part's particles to their owners.
        std::vector<std::uint64_t> histogram(cut_bins, 0);
        if (rank_ == root) add_to_histogram(particles, histogram);
        strips_ = DomainStrips(balanced_cuts(histogram, world_.box_size, ranks_));
        broadcast_cuts();
        const std::size_t part = std::size_t{1} << 16;
        const BytesType<Travelling> travelling;
        std::vector<int> counts(static_cast<std::size_t>(ranks_)), displacements(counts.size());
        // Each rank's share first, so that it takes its room once.
        std::vector<std::uint64_t> shares(counts.size(), 0);
        if (rank_ == root) {
            for (const Particle& p : particles) ++shares[static_cast<std::size_t>(owner(p))];
        }
        std::uint64_t share = 0;
        MPI_Scatter(shares.data(), 1, MPI_UINT64_T, &share, 1, MPI_UINT64_T, root, comm_);
        make_room(share);
        std::vector<Travelling> sorted;
        for (std::uint64_t first = 0; first < count_; first += part) {
            const std::uint64_t last = std::min<std::uint64_t>(count_, first + part);
            if (rank_ == root) {
                std::fill(counts.begin(), counts.end(), 0);
                for (std::uint64_t u = first; u < last; ++u) ++counts[owner(particles[u])];
                std::exclusive_scan(counts.begin(), counts.end(), displacements.begin(), 0);
                sorted.resize(last - first);
                std::vector<int> place = displacements;
                for (std::uint64_t u = first; u < last; ++u) {
                    sorted[static_cast<std::size_t>(place[owner(particles[u])]++)] = Travelling(particles[u], u);
                }
            }
            int mine = 0;
            MPI_Scatter(counts.data(), 1, MPI_INT, &mine, 1, MPI_INT, root, comm_);
            incoming_.resize(static_cast<std::size_t>(mine));
            require_mpi(MPI_Scatterv(sorted.data(), counts.data(), displacements.data(), travelling.get(),
                                     incoming_.data(), mine, travelling.get(), root, comm_),
                        "handing out the particles");
            for (const Travelling& t : incoming_) adopt(t);
        }
        incoming_ = {};
        sorted = {};
        particles = {};
#ifdef __GLIBC__
        malloc_trim(0);  // rank 0's copy of the scene is gone: its pages go back before the run
#endif
        sort_by_position();
    }

    void step() {
        last_step_ = {};
        if (steps_done_ > 0 && steps_done_ % balance_every == 0) balance();
        const int sort_every = options_.sort_by_position_every.value_or(
            count_ >= stepped_tuning::sort_by_position_from ? sort_every_steps : 0);
        if (sort_every > 0 && ++steps_since_sort_ >= sort_every) {
            sort_by_position();
            steps_since_sort_ = 0;
        }
        const double duration = 1.0 / options_.substeps;
        for (int micro = 0; micro < options_.substeps; ++micro) micro_step(duration);
        std::uint64_t sums[3] = {last_step_.particle_collisions, last_step_.wall_collisions, last_step_.pair_tests};
        all_reduce(sums, 3, MPI_UINT64_T, MPI_SUM);
        last_step_ = {sums[0], sums[1], sums[2]};
        totals_ += last_step_;
        ++steps_done_;
    }

    void gather(const PartSink& sink, std::size_t part_size) const {
        part_size = std::max<std::size_t>(part_size, 1);
        std::vector<std::uint32_t> by_user(owned_);
        std::iota(by_user.begin(), by_user.end(), 0U);
        std::sort(by_user.begin(), by_user.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return user_[a] < user_[b]; });
        const BytesType<Travelling> travelling;
        std::vector<Travelling> mine;
        std::vector<Travelling> received;
        std::vector<Particle> part;
        std::vector<int> counts(static_cast<std::size_t>(ranks_)), displacements(counts.size());
        std::size_t next = 0;
        for (std::uint64_t first = 0; first < count_; first += part_size) {
            const std::uint64_t last = std::min<std::uint64_t>(count_, first + part_size);
            mine.clear();
            while (next < by_user.size() && user_[by_user[next]] < last) {
                mine.emplace_back(local_[by_user[next]], user_[by_user[next]]);
                ++next;
            }
            int size = static_cast<int>(mine.size());
            MPI_Gather(&size, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_);
            if (rank_ == root) {
                std::exclusive_scan(counts.begin(), counts.end(), displacements.begin(), 0);
                received.resize(last - first);
            }
            require_mpi(MPI_Gatherv(mine.data(), size, travelling.get(), received.data(), counts.data(),
                                    displacements.data(), travelling.get(), root, comm_),
                        "gathering the particles");
            if (rank_ != root) continue;
            part.resize(last - first);
            for (const Travelling& t : received) part[t.user_index - first] = t.particle();
            sink(first, part);
        }
    }

    // The ranks' undecided candidates, and their particles taken that shared
    // ones name, gathered on the root, which decides them all by the greedy
    // pass; every rank takes what it accepted (rank_selection.hpp).
    void decide_the_rest_on_one_rank() {
        std::vector<Collision> accepted =
            decide_in_order(gather_on_root(selection_.undecided_by_user(), "gathering the undecided candidates"),
                            gather_on_root(selection_.taken_shared_by_user(), "gathering the taken particles"));
        broadcast_from_root(accepted, "sending the accepted candidates");
        selection_.take_accepted(accepted);
    }

    // The root's `collisions` to every rank.
    void broadcast_from_root(std::vector<Collision>& collisions, const char* what) {
        std::uint64_t count = collisions.size();
        require_mpi(MPI_Bcast(&count, 1, MPI_UINT64_T, root, comm_), what);
        if (rank_ != root) collisions.resize(count);
        const BytesType<Collision> type;
        require_mpi(MPI_Bcast(collisions.data(), static_cast<int>(count), type.get(), root, comm_), what);
    }

    // The owned disks that may have a pair at t = 0: no wall at t = 0 (read
    // before the selection writes collision times over the wall times).
    std::vector<Travelling> owned_able_to_pair() const {
        std::vector<Travelling> able;
        for (std::size_t k = 0; k < owned_; ++k) {
            if (wall_time_[k] > 0.0) able.emplace_back(local_[k], user_[k]);
        }
        return able;
    }

    // The candidates of the local disks not left out (`decisions`, for the
    // grid; `pairs_at_zero`: see GridSearch::find_pairs()) after the walls
    // of the owned disks, in candidates_.
    void find_candidates(double duration, bool carried, SliceDecisions* decisions, SliceDecisions* pairs_at_zero) {
        candidates_.clear();
        for (std::uint32_t k = 0; k < owned_; ++k) {
            if (wall_time_[k] <= duration) candidates_.push_back(Collision::wall(wall_time_[k], k));
        }
        thread_candidates_.resize(static_cast<std::size_t>(threads_));
        for (ThreadCandidates& thread : thread_candidates_) {
            thread.found.clear();
            thread.pair_tests = 0;
        }
        immediate_.reset(stepped_tuning::immediate_candidates_per_particle * local_.size() +
                         stepped_tuning::immediate_candidates_floor);
        const PairSearchInput input{
            local_,
            wall_time_,
            box_,
            duration,
            !carried && start_.with_motion ? std::span<const BlockStart>(start_.blocks) : std::span<const BlockStart>(),
            0.0,
            &immediate_};
        const auto count_tests = [&] {
            for (const ThreadCandidates& thread : thread_candidates_) last_step_.pair_tests += thread.pair_tests;
        };
        try {
            if (search_ == PairSearch::brute_force) {
                find_pairs_brute_force(input, thread_candidates_);
            } else {
                grid_.find_pairs(input, options_.grid_cells, thread_candidates_, decisions, pairs_at_zero);
            }
        } catch (const CrowdedFirstSlice&) {
            count_tests();
            throw;
        }
        count_tests();
        for (const ThreadCandidates& thread : thread_candidates_) {
            for (const Collision& c : thread.found) {
                if (c.i < owned_ || c.j < owned_) candidates_.push_back(c);
            }
        }
    }

    // Marks in left_out_ (no_collision elsewhere) the local disks, owned or
    // ghosts, of `decided`, by user index.
    void leave_out(std::span<const Collision> decided) {
        left_out_.assign(local_.size(), no_collision);
        const LocalByUser local(user_);
        for (const Collision& c : decided) {
            for (const std::uint32_t user : {c.i, c.j}) {
                if (const std::uint32_t l = local(user); l != no_collision) left_out_[l] = user;
            }
        }
    }

    // Every rank's disks that may have a pair at t = 0 gathered on the root,
    // which decides those pairs by the one-process rule
    // (select_immediate_pairs(): they come before every other candidate);
    // every rank gets the accepted pairs, by user index, and the rounds
    // decide the rest. Memory linear in N, where the pairs' candidates grow
    // as a pile's size squared.
    std::vector<Collision> decide_immediate_pairs_on_one_rank(const std::vector<Travelling>& able, double duration) {
        std::vector<Collision> accepted;
        const std::vector<Travelling> all = gather_on_root(able, "gathering the piled particles");
        if (rank_ == root) {
            std::vector<Particle> particles;
            std::vector<std::uint32_t> users;
            particles.reserve(all.size());
            users.reserve(all.size());
            for (const Travelling& t : all) {
                particles.push_back(t.particle());
                users.push_back(static_cast<std::uint32_t>(t.user_index));
            }
            const std::vector<double> no_wall(all.size(), never);
            std::vector<std::uint32_t> partner(all.size(), no_collision);
            std::vector<double> time(all.size());
            select_immediate_pairs(PairSearchInput{particles, no_wall, box_, duration}, users, partner, time);
            for (std::uint32_t k = 0; k < partner.size(); ++k) {
                if (partner[k] == no_collision || partner[k] < k) continue;
                const auto [low, high] = std::minmax(users[k], users[partner[k]]);
                accepted.push_back(Collision::pair(0.0, low, high));
            }
        }
        broadcast_from_root(accepted, "sending the pairs at t = 0");
        return accepted;
    }

    // Every rank's `mine`, one after another on the root (empty elsewhere).
    template <typename T>
    std::vector<T> gather_on_root(const std::vector<T>& mine, const char* what) {
        const BytesType<T> type;
        int size = static_cast<int>(mine.size());
        std::vector<int> counts(rank_ == root ? static_cast<std::size_t>(ranks_) : 0), displacements(counts.size());
        require_mpi(MPI_Gather(&size, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_), what);
        std::vector<T> all;
        if (rank_ == root) {
            std::exclusive_scan(counts.begin(), counts.end(), displacements.begin(), 0);
            all.resize(static_cast<std::size_t>(displacements.back() + counts.back()));
        }
        require_mpi(MPI_Gatherv(mine.data(), size, type.get(), all.data(), counts.data(), displacements.data(),
                                type.get(), root, comm_),
                    what);
        return all;
    }

    const World& world() const { return world_; }
    std::uint64_t particle_count() const { return count_; }
    std::int64_t steps_done() const { return steps_done_; }
    const StepCounts& last_step() const { return last_step_; }
    const StepCounts& totals() const { return totals_; }
    PairSearch pair_search() const { return search_; }
    int threads() const { return threads_; }
    int rank() const { return rank_; }
    int ranks() const { return ranks_; }
    std::size_t owned_count() const { return owned_; }
    std::size_t peak_local_count() const { return peak_local_; }
    const ExchangeCounts& exchange_counts() const { return counts_; }

private:
    int owner(const Particle& p) const { return strips_.owner_of(p.position.x()); }

    // An all-reduction of the step (counted and timed for the scaling model).
    void all_reduce(void* values, int count, MPI_Datatype type, MPI_Op op) {
        const auto start = std::chrono::steady_clock::now();
        require_mpi(MPI_Allreduce(MPI_IN_PLACE, values, count, type, op, comm_), "an all-reduction");
        ++counts_.collectives;
        counts_.seconds_exchanging += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    void add_to_histogram(std::span<const Particle> particles, std::vector<std::uint64_t>& histogram) const {
        const UniformGrid bins(world_.box_size, static_cast<int>(histogram.size()));
        for (const Particle& p : particles) ++histogram[static_cast<std::size_t>(bins.column_of(p.position.x()))];
    }

    void broadcast_cuts() {
        std::vector<double> cuts(strips_.inner_cuts().begin(), strips_.inner_cuts().end());
        MPI_Bcast(cuts.data(), static_cast<int>(cuts.size()), MPI_DOUBLE, root, comm_);
        strips_ = DomainStrips(std::move(cuts));
    }

    // An owned particle arrives (from rank 0's hand-out or a neighbour).
    void adopt(const Travelling& t) {
        local_.resize(owned_);
        user_.resize(owned_);
        local_.push_back(t.particle());
        user_.push_back(static_cast<std::uint32_t>(t.user_index));
        ++owned_;
        if (carried_.current) carry(local_.back());
    }

    // What the free flight measured of the owned particles for the next
    // micro-step, kept through migration: their first wall times (in
    // wall_time_) and their largest speed, so that neither costs another
    // pass. Anything that changes the owned particles otherwise clears it.
    void carry(const Particle& p) {
        wall_time_.resize(owned_ - 1);
        wall_time_.push_back(first_wall_time(p));
        carried_.max_speed_squared = std::max(carried_.max_speed_squared, p.velocity.squaredNorm());
    }
    [[nodiscard]] double first_wall_time(const Particle& p) const {
        BlockStart unused;
        return unused.measure<false>(p, box_, 1.0 / options_.substeps);
    }

    // Room for `needed` particles, with a little more for the ghosts and
    // migrants to come: taken rarely, rather than doubled on the way (a
    // doubling holds two copies of every particle for a moment).
    void make_room(std::size_t needed) {
        if (local_.capacity() >= needed && user_.capacity() >= needed) return;
        const std::size_t wanted = needed + needed / 64 + 1024;
        local_.reserve(wanted);
        user_.reserve(wanted);
    }

    // Owned particles in row-major cell order over the extent they cover,
    // for locality (as the one-process engine's storage order): a counting
    // sort by cell, applied in place along the permutation's cycles.
    void sort_by_position() {
        carried_.current = false;
        if (owned_ < 2) return;
        local_.resize(owned_);
        user_.resize(owned_);
        double low = local_[0].position.x(), high = low;
        for (const Particle& p : local_) {
            low = std::min(low, p.position.x());
            high = std::max(high, p.position.x());
        }
        const double width = high - low, height = world_.box_size;
        const double cell = std::max(4.0 * world_.radius, std::sqrt(width * height / static_cast<double>(owned_)));
        const auto columns = static_cast<std::uint32_t>(std::min(width / cell + 1.0, 65536.0));
        const auto rows = static_cast<std::uint32_t>(std::min(height / cell + 1.0, 65536.0));
        const auto cell_of = [&](const Particle& p) {
            const auto column = std::min(columns - 1, static_cast<std::uint32_t>((p.position.x() - low) / cell));
            const auto row = std::min(rows - 1, static_cast<std::uint32_t>(std::max(0.0, p.position.y()) / cell));
            return static_cast<std::size_t>(row) * columns + column;
        };
        cell_start_.assign(static_cast<std::size_t>(columns) * rows + 1, 0);
        for (const Particle& p : local_) ++cell_start_[cell_of(p) + 1];
        std::partial_sum(cell_start_.begin(), cell_start_.end(), cell_start_.begin());
        destination_.resize(owned_);
        for (std::size_t k = 0; k < owned_; ++k) destination_[k] = cell_start_[cell_of(local_[k])]++;
        for (std::uint32_t k = 0; k < owned_; ++k) {
            while (destination_[k] != k) {
                const std::uint32_t to = destination_[k];
                std::swap(local_[k], local_[to]);
                std::swap(user_[k], user_[to]);
                std::swap(destination_[k], destination_[to]);
            }
        }
    }

    // Moves the cuts when one strip holds too many more than the mean.
    void balance() {
        std::uint64_t most = owned_;
        MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_UINT64_T, MPI_MAX, comm_);
        if (static_cast<double>(most) <= allowed_imbalance * static_cast<double>(count_) / ranks_ + 64.0) return;
        carried_.current = false;
        std::vector<std::uint64_t> histogram(cut_bins, 0);
        add_to_histogram(std::span(local_).first(owned_), histogram);
        MPI_Allreduce(MPI_IN_PLACE, histogram.data(), static_cast<int>(histogram.size()), MPI_UINT64_T, MPI_SUM, comm_);
        strips_ = DomainStrips(balanced_cuts(histogram, world_.box_size, ranks_));
        // Any rank may now own any particle: every rank sends to every rank.
        std::vector<std::vector<Travelling>> leaving(static_cast<std::size_t>(ranks_));
        keep_owned_or_send([&](int to, const Travelling& t) { leaving[static_cast<std::size_t>(to)].push_back(t); });
        std::vector<int> to_all(static_cast<std::size_t>(ranks_)), from_all(to_all.size());
        for (int r = 0; r < ranks_; ++r) to_all[r] = static_cast<int>(leaving[r].size());
        MPI_Alltoall(to_all.data(), 1, MPI_INT, from_all.data(), 1, MPI_INT, comm_);
        std::vector<int> to_at(to_all.size()), from_at(to_all.size());
        std::exclusive_scan(to_all.begin(), to_all.end(), to_at.begin(), 0);
        std::exclusive_scan(from_all.begin(), from_all.end(), from_at.begin(), 0);
        std::vector<Travelling> out;
        for (const std::vector<Travelling>& list : leaving) out.insert(out.end(), list.begin(), list.end());
        incoming_.resize(static_cast<std::size_t>(from_at.back() + from_all.back()));
        const BytesType<Travelling> travelling;
        require_mpi(MPI_Alltoallv(out.data(), to_all.data(), to_at.data(), travelling.get(), incoming_.data(),
                                  from_all.data(), from_at.data(), travelling.get(), comm_),
                    "moving particles to the new strips");
        for (const Travelling& t : incoming_) adopt(t);
        sort_by_position();
        steps_since_sort_ = 0;
    }

    // Keeps the owned particles still in this rank's strip, in order, and
    // hands every other one to `send` with its new owner.
    template <typename Send>
    void keep_owned_or_send(Send&& send) {
        std::size_t kept = 0;
        const bool carry_times = carried_.current;
        double max_speed_squared = 0.0;
        // Most particles stay: nothing moves up to the first that leaves.
        while (kept < owned_ && owner(local_[kept]) == rank_) {
            max_speed_squared = std::max(max_speed_squared, local_[kept].velocity.squaredNorm());
            ++kept;
        }
        for (std::size_t k = kept; k < owned_; ++k) {
            const int to = owner(local_[k]);
            if (to == rank_) {
                max_speed_squared = std::max(max_speed_squared, local_[k].velocity.squaredNorm());
                local_[kept] = local_[k];
                user_[kept] = user_[k];
                if (carry_times) wall_time_[kept] = wall_time_[k];
                ++kept;
            } else {
                send(to, Travelling{local_[k], user_[k]});
            }
        }
        owned_ = kept;
        local_.resize(owned_);
        user_.resize(owned_);
        if (carry_times) wall_time_.resize(owned_);
        carried_.max_speed_squared = max_speed_squared;
    }

    void micro_step(double duration) {
        // The halo: as wide as this micro-step's fastest particle makes it.
        double max_speed_squared = carried_.max_speed_squared;
        if (!carried_.current) {
            max_speed_squared = 0.0;
            for (std::size_t k = 0; k < owned_; ++k) {
                max_speed_squared = std::max(max_speed_squared, local_[k].velocity.squaredNorm());
            }
        }
        all_reduce(&max_speed_squared, 1, MPI_DOUBLE, MPI_MAX);
        const double max_speed = std::sqrt(max_speed_squared);
        ++counts_.micro_steps;
        const double reach = halo_reach(world_, max_speed, duration);
        neighbours_ = strips_.neighbours_of(rank_, reach);
        const std::size_t near = neighbours_.size();

        exchange_ghosts(reach);
        const std::size_t local = local_.size();
        peak_local_ = std::max(peak_local_, local);

        // Detect: the owned particles' walls, the pairs with an owned particle.
        // The wall times: carried from the last free flight (the ghosts'
        // measured as they came), or measured afresh.
        const bool carried = carried_.current;
        if (!carried) {
            wall_time_.resize(local);
            start_.with_motion = search_ == PairSearch::grid;
            measure_step_start(local_, box_, duration, wall_time_, start_, threads_);
        }
        PARTICLESIM_ASSERT(wall_time_.size() == local, "every local particle has its first wall time");
        if constexpr (validating) {
            for (std::size_t k = 0; k < local; ++k) {
                PARTICLESIM_ASSERT(wall_time_[k] == first_wall_time(local_[k]),
                                   "the carried wall times are those of the particles as they are");
            }
        }
        // A first slice crowded with piled disks stops the grid's search
        // (DecidedAtZero): it is searched again once their pairs at t = 0
        // are decided, without their disks.
        DecidedAtZero probe({}, true);  // it stops the search before anything reads what it decided
        bool crowded = false;
        try {
            find_candidates(duration, carried, nullptr, &probe);
        } catch (const CrowdedFirstSlice&) {
            crowded = true;
        }

        // Select, in rounds with the neighbours.
        // wall_time_ holds each particle's first wall time up to here, then
        // the time of its accepted collision (as in the one-process engine).
        // Where any rank's search dropped candidates at t = 0, or stopped at
        // a crowd, their pairs are decided first, on one rank.
        int pairs_at_zero_first = immediate_.overflowed() || crowded ? 1 : 0;
        all_reduce(&pairs_at_zero_first, 1, MPI_INT, MPI_MAX);
        std::vector<Collision> decided_first;
        if (pairs_at_zero_first != 0) {
            decided_first = decide_immediate_pairs_on_one_rank(owned_able_to_pair(), duration);
            leave_out(decided_first);
            if (crowded) {
                DecidedAtZero known(left_out_, false);
                find_candidates(duration, carried, &known, nullptr);
            }
            // What is left of the pairs at t = 0, and every candidate of a
            // disk decided, are ruled out: all go, so that the ranks list
            // the same shared candidates whichever searched again.
            std::erase_if(candidates_, [&](const Collision& c) {
                return (c.kind == CollisionKind::pair && (c.time == 0.0 || left_out_[c.j] != no_collision)) ||
                       left_out_[c.i] != no_collision;
            });
        }
        selection_.begin(candidates_, static_cast<std::uint32_t>(owned_), user_, ghost_neighbour_, near, wall_time_);
        if (pairs_at_zero_first != 0) selection_.take_decided_first(decided_first);
        outgoing_bytes_.resize(near);
        incoming_bytes_.resize(near);
        std::uint64_t left_before = 0;
        for (int round = 1;; ++round) {
            selection_.claim();
            for (std::size_t n = 0; n < near; ++n) {
                selection_.write_claims(n, outgoing_bytes_[n]);
                incoming_bytes_[n].resize(selection_.shared_with(n));
            }
            exchange_.exchange(std::span<const int>(neighbours_), outgoing_bytes_, incoming_bytes_, tag_claims, true);
            selection_.accept(incoming_bytes_);
            for (std::size_t n = 0; n < near; ++n) selection_.write_taken(n, outgoing_bytes_[n]);
            exchange_.exchange(std::span<const int>(neighbours_), outgoing_bytes_, incoming_bytes_, tag_taken, true);
            std::uint64_t undecided = selection_.end_round(incoming_bytes_);
            all_reduce(&undecided, 1, MPI_UINT64_T, MPI_SUM);
            ++counts_.selection_rounds;
            if (undecided == 0) break;
            // Stalled: a pile of disks across a cut, whose shared pairs are decided one a round.
            if (round > 1 && selection_stalled(left_before, undecided)) {
                decide_the_rest_on_one_rank();
                break;
            }
            left_before = undecided;
        }
        last_step_.particle_collisions += selection_.accepted().particle_collisions;
        last_step_.wall_collisions += selection_.accepted().wall_collisions;

        // Resolve (a shared pair on both its ranks, each keeping its own
        // particle) and advance; the ghosts are then dropped.
        const std::span<std::uint32_t> partner = selection_.partner();
        resolve_collisions(local_, partner, wall_time_, selection_.accepted(), box_, duration, threads_);
        advance_free_particles(std::span(local_).first(owned_), partner.first(owned_), box_, duration,
                               std::span(wall_time_).first(owned_), next_start_, threads_);
        local_.resize(owned_);
        user_.resize(owned_);
        wall_time_.resize(owned_);
        carried_.current = true;  // the free flight measured the owned particles' next wall times
        migrate();
    }

    // Copies of the owned particles near each neighbour's strip become its ghosts.
    void exchange_ghosts(double reach) {
        const std::size_t near = neighbours_.size();
        outgoing_.resize(near);
        for (std::vector<Travelling>& list : outgoing_) list.clear();
        // Only particles within the reach of the strip's edges can be near
        // another strip (the test below, from this rank's strip, is implied
        // by the one against each neighbour).
        const double lower = strips_.lower(rank_), upper = strips_.upper(rank_);
        for (std::size_t k = 0; k < owned_; ++k) {
            const double x = local_[k].position.x();
            if (x - lower > reach && upper - x > reach) continue;
            for (std::size_t n = 0; n < near; ++n) {
                if (strips_.near(x, neighbours_[n], reach)) outgoing_[n].emplace_back(local_[k], user_[k]);
            }
        }
        exchange_.exchange(std::span<const int>(neighbours_), outgoing_, incoming_lists_, tag_ghosts);
        std::size_t ghosts = 0;
        for (const std::vector<Travelling>& list : incoming_lists_) ghosts += list.size();
        counts_.ghosts_received += ghosts;
        make_room(owned_ + ghosts);
        ghost_neighbour_.clear();
        for (std::size_t n = 0; n < near; ++n) {
            for (const Travelling& t : incoming_lists_[n]) {
                local_.push_back(t.particle());
                user_.push_back(static_cast<std::uint32_t>(t.user_index));
                ghost_neighbour_.push_back(static_cast<std::uint32_t>(n));
                if (carried_.current) wall_time_.push_back(first_wall_time(local_.back()));
            }
        }
    }

    // Particles that left the strip go to their new owner, a neighbour (no
    // particle moves farther than the halo's reach in a step).
    void migrate() {
        outgoing_.resize(neighbours_.size());
        for (std::vector<Travelling>& list : outgoing_) list.clear();
        keep_owned_or_send([&](int to, const Travelling& t) {
            const auto at = std::find(neighbours_.begin(), neighbours_.end(), to);
            if (at == neighbours_.end()) throw std::logic_error("a particle moved beyond the neighbouring strips");
            outgoing_[static_cast<std::size_t>(at - neighbours_.begin())].push_back(t);
        });
        exchange_.exchange(std::span<const int>(neighbours_), outgoing_, incoming_lists_, tag_migrants);
        std::size_t arriving = 0;
        for (const std::vector<Travelling>& list : incoming_lists_) arriving += list.size();
        counts_.migrants_received += arriving;
        make_room(owned_ + arriving);
        for (const std::vector<Travelling>& list : incoming_lists_) {
            for (const Travelling& t : list) adopt(t);
        }
    }

    World world_;
    Box box_;
    SteppedOptions options_;
    MPI_Comm comm_ = MPI_COMM_NULL;
    int rank_ = 0;
    int ranks_ = 1;
    int threads_ = 1;
    PairSearch search_ = PairSearch::grid;
    DomainStrips strips_;
    NeighbourExchange exchange_;
    std::uint64_t count_ = 0;

    // Local particles: the owned ones first, then (during a step) the ghosts.
    std::vector<Particle> local_;
    std::vector<std::uint32_t> user_;  // by local particle: its index in the scene
    std::size_t owned_ = 0;
    std::vector<std::uint32_t> ghost_neighbour_;  // by ghost: its owner's place in neighbours_
    std::vector<int> neighbours_;
    std::size_t peak_local_ = 0;
    int steps_since_sort_ = 0;  // sorted when handed out or balanced, then every sort_every steps

    std::vector<double> wall_time_;
    struct {
        bool current = false;
        double max_speed_squared = 0.0;
    } carried_;
    StepStart start_;
    StepStart next_start_;  // measured by the advance and not used: ghosts change every step
    std::vector<Collision> candidates_;
    std::vector<ThreadCandidates> thread_candidates_;
    ImmediateCandidateBudget immediate_;
    std::vector<std::uint32_t> left_out_;  // by local disk: no_collision, or decided before the search
    GridSearch grid_;
    RankSelection selection_;
    std::vector<std::uint32_t> cell_start_;   // the sort by position's, reused
    std::vector<std::uint32_t> destination_;  // likewise
    std::vector<std::vector<Travelling>> outgoing_;
    std::vector<std::vector<Travelling>> incoming_lists_;
    std::vector<Travelling> incoming_;
    std::vector<std::vector<std::uint8_t>> outgoing_bytes_;
    std::vector<std::vector<std::uint8_t>> incoming_bytes_;

    std::int64_t steps_done_ = 0;
    StepCounts last_step_;
    StepCounts totals_;
    ExchangeCounts counts_;
};

DistributedSimulation::DistributedSimulation(MPI_Comm comm, const World& world, std::vector<Particle> particles_on_root,
                                             const SteppedOptions& options)
    : engine_(std::make_unique<Implementation>(comm, world, agreed_options(comm, options))) {
    engine_->distribute(std::move(particles_on_root), 0, {});
}

DistributedSimulation::DistributedSimulation(std::unique_ptr<Implementation> engine) : engine_(std::move(engine)) {}

DistributedSimulation DistributedSimulation::restore(MPI_Comm comm, const World& world, std::istream* saved_on_root,
                                                     const SteppedOptions& options) {
    auto engine = std::make_unique<Implementation>(comm, world, agreed_options(comm, options));
    SteppedState state;
    std::string refusal;
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (rank == root) {
        try {
            state = read_stepped_state(*saved_on_root,
                                       "particlesim::DistributedSimulation::restore: the saved state is damaged");
        } catch (const std::invalid_argument& e) {
            refusal = e.what();
        }
    }
    agree_on_refusal(comm, refusal);
    engine->distribute(std::move(state.particles), state.steps_done, state.totals);
    return DistributedSimulation(std::move(engine));
}

void DistributedSimulation::save(const TextSink& write) const {
    std::ostringstream text;
    if (engine_->rank() == root) {
        write_stepped_state_head(text, particle_count(), steps_done(), totals());
        write(text.view());
    }
    gather([&](std::size_t, std::span<const Particle> part) {
        text.str({});
        for (const Particle& p : part) write_stepped_state_particle(text, p);
        write(text.view());
    });
}

DistributedSimulation::~DistributedSimulation() = default;
DistributedSimulation::DistributedSimulation(DistributedSimulation&&) noexcept = default;
DistributedSimulation& DistributedSimulation::operator=(DistributedSimulation&&) noexcept = default;

void DistributedSimulation::step() { engine_->step(); }
void DistributedSimulation::gather(const PartSink& part, std::size_t part_size) const {
    engine_->gather(part, part_size);
}
const World& DistributedSimulation::world() const { return engine_->world(); }
std::uint64_t DistributedSimulation::particle_count() const { return engine_->particle_count(); }
std::int64_t DistributedSimulation::steps_done() const { return engine_->steps_done(); }
const StepCounts& DistributedSimulation::last_step() const { return engine_->last_step(); }
const StepCounts& DistributedSimulation::totals() const { return engine_->totals(); }
PairSearch DistributedSimulation::pair_search() const { return engine_->pair_search(); }
int DistributedSimulation::threads() const { return engine_->threads(); }
int DistributedSimulation::rank() const { return engine_->rank(); }
int DistributedSimulation::ranks() const { return engine_->ranks(); }
std::size_t DistributedSimulation::owned_count() const { return engine_->owned_count(); }
std::size_t DistributedSimulation::peak_local_count() const { return engine_->peak_local_count(); }
const ExchangeCounts& DistributedSimulation::exchange_counts() const { return engine_->exchange_counts(); }

}  // namespace particlesim
