#include "particlesim/step_check.hpp"

#include "check/exact_step_check.hpp"
#include "check/uncertain_step.hpp"
#include "core/box.hpp"
#include "core/physics.hpp"
#include "input/options_check.hpp"
#include "input/scene_checks.hpp"
#include "io/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

namespace particlesim {

namespace {

// How far a printed number may be from the value its program held.
double tolerance(double printed, double uncertainty) { return uncertainty + std::fabs(printed) * 0x1p-51; }

bool matches(const UncertainParticle& allowed, const Particle& printed, double uncertainty) {
    const auto fits = [&](const Uncertain& bounds, double value) {
        return bounds.contains(value, tolerance(value, uncertainty));
    };
    return fits(allowed.x, printed.position.x()) && fits(allowed.y, printed.position.y()) &&
           fits(allowed.vx, printed.velocity.x()) && fits(allowed.vy, printed.velocity.y());
}

std::string time_text(const Uncertain& time) {
    if (!std::isfinite(time.hi)) return "a time within rounding of the step";
    return "t = " + format_brief(time.mid());
}

std::string describe(const PossibleCollision& c, std::uint32_t particle) {
    if (c.kind == CollisionKind::wall) {
        const bool corner = c.on_x == Tri::yes && c.on_y == Tri::yes;
        return "particle " + std::to_string(particle) + " reaches the " + (corner ? "corner" : "wall") + " at " +
               time_text(c.time);
    }
    if (c.touching == Tri::yes) {
        return "particles " + std::to_string(c.i) + " and " + std::to_string(c.j) +
               " overlap at the start of the step and approach each other, so they collide at t = 0";
    }
    return "particles " + std::to_string(c.i) + " and " + std::to_string(c.j) + " meet at " + time_text(c.time);
}

// A collision as the subject of a sentence.
std::string event_name(const PossibleCollision& c) {
    if (c.kind == CollisionKind::wall) {
        const bool corner = c.on_x == Tri::yes && c.on_y == Tri::yes;
        return "particle " + std::to_string(c.i) + "'s " + (corner ? "corner" : "wall") + " hit at " +
               time_text(c.time);
    }
    return "the meeting of particles " + std::to_string(c.i) + " and " + std::to_string(c.j) + " at " +
           time_text(c.time);
}

}  // namespace

class StepChecker::Impl {
public:
    Impl(const World& world, const StepCheckOptions& options)
        : world_(world),
          box_(Box::of(world)),
          options_(options),
          // Where centres may be: [r, L - r] between walls, [0, L) in a periodic box.
          lowest_(options.boundary == Boundary::periodic ? 0.0 : box_.lower),
          highest_(options.boundary == Boundary::periodic ? world.box_size : box_.upper),
          step_(box_, options.most_possible_pairs),
          exact_(world, options.boundary) {}

    StepCheck check(const PrintedState& before, const PrintedState& after) {
        require_printed_state(before);
        require_printing(after, "after");
        if (after.particles.size() != before.particles.size()) {
            throw std::invalid_argument("the two states have different numbers of particles");
        }
        StepCheck result;
        if (auto outside = outside_box(after)) {
            result.violation = std::move(outside);
            return result;
        }
        if (options_.rules == CheckedRules::exact) return exact_.check(before, after);
        return check_stepped(before, after);
    }

    Run run(const PrintedState& start, std::int64_t steps) {
        if (steps < 0)
            throw std::invalid_argument("StepChecker::run: steps must be >= 0, not " + std::to_string(steps));
        require_printed_state(start);
        if (options_.rules == CheckedRules::exact) {
            Run result = exact_.run(start, steps);
            result.steps = steps;
            return result;
        }
        Run result;
        result.steps = steps;
        const std::size_t count = start.particles.size();
        state_.resize(count);
        for (std::size_t p = 0; p < count; ++p) state_[p] = uncertain_particle(start.particles[p], start.uncertainty);
        result.collisions.assign(count, CollisionRange{});
        for (std::int64_t s = 1; s <= steps && !result.undecided_from; ++s) {
            for (int micro = 0; micro < options_.substeps && !result.undecided_from; ++micro) {
                advance_micro_step(result.collisions, &result.undecided_why);
                if (!result.undecided_why.empty()) result.undecided_from = s;
            }
        }
        result.lower.resize(count);
        result.upper.resize(count);
        for (std::size_t p = 0; p < count; ++p) {
            result.lower[p].position = Vec2(state_[p].x.lo, state_[p].y.lo);
            result.lower[p].velocity = Vec2(state_[p].vx.lo, state_[p].vy.lo);
            result.upper[p].position = Vec2(state_[p].x.hi, state_[p].y.hi);
            result.upper[p].velocity = Vec2(state_[p].vx.hi, state_[p].vy.hi);
        }
        return result;
    }

