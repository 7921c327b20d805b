#include "scenes/growth_packing.hpp"

#include "core/physics.hpp"
#include "core/random.hpp"
#include "core/uniform_grid.hpp"
#include "io/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>

namespace particlesim {

namespace {

// Every gap ends at least this fraction of a diameter wide, so that scaling
// the packing to the scene's units never makes two disks touch.
constexpr double clearance = 1e-9;

// Near its jam a growing packing collides ever faster while its radius all
// but stops: jammed when a window of this many events a disk grows the
// radius by less than `least_growth` of itself (far from the jam a window
// grows it by a percent or more), or after `most_events_per_disk` in all
// (then a jam, or a growth too slow where the radius still grew).
constexpr double events_per_disk_in_window = 100.0;
constexpr double least_growth = 1e-7;
constexpr double most_events_per_disk = 20000.0;
// A packing whose radius still grows by this much a window when the events
// run out was not jamming: its growth rate was too slow for the budget.
constexpr double still_growing = 1e-3;

class Growth {
public:
    explicit Growth(const GrowthRequest& request)
        : request_(request),
          count_(static_cast<std::uint32_t>(request.count)),
          box_(std::sqrt(static_cast<double>(request.count))),
          target_radius_(std::sqrt(request.area_fraction / std::numbers::pi)),
          final_radius_(target_radius_ * (1.0 + clearance)),
          radius_rate_(0.5 * request.growth_rate),
          end_(final_radius_ / radius_rate_),
          cells_per_side_(std::max(1, static_cast<int>(box_ / (2.0 * final_radius_ * (1.0 + 1e-6))))),
          disks_(count_),
          next_move_(count_, 0.0) {
        if (request.periodic && cells_per_side_ < periodic_cells_at_least) {
            throw std::invalid_argument("particlesim::make_family_scene: a periodic box must be at least " +
                                        std::to_string(periodic_cells_at_least) +
                                        " diameters wide to grow a packing in it: more disks or a lower fraction");
        }
        if (cells_per_side_ < 3) cells_per_side_ = 1;  // one cell: every pair is a neighbour
        cell_width_ = box_ / cells_per_side_;
        cells_.resize(static_cast<std::size_t>(cells_per_side_) * static_cast<std::size_t>(cells_per_side_));
        // Points at random (radius 0 at time 0), all at the same speed in
        // random directions: kT = 1, mass 1.
        SplitMix64 rng(request.seed);
        for (std::uint32_t i = 0; i < count_; ++i) {
            Disk& disk = disks_[i];
            disk.position = Vec2(rng.uniform() * box_, rng.uniform() * box_);
            disk.velocity = std::sqrt(2.0) * random_direction(rng);
            disk.cell = cell_containing(disk.position);
            cells_[disk.cell].push_back(i);
        }
    }

