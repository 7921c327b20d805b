#pragma once
// A binned box and its particle's line as one 32-byte record. The grid
// search places each box into cell order as one record (one store into one
// cache line), then turns the records into the rows that its scans read
// (FloatBoundsArray): placed row by row, each box took eight stores into
// eight lines scattered over the cells, most of them cache misses
// (docs/benchmarks.md).

#include "search/float_bounds_array.hpp"
#include "search/line_test.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace particlesim {

struct alignas(32) BoxRecord {
    FloatBounds bounds;
    FloatLine line;
};
static_assert(sizeof(BoxRecord) == 32, "eight floats, one aligned half line");

// The rows a record's eight floats go to, in the record's order.
using RecordRows = const std::array<float*, 8>&;

// rows[f][k] = float f of record k, for k < count, of the records stored as
// bytes from `records` (32 a record, as a BoxRecord's: the grid search keeps
// them in the room of the motion states that its scans with lines do not
// copy). `lanes`: 16, sixteen records at a time by AVX-512 permutations;
// 8, eight at a time by AVX2's transpose (x86-64; the processor must have
// them); else one at a time. The same floats every way.
void records_to_rows(const std::byte* records, std::uint32_t count, RecordRows rows, int lanes);

}  // namespace particlesim