    std::optional<RuleViolation> final_state_violation(const Run& run, const PrintedState& final_state) const {
        require_printing(final_state, "after");
        if (run.undecided_from) {
            throw std::invalid_argument(
                "StepChecker::final_state_violation: the run may go more than one way from "
                "step " +
                std::to_string(*run.undecided_from) + ", so no final state is certain");
        }
        if (final_state.particles.size() != run.lower.size() || run.upper.size() != run.lower.size()) {
            throw std::invalid_argument("StepChecker::final_state_violation: the run has " +
                                        std::to_string(run.lower.size()) + " particles and the final state " +
                                        std::to_string(final_state.particles.size()));
        }
        const auto inside = [&](double value, double low, double high) {
            const double slack = tolerance(value, final_state.uncertainty);
            return low - slack <= value && value <= high + slack;
        };
        for (std::uint32_t i = 0; i < final_state.particles.size(); ++i) {
            const Particle& printed = final_state.particles[i];
            const Particle& low = run.lower[i];
            const Particle& high = run.upper[i];
            bool fine = true;
            for (int axis = 0; axis < 2 && fine; ++axis) {
                double position = printed.position[axis];
                if (options_.boundary == Boundary::periodic) {  // the image nearest where the run went
                    position =
                        image_nearest(position, 0.5 * (low.position[axis] + high.position[axis]), world_.box_size);
                }
                fine = inside(position, low.position[axis], high.position[axis]) &&
                       inside(printed.velocity[axis], low.velocity[axis], high.velocity[axis]);
            }
            if (!fine) {
                RuleViolation violation;
                violation.particle = i;
                violation.what = "particle " + std::to_string(i) +
                                 ": the final state is not where the rules take it after " + std::to_string(run.steps) +
                                 " steps (every decision on the way is decided)";
                violation.expected.position = 0.5 * (low.position + high.position);
                violation.expected.velocity = 0.5 * (low.velocity + high.velocity);
                violation.printed = printed;
                return violation;
            }
        }
        return std::nullopt;
    }

private:
    // A state printed by a correct program: valid within its uncertainty (the
    // bounds made of it are clamped into the box, where the true state lies).
    void require_printed_state(const PrintedState& state) const {
        require_printing(state, "before");
        for (std::size_t p = 0; p < state.particles.size(); ++p) {
            const Particle& q = state.particles[p];
            for (int axis = 0; axis < 2; ++axis) {
                const double value = q.position[axis];
                const double velocity = q.velocity[axis];
                const double allowed = tolerance(value, state.uncertainty);
                if (!(value >= lowest_ - allowed && value <= highest_ + allowed) ||
                    !(std::fabs(velocity) <= max_magnitude)) {
                    throw std::invalid_argument("StepChecker: particle " + std::to_string(p) +
                                                " of the state before the step is outside the box or beyond the "
                                                "accepted range");
                }
            }
        }
    }

    // What the caller says of a state's printing, which no output can fix:
    // an uncertainty that is a distance, and a wall mark for each particle or none.
    static void require_printing(const PrintedState& state, const char* which) {
        if (!(state.uncertainty >= 0.0 && state.uncertainty <= max_magnitude)) {
            throw std::invalid_argument(
                std::string("StepChecker: the state ") + which +
                " the step has an uncertainty that is not a distance in [0, 1e60]: " + format_short(state.uncertainty));
        }
        if (!state.on_wall.empty() && state.on_wall.size() != state.particles.size()) {
            throw std::invalid_argument(std::string("StepChecker: the state ") + which + " the step has " +
                                        std::to_string(state.particles.size()) + " particles and " +
                                        std::to_string(state.on_wall.size()) +
                                        " on_wall marks; give one a particle, or none");
        }
    }

    // Every printed state must be valid (rules.md "World"), within its printing.
    std::optional<RuleViolation> outside_box(const PrintedState& after) const {
        for (std::uint32_t p = 0; p < after.particles.size(); ++p) {
            const Particle& printed = after.particles[p];
            for (int axis = 0; axis < 2; ++axis) {
                const double value = printed.position[axis];
                const double slack = tolerance(value, after.uncertainty);
                const char* name = axis == 0 ? "x" : "y";
                std::string what;
                const bool periodic = options_.boundary == Boundary::periodic;
                if (!(value >= lowest_ - slack)) {
                    what = "particle " + std::to_string(p) + " is outside the box: " + name + " = " +
                           format_short(value) + (periodic ? " is below 0" : " is below r = " + format_short(lowest_));
                } else if (!(value <= highest_ + slack)) {
                    what = "particle " + std::to_string(p) + " is outside the box: " + name + " = " +
                           format_short(value) + (periodic ? " is beyond L = " : " is beyond L - r = ") +
                           format_short(highest_);
                }
                if (!what.empty()) {
                    Particle expected = printed;
                    expected.position[axis] = std::clamp(value, lowest_, highest_);
                    return RuleViolation{p, what, expected, printed};
                }
            }
        }
        return std::nullopt;
    }

