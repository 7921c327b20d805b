// The distributed engine's benchmark, run under mpirun (bench/run-distributed.sh
// drives it and writes bench/results/<machine>/distributed*.csv):
//
//   distributed_bench gas N STEPS [one-process|distributed]
//       the dense gas (area fraction 0.3, speeds 0.1 to 1 r a step): the
//       scene placed on rank 0 and handed out, then STEPS steps timed (the
//       placing and start-up excluded). On one rank the one-process engine
//       runs (simcli's path under mpirun -np 1) unless `distributed` is
//       asked. One CSV line: the time per step, the largest rank's peak
//       memory, and each exchange's cost per step for the scaling model.
//   distributed_bench pingpong
//       latency and bandwidth between ranks 0 and 1 (one CSV line).

#include "particlesim/distributed_simulation.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <malloc.h>
#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double peak_megabytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

double max_over_ranks(double value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return value;
}

double sum_over_ranks(double value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return value;
}

int gas(std::size_t count, int steps, bool distributed) {
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const World world{std::sqrt(static_cast<double>(count) * std::numbers::pi / 0.3), 1.0};
    std::vector<Particle> particles;
    if (rank == 0) particles = make_random_particles(count, world, {3210, SpeedRange{0.1, 1.0}});
    SteppedOptions options;
    options.threads = 1;
    if (ranks == 1 && !distributed) {
        SteppedSimulation engine(world, std::move(particles), options);
        const double start = now();
        for (int step = 0; step < steps; ++step) engine.step();
        const double seconds = now() - start;
        std::printf("1,%zu,%d,one-process,%.6f,%.1f,%.1f,0,0,0,0,0,%.6f\n", count, steps, seconds / steps,
                    peak_megabytes(), peak_megabytes(), seconds / steps);
        return 0;
    }
    DistributedSimulation engine(MPI_COMM_WORLD, world, std::move(particles), options);
    MPI_Barrier(MPI_COMM_WORLD);
    const ExchangeCounts before = engine.exchange_counts();
    const double start = now();
    for (int step = 0; step < steps; ++step) engine.step();
    const double seconds = max_over_ranks(now() - start);
    const ExchangeCounts& after = engine.exchange_counts();
    const double per_rank_step = 1.0 / (static_cast<double>(steps) * ranks);
    const double ghosts = sum_over_ranks(static_cast<double>(after.ghosts_received - before.ghosts_received));
    const double bytes = sum_over_ranks(static_cast<double>(after.bytes_sent - before.bytes_sent));
    const double messages = sum_over_ranks(static_cast<double>(after.messages_sent - before.messages_sent));
    const double rounds = max_over_ranks(static_cast<double>(after.selection_rounds - before.selection_rounds));
    const double exchanging = max_over_ranks(after.seconds_exchanging - before.seconds_exchanging);
    const double computing = max_over_ranks((now() - start) - (after.seconds_exchanging - before.seconds_exchanging));
    const double peak = max_over_ranks(peak_megabytes());
    if (rank == 0) {
        // ranks,particles,steps,engine,seconds_per_step,peak_mb_largest_rank,peak_mb_rank0,ghosts_per_rank_step,
        // bytes_per_rank_step,messages_per_rank_step,rounds_per_step,exchange_seconds_per_step,compute_seconds_per_step
        std::printf("%d,%zu,%d,distributed,%.6f,%.1f,%.1f,%.1f,%.0f,%.1f,%.2f,%.6f,%.6f\n", ranks, count, steps,
                    seconds / steps, peak, peak_megabytes(), ghosts * per_rank_step, bytes * per_rank_step,
                    messages * per_rank_step, rounds / steps, exchanging / steps, computing / steps);
    }
    return 0;
}

int pingpong() {
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (ranks < 2) {
        if (rank == 0) std::fprintf(stderr, "pingpong needs two ranks\n");
        return 2;
    }
    const auto one_way = [&](std::size_t bytes, int repeats) {
        std::vector<char> buffer(std::max<std::size_t>(bytes, 1));
        MPI_Barrier(MPI_COMM_WORLD);
        const double start = now();
        for (int k = 0; k < repeats; ++k) {
            if (rank == 0) {
                MPI_Send(buffer.data(), static_cast<int>(bytes), MPI_BYTE, 1, 0, MPI_COMM_WORLD);
                MPI_Recv(buffer.data(), static_cast<int>(bytes), MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            } else if (rank == 1) {
                MPI_Recv(buffer.data(), static_cast<int>(bytes), MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Send(buffer.data(), static_cast<int>(bytes), MPI_BYTE, 0, 0, MPI_COMM_WORLD);
            }
        }
        return (now() - start) / (2.0 * repeats);
    };
    one_way(8, 1000);  // warm up
    const double latency = one_way(8, 20000);
    const std::size_t large = std::size_t{4} << 20;
    const double transfer = one_way(large, 200);
    const double bandwidth = static_cast<double>(large) / (transfer - latency);
    double allreduce_seconds = 0.0;
    {
        double value = 1.0;
        MPI_Barrier(MPI_COMM_WORLD);
        const double start = now();
        for (int k = 0; k < 20000; ++k) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        allreduce_seconds = (now() - start) / 20000;
    }
    // ranks,latency_seconds,bandwidth_bytes_per_second,allreduce_seconds
    if (rank == 0) std::printf("%d,%.3e,%.3e,%.3e\n", ranks, latency, bandwidth, allreduce_seconds);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    mallopt(M_MMAP_THRESHOLD, 1 << 20);  // as simcli under mpirun
    MPI_Init(&argc, &argv);
    const std::string mode = argc > 1 ? argv[1] : "";
    int status = 2;
    if (mode == "gas" && argc >= 4) {
        status = gas(std::strtoull(argv[2], nullptr, 10), std::atoi(argv[3]),
                     argc > 4 && std::string(argv[4]) == "distributed");
    } else if (mode == "pingpong") {
        status = pingpong();
    } else {
        std::fprintf(stderr, "usage: distributed_bench gas N STEPS [one-process|distributed] | pingpong\n");
    }
    MPI_Finalize();
    return status;
}