    GrownPacking run() {
        predict_all();
        const double disks = std::max<double>(count_, 16.0);
        const double budget = most_events_per_disk * disks, window = events_per_disk_in_window * disks;
        std::uint64_t events = 0, since_rescale = 0, since_window = 0;
        double window_start = now_;
        double last_window_growth = 1.0;  // the radius's relative growth over the last window
        while (!queue_.empty() && queue_.top().time <= end_) {
            const Event event = queue_.top();
            queue_.pop();
            if (disks_[event.i].version != event.version_i) continue;  // predicted afresh since
            if (event.kind == Kind::pair && disks_[event.j].version != event.version_j) {
                // The partner met another first: the owner's next pair is unknown.
                now_ = event.time;
                predict_pairs(event.i);
                continue;
            }
            if (static_cast<double>(++events) > budget) {
                if (last_window_growth > still_growing) refuse_too_slow(events, last_window_growth);
                refuse_jammed(events);
            }
            if (static_cast<double>(++since_window) > window) {
                last_window_growth = (event.time - window_start) / event.time;
                if (last_window_growth < least_growth) refuse_jammed(events);
                since_window = 0;
                window_start = event.time;
            }
            now_ = event.time;
            switch (event.kind) {
            case Kind::pair: collide(event.i, event.j); break;
            case Kind::wall: bounce(event.i, event.j); break;
            case Kind::crossing: cross(event.i, event.j); break;
            }
            // Growth heats the disks; bring them back to kT = 1 now and then
            // (which also drops the queue's stale entries).
            if (++since_rescale >= std::max<std::uint32_t>(count_, 64)) {
                since_rescale = 0;
                rescale_speeds();
                if (request_.progress) request_.progress(fraction_reached(), request_.area_fraction);
            }
        }
        now_ = end_;
        GrownPacking packing;
        packing.box_size = box_;
        for (std::uint32_t i = 0; i < count_; ++i) {
            Vec2 centre = position_at(i, now_);
            if (request_.periodic) {
                for (int axis = 0; axis < 2; ++axis) centre[axis] = wrap_into_periodic_box(centre[axis], box_);
            }
            packing.centres.push_back(centre);
        }
        return packing;
    }

private:
    enum class Kind : std::uint8_t { wall, pair, crossing };
    struct Event {
        double time;
        Kind kind;
        std::uint32_t i;  // the disk whose prediction this is
        std::uint32_t j;  // pair: the partner; wall: 2 axis + side; crossing: 2 axis + (1 if upwards)
        std::uint32_t version_i;
        std::uint32_t version_j;
    };
    // Earliest first, ties in a fixed order whatever the heap does with them.
    struct Later {
        bool operator()(const Event& a, const Event& b) const {
            return std::tie(a.time, a.kind, a.i, a.j) > std::tie(b.time, b.kind, b.i, b.j);
        }
    };
    struct Disk {
        Vec2 position;  // at `stamp`
        Vec2 velocity;
        double stamp = 0.0;
        std::uint32_t version = 0;  // changes with every event of the disk
        std::uint32_t cell = 0;
    };

    double radius_at(double time) const { return radius_rate_ * time; }
    Vec2 position_at(std::uint32_t i, double time) const {
        return disks_[i].position + disks_[i].velocity * (time - disks_[i].stamp);
    }
    void bring_to_now(std::uint32_t i) {
        disks_[i].position = position_at(i, now_);
        disks_[i].stamp = now_;
    }
    std::uint32_t cell_containing(const Vec2& p) const {
        const auto index = [&](double x) {
            return std::clamp(static_cast<int>(x / box_ * cells_per_side_), 0, cells_per_side_ - 1);
        };
        return static_cast<std::uint32_t>(index(p.y()) * cells_per_side_ + index(p.x()));
    }
    Vec2 separation(std::uint32_t i, std::uint32_t j) const {
        Vec2 d = position_at(j, now_) - position_at(i, now_);
        if (request_.periodic) {
            for (int axis = 0; axis < 2; ++axis) d[axis] = nearest_image(d[axis], box_);
        }
        return d;
    }

    // When the contact distance 2 r(t), growing at 2 radius_rate_, meets the
    // distance of i and j: the first root of |d + dv t|^2 = (D + g t)^2.
    double pair_time(std::uint32_t i, std::uint32_t j) const {
        const Vec2 d = separation(i, j);
        const Vec2 dv = disks_[j].velocity - disks_[i].velocity;
        const double contact = 2.0 * radius_at(now_), growth = 2.0 * radius_rate_;
        const double a = dv.squaredNorm() - growth * growth;
        const double b = d.dot(dv) - contact * growth;
        const double c = d.squaredNorm() - contact * contact;
        if (c <= 0.0 && b < 0.0) return now_;  // touching (to rounding) and closing
        const double discriminant = b * b - a * c;
        if (discriminant < 0.0) return never;
        if (a < 0.0) {  // the growth outruns their parting: they meet
            const double root = b > 0.0 ? (b + std::sqrt(discriminant)) / -a : c / (std::sqrt(discriminant) - b);
            return now_ + std::max(root, 0.0);
        }
        if (b >= 0.0) return never;
        return now_ + std::max(c / (std::sqrt(discriminant) - b), 0.0);
    }

    void push(double time, Kind kind, std::uint32_t i, std::uint32_t j) {
        queue_.push(Event{time, kind, i, j, disks_[i].version, kind == Kind::pair ? disks_[j].version : 0});
    }