    // One micro-step on the bounds, every allowed fate merged; says why when
    // a particle may go more than one way.
    void advance_micro_step(std::vector<CollisionRange>& counts, std::string* undecided) {
        step_.predict(state_, 1.0 / options_.substeps);
        next_.resize(state_.size());
        for (std::uint32_t p = 0; p < state_.size(); ++p) {
            next_[p] = merged_fates(p, counts[p]);
            if (fates_.size() > 1 && undecided && undecided->empty()) *undecided = why_undecided(p);
        }
        state_.swap(next_);
    }

    // Every fate the last predict() allows particle p, merged into one set of
    // bounds, their collisions added to `counts` (the fates stay in fates_).
    UncertainParticle merged_fates(std::uint32_t p, CollisionRange& counts) {
        step_.fates_of(p, fates_);
        add_counts(counts, fates_);
        UncertainParticle merged = fates_.front().outcome;
        for (const Fate& f : fates_) merged = hull(merged, f.outcome);
        return merged;
    }

    void add_counts(CollisionRange& counts, const std::vector<Fate>& fates) const {
        std::uint64_t pmin = 1, pmax = 0, wmin = 1, wmax = 0;
        for (const Fate& f : fates) {
            const bool pair = pair_candidate(f.candidate) != nullptr;
            const bool wall = f.candidate >= 0 && !pair;
            pmin = std::min<std::uint64_t>(pmin, pair);
            pmax = std::max<std::uint64_t>(pmax, pair);
            wmin = std::min<std::uint64_t>(wmin, wall);
            wmax = std::max<std::uint64_t>(wmax, wall);
        }
        counts.particle_min += pmin;
        counts.particle_max += pmax;
        counts.wall_min += wmin;
        counts.wall_max += wmax;
    }

    std::string why_undecided(std::uint32_t particle) const {
        for (const std::uint32_t k : step_.candidates_of(particle)) {
            if (step_.candidates()[k].accepted == Tri::maybe) return why_undecided(step_.candidates()[k]);
        }
        return "particle " + std::to_string(particle) + ": a decision within rounding";
    }

    static std::string why_undecided(const PossibleCollision& c) {
        const std::string who = c.kind == CollisionKind::wall
                                    ? "particle " + std::to_string(c.i)
                                    : "particles " + std::to_string(c.i) + " and " + std::to_string(c.j);
        if (c.exists == Tri::maybe) {
            if (c.kind == CollisionKind::wall && !std::isfinite(c.time.hi)) {
                return who + " creeps along a wall: whether it reaches it in this step is within rounding";
            }
            if (c.kind == CollisionKind::wall) return who + " reaches the wall within rounding of the end of the step";
            if (c.touching == Tri::maybe)
                return who + " touch within rounding: whether they collide at t = 0 is within rounding";
            if (c.approaching == Tri::maybe) {
                return who +
                       " move neither towards nor away from each other, within rounding: whether they collide is "
                       "within rounding";
            }
            if (c.time.lo <= 1.0 && 1.0 <= c.time.hi) return who + " meet within rounding of the end of the step";
            return who + " graze: whether they touch is within rounding";
        }
        return describe(c, c.i) + ", and whether it comes before another collision of " +
               (c.kind == CollisionKind::wall ? "it" : "theirs") + " is within rounding (a near tie)";
    }

    // The state after some micro-steps of a step, on one branch of the
    // decisions within rounding met so far, with its counts and notes.
    struct Branch {
        std::vector<UncertainParticle> state;
        std::vector<CollisionRange> counts;
        std::vector<std::string> notes;  // its decisions within rounding, in order
        // Some micro-step's fates were merged into one set of bounds (too
        // many ways): wide bounds then hold states no correct program
        // reaches. (Wide bounds of one way are the scene's own sensitivity:
        // correct programs do end anywhere in them.)
        bool merged = false;
    };

