#pragma once
// Point-to-point exchanges with a list of neighbouring ranks: each sends a
// vector to each neighbour and receives one from it. Neighbours are mutual
// (DomainStrips::strips_near), so every send has its receive. Elements are
// trivially copyable and sent as bytes of one contiguous type, so counts
// stay elements (int) whatever the element's size.

#include "particlesim/distributed_simulation.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace particlesim {

// An MPI call that did not succeed: the run cannot go on on this rank.
inline void require_mpi(int result, const char* what) {
    if (result != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// An MPI datatype of sizeof(T) bytes, freed with the object: elements of
// any trivially copyable type travel as one unit each.
template <typename T>
class BytesType {
public:
    BytesType() {
        static_assert(std::is_trivially_copyable_v<T>);
        require_mpi(MPI_Type_contiguous(static_cast<int>(sizeof(T)), MPI_BYTE, &type_), "making a type");
        require_mpi(MPI_Type_commit(&type_), "committing a type");
    }
    ~BytesType() { MPI_Type_free(&type_); }
    BytesType(const BytesType&) = delete;
    BytesType& operator=(const BytesType&) = delete;
    [[nodiscard]] MPI_Datatype get() const { return type_; }

private:
    MPI_Datatype type_ = MPI_DATATYPE_NULL;
};

class NeighbourExchange {
public:
    NeighbourExchange() = default;
    // Counts every message sent, and the time spent, in `counts`.
    NeighbourExchange(MPI_Comm comm, ExchangeCounts* counts) : comm_(comm), counts_(counts) {}

    // Sends out[n] to neighbours[n], receives in[n] from it. With
    // `sizes_known`, in[n] already has the size the neighbour sends (both
    // sides derived it from the same data) and no sizes are exchanged; a
    // message of another size then throws std::logic_error (never a wait for
    // a message that does not come: even empty messages are sent).
    template <typename T>
    void exchange(std::span<const int> neighbours, const std::vector<std::vector<T>>& out,
                  std::vector<std::vector<T>>& in, int tag, bool sizes_known = false) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto start = std::chrono::steady_clock::now();
        const std::size_t count = neighbours.size();
        in.resize(count);
        if (!sizes_known) {
            sizes_out_.resize(count);
            sizes_in_.resize(count);
            requests_.clear();
            for (std::size_t n = 0; n < count; ++n) {
                sizes_out_[n] = out[n].size();
                requests_.emplace_back();
                require_mpi(MPI_Irecv(&sizes_in_[n], 1, MPI_UINT64_T, neighbours[n], tag, comm_, &requests_.back()),
                            "receiving a message size");
                requests_.emplace_back();
                require_mpi(MPI_Isend(&sizes_out_[n], 1, MPI_UINT64_T, neighbours[n], tag, comm_, &requests_.back()),
                            "sending a message size");
            }
            wait_all();
            counts_->messages_sent += count;
            counts_->bytes_sent += count * sizeof(std::uint64_t);
            for (std::size_t n = 0; n < count; ++n) {
                if (sizes_in_[n] > static_cast<std::uint64_t>(INT32_MAX))
                    throw std::runtime_error("MPI: a message of over 2^31 elements");
                in[n].resize(sizes_in_[n]);
            }
        }
        const BytesType<T> type;
        const MPI_Datatype element = type.get();
        requests_.clear();
        for (std::size_t n = 0; n < count; ++n) {
            requests_.emplace_back();
            require_mpi(MPI_Irecv(in[n].data(), static_cast<int>(in[n].size()), element, neighbours[n], tag + 1, comm_,
                                  &requests_.back()),
                        "receiving");
        }
        for (std::size_t n = 0; n < count; ++n) {
            requests_.emplace_back();
            require_mpi(MPI_Isend(out[n].data(), static_cast<int>(out[n].size()), element, neighbours[n], tag + 1,
                                  comm_, &requests_.back()),
                        "sending");
        }
        statuses_.resize(requests_.size());
        require_mpi(MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), statuses_.data()),
                    "waiting for neighbours");
        for (std::size_t n = 0; n < count; ++n) {
            int received = 0;
            MPI_Get_count(&statuses_[n], element, &received);
            if (static_cast<std::size_t>(received) != in[n].size())
                throw std::logic_error("a neighbouring rank sent a message of an unexpected size");
            counts_->bytes_sent += out[n].size() * sizeof(T);
        }
        counts_->messages_sent += count;
        counts_->seconds_exchanging += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

private:
    void wait_all() {
        require_mpi(MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE),
                    "waiting for neighbours");
    }

    MPI_Comm comm_ = MPI_COMM_NULL;
    ExchangeCounts* counts_ = nullptr;
    std::vector<std::uint64_t> sizes_out_;
    std::vector<std::uint64_t> sizes_in_;
    std::vector<MPI_Request> requests_;
    std::vector<MPI_Status> statuses_;
};

}  // namespace particlesim