    template <typename Visit>
    void for_each_neighbour(std::uint32_t i, Visit&& visit) const {
        if (cells_per_side_ == 1) {
            for (std::uint32_t j : cells_[0]) visit(j);
            return;
        }
        const int side = cells_per_side_;
        const int column = static_cast<int>(disks_[i].cell) % side, row = static_cast<int>(disks_[i].cell) / side;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                int x = column + dx, y = row + dy;
                if (request_.periodic) {
                    x = (x + side) % side;
                    y = (y + side) % side;
                } else if (x < 0 || y < 0 || x >= side || y >= side) {
                    continue;
                }
                for (std::uint32_t j : cells_[static_cast<std::size_t>(y * side + x)]) visit(j);
            }
        }
    }

    void predict(std::uint32_t i) {
        const Disk& disk = disks_[i];
        const Vec2 at = position_at(i, now_);
        const double radius = radius_at(now_);
        double first = end_;
        if (!request_.periodic) {
            for (std::uint32_t axis = 0; axis < 2; ++axis) {
                const double v = disk.velocity[static_cast<int>(axis)], x = at[static_cast<int>(axis)];
                if (v + radius_rate_ > 0.0) {
                    const double t = now_ + std::max((box_ - radius - x) / (v + radius_rate_), 0.0);
                    if (t <= first) push(t, Kind::wall, i, 2 * axis + 1);
                    first = std::min(first, t);
                }
                if (radius_rate_ - v > 0.0) {
                    const double t = now_ + std::max((x - radius) / (radius_rate_ - v), 0.0);
                    if (t <= first) push(t, Kind::wall, i, 2 * axis);
                    first = std::min(first, t);
                }
            }
        }
        if (cells_per_side_ > 1) {
            const int cell[2] = {static_cast<int>(disk.cell) % cells_per_side_,
                                 static_cast<int>(disk.cell) / cells_per_side_};
            for (std::uint32_t axis = 0; axis < 2; ++axis) {
                const double v = disk.velocity[static_cast<int>(axis)], x = at[static_cast<int>(axis)];
                const int k = cell[axis];
                const bool up = v > 0.0;
                if (v == 0.0 || (!request_.periodic && (up ? k == cells_per_side_ - 1 : k == 0))) continue;
                const double boundary = (up ? k + 1 : k) * cell_width_;
                const double t = now_ + std::max((boundary - x) / v, 0.0);
                if (t <= first) push(t, Kind::crossing, i, 2 * axis + (up ? 1U : 0U));
                first = std::min(first, t);
            }
        }
        next_move_[i] = first;
        predict_pairs(i);
    }

    // The disk's earliest pair event, if before its next wall or crossing
    // (which predicts afresh). Only the earliest is queued: when its partner
    // meets another first, the disk predicts again then, still before any
    // later contact of its own (the exact engine's argument).
    void predict_pairs(std::uint32_t i) {
        double earliest = next_move_[i];
        std::uint32_t partner = i;
        for_each_neighbour(i, [&](std::uint32_t j) {
            if (j == i) return;
            const double t = pair_time(i, j);
            if (t < earliest || (t == earliest && partner != i && j < partner)) {
                earliest = t;
                partner = j;
            }
        });
        if (partner != i) push(earliest, Kind::pair, i, partner);
    }

    void predict_all() {
        queue_ = {};
        for (std::uint32_t i = 0; i < count_; ++i) predict(i);
    }

    void collide(std::uint32_t i, std::uint32_t j) {
        bring_to_now(i);
        bring_to_now(j);
        const Vec2 d = separation(i, j);
        const Vec2 normal = d / d.norm();
        const double closing = (disks_[j].velocity - disks_[i].velocity).dot(normal);
        const double growth = 2.0 * radius_rate_;
        if (closing < growth) {
            // Elastic, and parting faster than the contact distance grows:
            // the normal relative speed u becomes 2 g - u > g.
            const Vec2 kick = (growth - closing) * normal;
            disks_[i].velocity -= kick;
            disks_[j].velocity += kick;
        }
        ++disks_[i].version;
        ++disks_[j].version;
        predict(i);
        predict(j);
    }

    void bounce(std::uint32_t i, std::uint32_t wall) {
        bring_to_now(i);
        const int axis = static_cast<int>(wall / 2);
        double& v = disks_[i].velocity[axis];
        // The wall closes in at the growth rate: reflect the speed relative to it.
        v = (wall % 2 == 1) ? -v - 2.0 * radius_rate_ : -v + 2.0 * radius_rate_;
        ++disks_[i].version;
        predict(i);
    }