    // With substeps, the micro-steps before the last follow each way the
    // decisions within rounding may go (up to max_branches at once, beyond
    // which fates are merged into bounds); the step conforms if one branch
    // explains the printed state, strictly if its bounds stay narrow.
    StepCheck check_stepped(const PrintedState& before, const PrintedState& after) {
        const std::size_t count = before.particles.size();
        std::vector<Branch> branches(1);
        branches.front().state.resize(count);
        for (std::size_t p = 0; p < count; ++p) {
            branches.front().state[p] = uncertain_particle(before.particles[p], before.uncertainty);
        }
        place_on_walls(before, branches.front().state);
        branches.front().counts.assign(count, CollisionRange{});
        for (int micro = 1; micro < options_.substeps; ++micro) {
            std::vector<Branch> next;
            const std::size_t most =
                std::clamp<std::size_t>(branched_particles / std::max<std::size_t>(count, 1), 1, max_branches);
            const std::size_t room = std::max<std::size_t>(1, most / branches.size());
            for (Branch& branch : branches) advance_branch(branch, micro, room, next);
            branches = std::move(next);
        }
        // Every branch that explains the printed state may be the one the
        // program took: their collision counts are merged, and the step is
        // strict if one of them is.
        std::optional<StepCheck> passed, failure;
        std::size_t fewest_unmatched = count + 1;
        for (Branch& branch : branches) {
            std::size_t unmatched = 0;
            StepCheck checked = match_last_micro_step(branch, after, unmatched);
            if (!checked.violation) {
                if (!passed) {
                    passed = std::move(checked);
                    continue;
                }
                for (std::size_t p = 0; p < count; ++p) {
                    merge_counts(passed->collisions[p], checked.collisions[p]);
                    merge_on_wall(passed->on_wall[p], checked.on_wall[p]);
                }
                if (!checked.loose) passed->loose.reset();
            } else if (unmatched < fewest_unmatched) {
                fewest_unmatched = unmatched;
                failure = std::move(checked);
            }
        }
        return passed ? std::move(*passed) : std::move(*failure);
    }

    // The coordinates the previous step put exactly on a wall start there
    // exactly, where the printed value agrees.
    void place_on_walls(const PrintedState& before, std::vector<UncertainParticle>& state) const {
        if (before.on_wall.size() != before.particles.size()) return;
        const auto place = [&](Uncertain& bounds, std::int8_t side) {
            if (side == 0) return;
            const double wall = side < 0 ? box_.lower : box_.upper;
            if (bounds.lo <= wall && wall <= bounds.hi) bounds = Uncertain::exact(wall);
        };
        for (std::size_t p = 0; p < state.size(); ++p) {
            place(state[p].x, before.on_wall[p].x);
            place(state[p].y, before.on_wall[p].y);
        }
    }
    // On a wall in both explanations, or not known to be.
    static void merge_on_wall(OnWall& into, const OnWall& other) {
        if (into.x != other.x) into.x = 0;
        if (into.y != other.y) into.y = 0;
    }
    // The side of the wall a fate's outcome sets a coordinate exactly on, or 0.
    std::int8_t wall_side(const Uncertain& coordinate) const {
        if (!coordinate.is_exact()) return 0;
        if (coordinate.lo == box_.lower) return -1;
        return coordinate.lo == box_.upper ? 1 : 0;
    }

    static void merge_counts(CollisionRange& into, const CollisionRange& other) {
        into.particle_min = std::min(into.particle_min, other.particle_min);
        into.particle_max = std::max(into.particle_max, other.particle_max);
        into.wall_min = std::min(into.wall_min, other.wall_min);
        into.wall_max = std::max(into.wall_max, other.wall_max);
    }

    // One micro-step of `branch`: a branch in `out` for each way its
    // decisions within rounding may go together, or one with their fates
    // merged into bounds when there are more than `room` ways.
    void advance_branch(Branch& branch, int micro, std::size_t room, std::vector<Branch>& out) {
        const auto count = static_cast<std::uint32_t>(branch.state.size());
        step_.predict(branch.state, 1.0 / options_.substeps);
        next_.resize(count);
        sole_candidate_.resize(count);
        undecided_.clear();
        undecided_groups_.clear();
        for (std::uint32_t p = 0; p < count; ++p) {
            step_.fates_of(p, fates_);
            if (fates_.size() == 1) {
                sole_candidate_[p] = fates_.front().candidate;
                next_[p] = fates_.front().outcome;
                add_counts(branch.counts[p], fates_);
                continue;
            }
            group_fates(fates_, groups_);
            if (groups_.size() == 1) {  // every way ends alike
                sole_candidate_[p] = several_candidates;
                next_[p] = groups_.front().outcome;
                add_counts(branch.counts[p], groups_.front().fates);
                continue;
            }
            undecided_.push_back(p);
            undecided_groups_.push_back(groups_);
        }
        if (undecided_.empty()) {
            branch.state.swap(next_);
            out.push_back(std::move(branch));
            return;
        }
        branch.notes.push_back("micro-step " + std::to_string(micro) + ": " + why_undecided(undecided_.front()));
        const std::vector<std::vector<std::size_t>> ways = ways_to_decide(room);
        if (ways.empty()) {  // too many: every fate merged into one bounds
            branch.merged = true;
            for (const std::uint32_t p : undecided_) next_[p] = merged_fates(p, branch.counts[p]);
            branch.state.swap(next_);
            out.push_back(std::move(branch));
            return;
        }
        for (const std::vector<std::size_t>& way : ways) {
            Branch taken{next_, branch.counts, branch.notes, branch.merged};
            for (std::size_t u = 0; u < undecided_.size(); ++u) {
                const FateGroup& g = undecided_groups_[u][way[u]];
                taken.state[undecided_[u]] = g.outcome;
                add_counts(taken.counts[undecided_[u]], g.fates);
            }
            out.push_back(std::move(taken));
        }
    }

