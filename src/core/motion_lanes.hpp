#pragma once
// A particle's position and velocity in two lanes (x, y), moved as
// physics.hpp moves them but without a branch on which wall comes first, or
// on whether one comes within the rest of the step: in a sparse scene both
// are random, and such branches were mispredicted for most wall hits (the
// stepped engine's resolution). The same IEEE operations on the same values,
// lane by lane, so the same bits as bounce_off_wall(),
// move_stopping_at_wall() and move_freely().

#include "core/box.hpp"
#include "core/physics.hpp"
#include "particlesim/particle.hpp"

#include <algorithm>

namespace particlesim {

class MotionLanes {
public:
    MotionLanes(const Particle& particle, const Box& box)
        : where_{particle.position.x(), particle.position.y()},
          speed_{particle.velocity.x(), particle.velocity.y()},
          lower_{box.lower, box.lower},
          upper_{box.upper, box.upper} {}

    // bounce_off_wall() at the first wall (without counting the collision).
    void bounce() {
        const Hit hit = first_wall();
        advance_onto_walls(hit.time, hit.on);
        speed_ = hit.on ? -speed_ : speed_;
    }

    // move_stopping_at_wall() for `remaining`.
    void move_stopping_at_wall(double remaining) {
        const Hit hit = first_wall();
        const TwoMasks stops = TwoDoubles{hit.time, hit.time} <= TwoDoubles{remaining, remaining};
        // std::min() is hit.time where it is at most `remaining`: the time of either branch.
        advance_onto_walls(std::min(hit.time, remaining), hit.on & stops);
    }

    // move_freely() for `time`.
    void fly(double time) { advance_onto_walls(time, TwoMasks{0, 0}); }

    // time_to_wall()'s time.
    double wall_time() const { return first_wall().time; }

    Vec2 position() const { return {where_[0], where_[1]}; }
    Vec2 velocity() const { return {speed_[0], speed_[1]}; }

private:
    // time_to_wall(), with the axes it names as a mask of lanes.
    struct Hit {
        double time;
        TwoMasks on;
    };
    Hit first_wall() const {
        const TwoDoubles times = times_to_walls(where_, speed_, lower_, upper_);
        const double time = std::min(times[0], times[1]);
        return {time, (times == TwoDoubles{time, time}) & (times != TwoDoubles{never, never})};
    }

    // Moves for `time`, clamps into the box (std::clamp()'s comparisons), and
    // puts the coordinates that `on` names exactly on the wall the velocity
    // points to (place_on_wall()).
    void advance_onto_walls(double time, const TwoMasks& on) {
        TwoDoubles at = where_ + speed_ * time;
        at = at < lower_ ? lower_ : at;
        at = upper_ < at ? upper_ : at;
        where_ = on ? (speed_ < 0.0 ? lower_ : upper_) : at;
    }

    TwoDoubles where_;
    TwoDoubles speed_;
    TwoDoubles lower_;
    TwoDoubles upper_;
};

}  // namespace particlesim