    void cross(std::uint32_t i, std::uint32_t direction) {
        bring_to_now(i);
        Disk& disk = disks_[i];
        const int axis = static_cast<int>(direction / 2);
        const int step = direction % 2 == 1 ? 1 : -1;
        int cell[2] = {static_cast<int>(disk.cell) % cells_per_side_, static_cast<int>(disk.cell) / cells_per_side_};
        cell[axis] += step;
        if (cell[axis] < 0 || cell[axis] >= cells_per_side_) {  // periodic: wrap
            cell[axis] = (cell[axis] + cells_per_side_) % cells_per_side_;
            disk.position[axis] -= step * box_;
        }
        auto& members = cells_[disk.cell];
        members.erase(std::find(members.begin(), members.end(), i));
        disk.cell = static_cast<std::uint32_t>(cell[1] * cells_per_side_ + cell[0]);
        cells_[disk.cell].push_back(i);
        ++disk.version;
        predict(i);
    }

    void rescale_speeds() {
        double kinetic = 0.0;
        for (std::uint32_t i = 0; i < count_; ++i) {
            bring_to_now(i);
            kinetic += 0.5 * disks_[i].velocity.squaredNorm();
        }
        const double scale = kinetic > 0.0 ? std::sqrt(static_cast<double>(count_) / kinetic) : 1.0;
        for (Disk& disk : disks_) {
            disk.velocity *= scale;
            ++disk.version;
        }
        predict_all();
    }

    // The area fraction the disks fill now, and the events so far a disk: what a refusal names.
    [[nodiscard]] double fraction_reached() const {
        const double radius = radius_at(now_);
        return static_cast<double>(count_) * std::numbers::pi * radius * radius / (box_ * box_);
    }
    [[nodiscard]] double per_disk(std::uint64_t events) const {
        return static_cast<double>(events) / std::max<double>(count_, 1.0);
    }

    [[noreturn]] void refuse_jammed(std::uint64_t events) const {
        throw std::invalid_argument("particlesim::make_family_scene: the disks jammed at area fraction " +
                                    format_brief(fraction_reached()) + " before reaching " +
                                    format_short(request_.area_fraction) + " (after " + format_brief(per_disk(events)) +
                                    " events a disk); ask for a lower fraction or a slower growth rate");
    }

    [[noreturn]] void refuse_too_slow(std::uint64_t events, double window_growth) const {
        throw std::invalid_argument(
            "particlesim::make_family_scene: the compression took its most events (" + format_brief(per_disk(events)) +
            " a disk) at area fraction " + format_brief(fraction_reached()) + ", short of " +
            format_short(request_.area_fraction) + ", still growing (" + format_brief(100.0 * window_growth) +
            " % over the last " + format_brief(events_per_disk_in_window) +
            " events a disk): ask for a faster growth rate than " + format_short(request_.growth_rate));
    }

    GrowthRequest request_;
    std::uint32_t count_;
    double box_;
    double target_radius_;
    double final_radius_;
    double radius_rate_;
    double end_;  // the time the radius reaches final_radius_
    int cells_per_side_;
    double cell_width_ = 0.0;
    std::vector<Disk> disks_;
    std::vector<double> next_move_;  // each disk's next wall or crossing (or the end)
    std::vector<std::vector<std::uint32_t>> cells_;
    std::priority_queue<Event, std::vector<Event>, Later> queue_;
    double now_ = 0.0;
};

}  // namespace

GrownPacking grow_packing(const GrowthRequest& request) {
    if (!(request.area_fraction > 0.0 && request.area_fraction < close_packing_fraction)) {
        throw std::invalid_argument("particlesim::make_family_scene: a compression reaches area fractions in (0, " +
                                    format_short(close_packing_fraction) + "), below close packing, not " +
                                    format_short(request.area_fraction));
    }
    if (!(request.growth_rate > 0.0 && request.growth_rate <= 10.0)) {
        throw std::invalid_argument("particlesim::make_family_scene: the growth rate must be in (0, 10], not " +
                                    format_short(request.growth_rate));
    }
    if (request.count > 0xfffffffeU) {
        throw std::invalid_argument("particlesim::make_family_scene: too many disks to grow a packing");
    }
    if (request.count == 0) return GrownPacking{};
    return Growth(request).run();
}

}  // namespace particlesim