    // Fates whose outcomes differ negligibly (joined, their bounds span at
    // most a millionth of a diameter more by the step's end than either's)
    // are followed as one: a pair at rest touching within rounding collides
    // or not to the same effect.
    struct FateGroup {
        std::vector<int> candidates;
        UncertainParticle outcome;
        std::vector<Fate> fates;
    };
    void group_fates(const std::vector<Fate>& fates, std::vector<FateGroup>& groups) const {
        const double negligible = 1e-6 * 2.0 * world_.radius;
        groups.clear();
        for (const Fate& f : fates) {
            const auto joins = [&](FateGroup& g) {
                const UncertainParticle both = hull(g.outcome, f.outcome);
                const double span = end_span(both);
                if (!(std::isfinite(span) && span <= std::max(end_span(g.outcome), end_span(f.outcome)) + negligible))
                    return false;
                g.candidates.push_back(f.candidate);
                g.outcome = both;
                g.fates.push_back(f);
                return true;
            };
            if (std::none_of(groups.begin(), groups.end(), joins)) groups.push_back({{f.candidate}, f.outcome, {f}});
        }
    }
    // How far apart a particle may end the step along an axis: its
    // position's bounds plus its velocity's over the last micro-step; and on
    // its wider axis.
    double end_span_along(const Uncertain& position, const Uncertain& velocity) const {
        const double last_micro_step = 1.0 / options_.substeps;
        return (position.hi - position.lo) + last_micro_step * (velocity.hi - velocity.lo);
    }
    double end_span(const UncertainParticle& q) const {
        return std::max(end_span_along(q.x, q.vx), end_span_along(q.y, q.vy));
    }

    // Every choice of one group of fates per undecided particle in which no
    // pair collision is taken by one of its particles alone (each a group
    // index per undecided particle), or nothing when there are more than
    // `room`. Particles that share no possible collision decide
    // independently: the choices are made per group of linked particles,
    // then combined.
    std::vector<std::vector<std::size_t>> ways_to_decide(std::size_t room) const {
        const std::size_t count = undecided_.size();
        const auto index_of = [&](std::uint32_t particle) -> std::optional<std::size_t> {
            const auto at = std::lower_bound(undecided_.begin(), undecided_.end(), particle);
            if (at == undecided_.end() || *at != particle) return std::nullopt;
            return static_cast<std::size_t>(at - undecided_.begin());
        };
        std::vector<std::size_t> linked(count);
        std::iota(linked.begin(), linked.end(), std::size_t{0});
        const auto root = [&](std::size_t u) {
            while (linked[u] != u) u = linked[u] = linked[linked[u]];
            return u;
        };
        for (std::size_t u = 0; u < count; ++u) {
            for (const FateGroup& g : undecided_groups_[u]) {
                for (const int k : g.candidates) {
                    const PossibleCollision* c = pair_candidate(k);
                    if (const auto other = c ? index_of(c->other(undecided_[u])) : std::nullopt)
                        linked[root(*other)] = root(u);
                }
            }
        }
        std::vector<std::size_t> way(count, 0);
        // Whether a particle's choice may take pair k, and whether it must.
        struct Takes {
            bool may, must;
        };
        const auto takes = [&](std::uint32_t particle, std::uint32_t k) -> Takes {
            if (const auto u = index_of(particle)) {
                const std::vector<int>& chosen = undecided_groups_[*u][way[*u]].candidates;
                const bool may = std::find(chosen.begin(), chosen.end(), static_cast<int>(k)) != chosen.end();
                return {may, may && chosen.size() == 1};
            }
            if (sole_candidate_[particle] == several_candidates)
                return {step_.candidates()[k].accepted != Tri::no, false};
            const bool only = sole_candidate_[particle] == static_cast<int>(k);
            return {only, only};
        };
        // No pair that one particle must take and its partner may not.
        const auto consistent = [&](const std::vector<std::size_t>& members) {
            for (const std::size_t u : members) {
                for (const std::uint32_t k : step_.candidates_of(undecided_[u])) {
                    const PossibleCollision& c = step_.candidates()[k];
                    if (c.kind != CollisionKind::pair) continue;
                    const Takes mine = takes(undecided_[u], k);
                    const Takes theirs = takes(c.other(undecided_[u]), k);
                    if ((mine.must && !theirs.may) || (theirs.must && !mine.may)) return false;
                }
            }
            return true;
        };
        std::vector<std::vector<std::size_t>> ways{way};
        for (std::size_t first = 0; first < count; ++first) {
            if (root(first) != first) continue;
            std::vector<std::size_t> members;
            double combinations = 1.0;
            for (std::size_t u = 0; u < count; ++u) {
                if (root(u) != first) continue;
                members.push_back(u);
                combinations *= static_cast<double>(undecided_groups_[u].size());
            }
            if (combinations > max_combinations_tried) return {};
            // Every combination of the linked particles, like an odometer.
            std::vector<std::vector<std::size_t>> choices;
            for (const std::size_t u : members) way[u] = 0;
            while (true) {
                if (consistent(members)) {
                    std::vector<std::size_t>& choice = choices.emplace_back();
                    for (const std::size_t u : members) choice.push_back(way[u]);
                }
                std::size_t m = 0;
                while (m < members.size() && ++way[members[m]] == undecided_groups_[members[m]].size())
                    way[members[m++]] = 0;
                if (m == members.size()) break;
            }
            if (choices.empty() || ways.size() * choices.size() > room) return {};
            std::vector<std::vector<std::size_t>> combined;
            for (const std::vector<std::size_t>& partial : ways) {
                for (const std::vector<std::size_t>& choice : choices) {
                    std::vector<std::size_t>& next = combined.emplace_back(partial);
                    for (std::size_t m = 0; m < members.size(); ++m) next[members[m]] = choice[m];
                }
            }
            ways = std::move(combined);
        }
        return ways;
    }

