#pragma once
// The column (or row) of a uniform grid that a coordinate falls in, clamped
// to the grid: coordinates below it (and NaN) map to 0, above it to the last.

namespace particlesim {

struct CellMapper {
    double inverse_size;  // 1 / cell size
    int per_side;

    [[nodiscard]] int operator()(double coordinate) const {
        const double scaled = coordinate * inverse_size;
        if (!(scaled > 0.0)) return 0;
        if (scaled >= per_side) return per_side - 1;
        return static_cast<int>(scaled);
    }
};

}  // namespace particlesim
