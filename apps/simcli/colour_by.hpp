#pragma once
// What --snapshot and --animate colour the disks by: their speed, or the
// local hexatic order (--colour-by psi6): the phase of each disk's psi6 as a
// hue round the colour wheel (the orientation of the local lattice, 60
// degrees a turn), darker where |psi6| is small: the standard picture of
// hexatic domains.

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

namespace simcli {

enum class ColourBy { speed, psi6 };

// The phase of a local psi6 as a fraction of a turn, in [0, 1]: what the
// snapshot's hue and the page's phase byte are made of.
inline double phase_turns(std::complex<double> psi) {
    return (std::arg(psi) + std::numbers::pi) / (2.0 * std::numbers::pi);
}

// The colour of a disk whose local psi6 is `psi`: hue from its phase,
// brightness from 0.25 (disordered) to 1 (|psi6| = 1).
inline std::array<int, 3> psi6_colour(std::complex<double> psi) {
    const double hue = phase_turns(psi) * 6.0;  // [0, 6]
    const double value = 0.25 + 0.75 * std::clamp(std::abs(psi), 0.0, 1.0);
    const int sector = std::min(static_cast<int>(hue), 5);
    const double f = hue - sector;
    const double rising = value * f, falling = value * (1.0 - f);
    double rgb[3];
    switch (sector) {
    case 0: rgb[0] = value, rgb[1] = rising, rgb[2] = 0.0; break;
    case 1: rgb[0] = falling, rgb[1] = value, rgb[2] = 0.0; break;
    case 2: rgb[0] = 0.0, rgb[1] = value, rgb[2] = rising; break;
    case 3: rgb[0] = 0.0, rgb[1] = falling, rgb[2] = value; break;
    case 4: rgb[0] = rising, rgb[1] = 0.0, rgb[2] = value; break;
    default: rgb[0] = value, rgb[1] = 0.0, rgb[2] = falling; break;
    }
    return {static_cast<int>(std::lround(255.0 * rgb[0])), static_cast<int>(std::lround(255.0 * rgb[1])),
            static_cast<int>(std::lround(255.0 * rgb[2]))};
}

}  // namespace simcli