    // Candidate k if it is a pair collision, or null (k < 0: no collision).
    const PossibleCollision* pair_candidate(int k) const {
        if (k < 0) return nullptr;
        const PossibleCollision& c = step_.candidates()[static_cast<std::size_t>(k)];
        return c.kind == CollisionKind::pair ? &c : nullptr;
    }

    // The last micro-step of `branch`, matched fate by fate against the
    // printed state; `unmatched` counts the particles no fate explains.
    StepCheck match_last_micro_step(Branch& branch, const PrintedState& after, std::size_t& unmatched) {
        StepCheck result;
        const auto count = static_cast<std::uint32_t>(branch.state.size());
        result.collisions = std::move(branch.counts);
        result.on_wall.assign(count, OnWall{});
        if (branch.merged) result.loose = wider_than_a_diameter(branch.state, branch.notes);
        result.within_rounding = std::move(branch.notes);
        step_.predict(branch.state, 1.0 / options_.substeps);
        matched_.assign(count, {});
        for (std::uint32_t p = 0; p < count; ++p) {
            step_.fates_of(p, fates_);
            for (const Fate& f : fates_) {
                if (matches(f.outcome, after.particles[p], after.uncertainty)) matched_[p].push_back(f.candidate);
            }
            unmatched += matched_[p].empty() ? 1 : 0;
        }
        // A particle that no fate explains on its own comes first; then one
        // whose collision its partner's printed state does not show.
        for (std::uint32_t p = 0; p < count; ++p) {
            if (matched_[p].empty()) {
                result.violation = explain(p, after);
                return result;
            }
        }
        drop_one_sided_pairs();
        for (std::uint32_t p = 0; p < count; ++p) {
            if (matched_[p].empty()) {
                ++unmatched;
                result.violation = explain(p, after);
                return result;
            }
            step_.fates_of(p, fates_);
            if (fates_.size() > 1) note_either_way(p, result.within_rounding);
            fates_.erase(std::remove_if(fates_.begin(), fates_.end(),
                                        [&](const Fate& f) {
                                            return std::find(matched_[p].begin(), matched_[p].end(), f.candidate) ==
                                                   matched_[p].end();
                                        }),
                         fates_.end());
            add_counts(result.collisions[p], fates_);
            result.on_wall[p] = placed_on_walls(fates_);
        }
        return result;
    }

    // Where every one of these fates sets the particle exactly on a wall: a
    // collision's (a stop at the wall, or a hit at the step's very end); a
    // free flight's bounds are no such placement.
    OnWall placed_on_walls(const std::vector<Fate>& fates) const {
        OnWall placed{wall_side(fates.front().outcome.x), wall_side(fates.front().outcome.y)};
        for (const Fate& f : fates) {
            if (f.candidate < 0) return {};
            merge_on_wall(placed, {wall_side(f.outcome.x), wall_side(f.outcome.y)});
        }
        return placed;
    }

