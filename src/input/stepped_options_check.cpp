#include "input/stepped_options_check.hpp"

#include "input/options_check.hpp"
#include "particlesim/engine.hpp"

#include <string>

namespace particlesim {

void require_valid_stepped_options(const SteppedOptions& options) {
    const OptionsCheck check("particlesim::SteppedOptions");
    switch (options.pair_search) {
    case PairSearch::automatic:
    case PairSearch::brute_force:
    case PairSearch::grid:
    case PairSearch::paths: break;
    default:
        // A value cast from a number that names no search.
        check.fail("pair_search must be one of the PairSearch values, not " +
                   std::to_string(static_cast<int>(options.pair_search)));
    }
    if (options.grid_cells) {
        check.in_range("grid_cells", *options.grid_cells, 1, max_grid_cells);
        if (options.pair_search != PairSearch::grid) check.fail("grid_cells needs pair_search = PairSearch::grid");
    }
    if (options.threads) check.in_range("threads", *options.threads, 1, max_threads);
    check.at_least("substeps", options.substeps, 1);
    if (options.sort_by_position_every) check.at_least("sort_by_position_every", *options.sort_by_position_every, 0);
}

}  // namespace particlesim
