#include "search/line_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace particlesim {

namespace {

// Calls visit(cell) once for every cell of `grid` that holds a point within
// `widen` (in x and in y) of the segment a-b. Points beyond the grid belong
// to its edge cells; clamping never moves two points apart, so two points
// within `widen` of each other stay in cells within `widen` of each other.
template <typename Visit>
void for_each_cell_near(const UniformGrid& grid, Vec2 a, Vec2 b, double widen, Visit&& visit) {
    if (a.x() > b.x()) std::swap(a, b);
    const double cell = grid.cell_size();
    const int last = grid.per_side() - 1;
    const int first_column = grid.column_of(a.x() - widen);
    const int last_column = grid.column_of(b.x() + widen);
    const double run = b.x() - a.x();
    const double rise = b.y() - a.y();
    for (int column = first_column; column <= last_column; ++column) {
        // The part of the segment within `widen` of this column's x range.
        double t_first = 0.0, t_last = 1.0;
        if (run > 0.0) {
            const double low = column == 0 ? -std::numeric_limits<double>::infinity() : column * cell - widen;
            const double high =
                column == last ? std::numeric_limits<double>::infinity() : (column + 1) * cell + widen;
            t_first = std::clamp((low - a.x()) / run, 0.0, 1.0);
            t_last = std::clamp((high - a.x()) / run, 0.0, 1.0);
        }
        const double y_first = a.y() + rise * t_first;
        const double y_last = a.y() + rise * t_last;
        const int first_row = grid.column_of(std::min(y_first, y_last) - widen);
        const int last_row = grid.column_of(std::max(y_first, y_last) + widen);
        for (int row = first_row; row <= last_row; ++row) visit(grid.cell_at(column, row));
    }
}

// Far above the rounding of a segment's ends and of the clipping above.
double rounding_margin(double box_side, const LineSegment& s) {
    const double extent = std::max({box_side, std::abs(s.from.x()), std::abs(s.from.y()), std::abs(s.to.x()),
                                    std::abs(s.to.y())});
    return 0x1p-30 * extent;
}

}  // namespace

void LineCells::build(const PathLines& lines, std::span<const LineSegment> segments, double box_side,
                      int per_side, double widen) {
    grid_ = UniformGrid(box_side, per_side);
    const std::size_t cells = grid_.cell_count();
    entry_cell_.clear();
    entry_line_.clear();
    cell_start_.assign(cells + 1, 0);
    for (std::uint32_t i = 0; i < segments.size(); ++i) {
        const LineSegment& s = segments[i];
        for_each_cell_near(grid_, s.from, s.to, widen + rounding_margin(box_side, s), [&](std::uint32_t cell) {
            entry_cell_.push_back(cell);
            entry_line_.push_back(i);
            ++cell_start_[cell + 1];
        });
    }
    // Each cell's lines padded to whole groups of lanes.
    const auto lanes = static_cast<std::uint32_t>(lines.lanes());
    for (std::size_t cell = 0; cell < cells; ++cell) {
        const std::uint32_t count = cell_start_[cell + 1];
        cell_start_[cell + 1] = cell_start_[cell] + (count + lanes - 1) / lanes * lanes;
    }
    const std::uint32_t places = cell_start_[cells];
    constexpr float never_passes = std::numeric_limits<float>::quiet_NaN();
    ids_.assign(places, std::numeric_limits<std::uint32_t>::max());
    for (std::vector<float>* component : {&x_, &y_, &vx_, &vy_}) component->assign(places, never_passes);
    fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t k = 0; k < entry_line_.size(); ++k) {
        const std::uint32_t at = fill_[entry_cell_[k]]++;
        const std::uint32_t i = entry_line_[k];
        ids_[at] = i;
        x_[at] = lines.x(i);
        y_[at] = lines.y(i);
        vx_[at] = lines.vx(i);
        vy_[at] = lines.vy(i);
    }
}

void LineCells::gather_near(const PathLines& lines, std::uint32_t i, const LineSegment& segment, double reach,
                            std::vector<std::uint32_t>& near) const {
    const std::size_t first = near.size();
    const PathLines::Query query = lines.query(i, reach);
    for_each_cell_near(grid_, segment.from, segment.to, rounding_margin(grid_.cell_size() * grid_.per_side(), segment),
                       [&](std::uint32_t cell) {
                           const std::uint32_t begin = cell_start_[cell];
                           const std::uint32_t end = cell_start_[cell + 1];
                           if (begin == end) return;
                           const std::size_t found = near.size();
                           lines.gather_among(x_.data() + begin, y_.data() + begin, vx_.data() + begin,
                                              vy_.data() + begin, end - begin, query, near);
                           for (std::size_t k = found; k < near.size(); ++k) near[k] = ids_[begin + near[k]];
                       });
    // A line in several of the cells is found once; i's own line is not a neighbour.
    const auto from = near.begin() + static_cast<std::ptrdiff_t>(first);
    std::sort(from, near.end());
    near.erase(std::unique(from, near.end()), near.end());
    near.erase(std::remove(from, near.end(), i), near.end());
}

}  // namespace particlesim