    // Whether, after the micro-steps before the last, some particle may end
    // the step anywhere in a span wider than a diameter on an axis: why, or
    // nothing. The first of `notes` names the first decision within rounding
    // (whose fates were merged).
    std::optional<std::string> wider_than_a_diameter(std::span<const UncertainParticle> state,
                                                     const std::vector<std::string>& notes) const {
        for (std::uint32_t p = 0; p < state.size(); ++p) {
            const double span_x = end_span_along(state[p].x, state[p].vx);
            const double span_y = end_span_along(state[p].y, state[p].vy);
            const double span = std::max(span_x, span_y);
            if (!(span > 2.0 * world_.radius)) continue;
            char span_text[32];
            std::snprintf(span_text, sizeof span_text, " in a span of %.4g", span);
            return "particle " + std::to_string(p) + " may end the step anywhere" +
                   (std::isfinite(span) ? std::string(span_text) : std::string()) + " along " +
                   (span_x == span ? "x" : "y") + (notes.empty() ? "" : " (" + notes.front() + ")");
        }
        return std::nullopt;
    }

    // A pair fate needs both particles: drop it where the other does not match it.
    void drop_one_sided_pairs() {
        for (bool changed = true; changed;) {
            changed = false;
            for (std::uint32_t p = 0; p < matched_.size(); ++p) {
                auto& mine = matched_[p];
                const auto one_sided = [&](int k) {
                    if (k < 0) return false;
                    const PossibleCollision& c = step_.candidates()[k];
                    if (c.kind != CollisionKind::pair) return false;
                    const auto& theirs = matched_[c.other(p)];
                    return std::find(theirs.begin(), theirs.end(), k) == theirs.end();
                };
                const auto end = std::remove_if(mine.begin(), mine.end(), one_sided);
                if (end != mine.end()) {
                    mine.erase(end, mine.end());
                    changed = true;
                }
            }
        }
    }

    void note_either_way(std::uint32_t particle, std::vector<std::string>& notes) const {
        for (const std::uint32_t k : step_.candidates_of(particle)) {
            const PossibleCollision& c = step_.candidates()[k];
            // Each undecided candidate once: a pair at its lower index.
            if (c.accepted == Tri::maybe && particle == c.i) notes.push_back(why_undecided(c));
        }
    }

    // The first particle that no allowed fate explains: what the rules do,
    // and what the output seems to have done instead.
    RuleViolation explain(std::uint32_t particle, const PrintedState& after) const {
        RuleViolation v;
        v.particle = particle;
        v.printed = after.particles[particle];
        std::vector<Fate> fates;
        step_.fates_of(particle, fates);
        // The expected fate: the accepted collision, else the first allowed.
        const Fate* expected = &fates.front();
        for (const Fate& f : fates) {
            if (f.candidate >= 0 && step_.candidates()[f.candidate].accepted == Tri::yes) expected = &f;
        }
        v.expected = midpoint(expected->outcome);
        const std::string mine = "particle " + std::to_string(particle);
        const auto printed_matches = [&](int candidate) {
            return matches(step_.outcome(particle, candidate), v.printed, after.uncertainty);
        };
        if (expected->candidate < 0) {
            v.what = mine + " has no collision in this step";
            if (printed_matches(-1)) {
                v.what += "; its partner's printed state does not match the collision it shows";
                return v;
            }
            for (const std::uint32_t k : step_.candidates_of(particle)) {
                if (!printed_matches(static_cast<int>(k))) continue;
                const PossibleCollision& lost = step_.candidates()[k];
                v.what += ": " + describe(lost, particle) + ", but ";
                const PossibleCollision* winner = winner_over(lost);
                v.what += winner ? event_name(*winner) + " comes first" : "that collision is not selected";
                if (winner && winner->time.is_exact() && lost.time.is_exact() && winner->time.lo == lost.time.lo) {
                    v.what += " (a tie: at equal times a wall comes before a particle, then the lowest indices win)";
                }
                v.what += "; the output carries it out";
                return v;
            }
            v.what += " and moves freely, but the output changes its state";
            return v;
        }
        const PossibleCollision& c = step_.candidates()[static_cast<std::size_t>(expected->candidate)];
        const std::string rule = describe(c, particle);
        if (printed_matches(expected->candidate)) {
            v.what = rule + ", but only particle " + std::to_string(particle) + "'s printed state shows it: particle " +
                     std::to_string(c.other(particle)) + "'s does not follow from it";
            return v;
        }
        if (printed_matches(-1)) {
            v.what = rule + (c.kind == CollisionKind::wall ? ", and the output lets it pass"
                                                           : ", and the output lets them pass");
            return v;
        }
        for (const std::uint32_t k : step_.candidates_of(particle)) {
            if (static_cast<int>(k) == expected->candidate || !printed_matches(static_cast<int>(k))) continue;
            const PossibleCollision& other = step_.candidates()[k];
            v.what = rule + ", but the output carries out another collision first: " + describe(other, particle);
            if (other.time.is_exact() && c.time.is_exact() && other.time.lo == c.time.lo) {
                v.what += " (a tie: at equal times a wall comes before a particle, then the lowest indices win)";
            }
            return v;
        }
        if (c.kind == CollisionKind::wall && c.on_x == Tri::yes && c.on_y == Tri::yes) {
            const bool only_x = v.printed.velocity.x() * v.expected.velocity.x() > 0.0 &&
                                v.printed.velocity.y() * v.expected.velocity.y() < 0.0;
            const bool only_y = v.printed.velocity.x() * v.expected.velocity.x() < 0.0 &&
                                v.printed.velocity.y() * v.expected.velocity.y() > 0.0;
            if (only_x || only_y) {
                v.what = rule + ": both vx and vy flip, but the output flips only " + (only_x ? "vx" : "vy");
                return v;
            }
        }
        if (const char* axis = stopped_at_wall(v.expected)) {
            const bool reflected = (axis[0] == 'x' ? v.printed.velocity.x() * v.expected.velocity.x()
                                                   : v.printed.velocity.y() * v.expected.velocity.y()) < 0.0;
            if (reflected) {
                v.what = rule + "; after it " + mine + " must stop at the wall (" + axis + " = " +
                         format_short(axis[0] == 'x' ? v.expected.position.x() : v.expected.position.y()) +
                         ") and bounce at t = 0 of the next step, but the output bounces it within this step";
                return v;
            }
        }
        v.what = rule + " (its one collision in this step), but " + mine + "'s printed state does not follow from it";
        return v;
    }

