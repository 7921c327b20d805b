#include "parallel/parallel.hpp"

#include <omp.h>

namespace particlesim {

int default_thread_count() { return std::max(omp_get_max_threads(), 1); }

}  // namespace particlesim
