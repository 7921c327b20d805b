// The one uniform grid: its sizing against the bounds it is given, and the
// cell a point falls in, clamped, worked out by hand.

#include "check.hpp"
#include "core/uniform_grid.hpp"

#include <cmath>
#include <limits>

using namespace particlesim;

namespace {

void sizing() {
    // 20 / 2 = 10 cells of exactly a diameter would leave no room for
    // rounding: one fewer, each wider than the minimum.
    CHECK_EQ(UniformGrid::cells_per_side(20.0, 2.0, 100.0), 9);
    CHECK_EQ(UniformGrid::cells_per_side(20.0, 1.9, 100.0), 10);
    CHECK_EQ(UniformGrid::cells_per_side(20.0, 2.0, 4.7), 4);        // the maximum wins
    CHECK_EQ(UniformGrid::cells_per_side(20.0, 50.0, 100.0), 1);     // never fewer than one
    CHECK_EQ(UniformGrid::cells_per_side(20.0, 0.0, 33.0), 33);      // no minimum size
    CHECK_EQ(UniformGrid::cells_per_side(1.0, 1e-12, 1e12), 65536);  // capped for 32-bit cell indices
    CHECK_EQ(UniformGrid::cells_per_side(20.0, 1.0, 0.0), 1);
    for (const double extent : {1.0, 3.0, 1e-9, 1e6, 12345.678}) {
        for (const double min_cell : {1e-3, 0.1, 0.37, 1.0}) {
            const check::Context context("extent ", extent, ", minimum cell ", min_cell);
            const int side = UniformGrid::cells_per_side(extent, min_cell * extent, 1e9);
            CHECK(side == 1 || UniformGrid(extent, side).cell_size() >= min_cell * extent);
        }
    }
}

void cells_of_points() {
    const UniformGrid grid(20.0, 4);  // cells of 5
    CHECK_EQ(grid.cell_count(), 16U);
    CHECK_EQ(grid.cell_size(), 5.0);
    CHECK_EQ(grid.column_of(0.0), 0);
    CHECK_EQ(grid.column_of(4.999), 0);
    CHECK_EQ(grid.column_of(5.0), 1);
    CHECK_EQ(grid.column_of(19.999), 3);
    CHECK_EQ(grid.column_of(20.0), 3);  // the far wall belongs to the last cell
    CHECK_EQ(grid.column_of(-3.0), 0);  // clamped
    CHECK_EQ(grid.column_of(1e300), 3);
    CHECK_EQ(grid.column_of(std::numeric_limits<double>::quiet_NaN()), 0);
    CHECK_EQ(grid.cell_of(Vec2(12.0, 7.0)), 6U);  // column 2, row 1
    CHECK_EQ(grid.cell_at(3, 3), 15U);
    CHECK_EQ(grid.column(6), 2);
    CHECK_EQ(grid.row(6), 1);
    // Monotone: a point further right is never in a column further left.
    int previous = 0;
    for (double x = 0.0; x <= 20.0; x += 0.01) {
        const int column = grid.column_of(x);
        CHECK(column >= previous);
        previous = column;
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_uniform_grid", {{"sizing", sizing}, {"cells of points", cells_of_points}});
}