    // The accepted collision that takes a particle of `lost` before it.
    const PossibleCollision* winner_over(const PossibleCollision& lost) const {
        for (const std::uint32_t particle : {lost.i, lost.j}) {
            for (const std::uint32_t k : step_.candidates_of(particle)) {
                const PossibleCollision& c = step_.candidates()[k];
                if (&c != &lost && c.accepted == Tri::yes) return &c;
            }
        }
        return nullptr;
    }

    // "x" or "y" when the expected state sits on a wall it moves towards.
    const char* stopped_at_wall(const Particle& expected) const {
        const auto towards = [&](double position, double velocity) {
            return (position == box_.lower && velocity < 0.0) || (position == box_.upper && velocity > 0.0);
        };
        if (towards(expected.position.x(), expected.velocity.x())) return "x";
        if (towards(expected.position.y(), expected.velocity.y())) return "y";
        return nullptr;
    }

    World world_;
    Box box_;
    StepCheckOptions options_;
    double lowest_;   // the least a centre may be
    double highest_;  // the most
    UncertainStep step_;
    ExactStepCheck exact_;
    std::vector<UncertainParticle> state_, next_;
    std::vector<Fate> fates_;
    std::vector<std::vector<int>> matched_;
    // Of the micro-step being branched: each particle's fate when it has one,
    // the particles with several ways to end (ascending) and their fates, grouped.
    std::vector<int> sole_candidate_;  // or several_candidates, all ending alike
    std::vector<std::uint32_t> undecided_;
    std::vector<std::vector<FateGroup>> undecided_groups_;
    std::vector<FateGroup> groups_;
    static constexpr int several_candidates = -2;
    // Branches followed at once; a micro-step whose undecided particles'
    // fates combine in more ways than this is merged into bounds untried.
    static constexpr std::size_t max_branches = 256;
    // And fewer for a larger scene: branches times particles at most this,
    // which bounds the work of a micro-step (a dense scene of 299 disks took
    // 45 s at 256 branches, 0.26 s under this bound) and the memory.
    static constexpr std::size_t branched_particles = std::size_t{1} << 15;
    static constexpr double max_combinations_tried = 4096.0;
};

StepChecker::StepChecker(const World& world, const StepCheckOptions& options) {
    require_valid_scene("StepChecker", world, {});
    OptionsCheck check("StepCheckOptions");
    check.at_least("substeps", options.substeps, 1);
    if (options.rules != CheckedRules::stepped && options.rules != CheckedRules::exact)
        check.fail("rules must be CheckedRules::stepped or CheckedRules::exact, not " +
                   std::to_string(static_cast<int>(options.rules)));
    check.known_boundary("boundary", options.boundary);
    if (options.boundary == Boundary::periodic && options.rules != CheckedRules::exact)
        check.fail("a periodic box has the exact rules only (rules = exact)");
    impl_ = std::make_unique<Impl>(world, options);
}

StepChecker::~StepChecker() = default;
StepChecker::StepChecker(StepChecker&&) noexcept = default;
StepChecker& StepChecker::operator=(StepChecker&&) noexcept = default;

StepCheck StepChecker::check(const PrintedState& before, const PrintedState& after) {
    return impl_->check(before, after);
}

StepChecker::Run StepChecker::run(const PrintedState& start, std::int64_t steps) { return impl_->run(start, steps); }

std::optional<RuleViolation> StepChecker::final_state_violation(const Run& run, const PrintedState& final_state) const {
    return impl_->final_state_violation(run, final_state);
}

}  // namespace particlesim
