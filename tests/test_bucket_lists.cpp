// The linked buckets of the exact engine's cells and linked calendar, against
// a plain model (a vector per bucket) over random inserts and moves: every
// bucket holds what the model holds, and gather() lists exactly what
// for_each_in() visits, in the same order, the skipped item left out, within
// the room it is given; each bucket's head names its first two items, also
// after the first is moved away (the third becomes the second, read through
// the spare slot when there is none).

#include "check.hpp"

#include "core/random.hpp"
#include "exact/bucket_lists.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

using particlesim::BucketLists;

namespace {

std::vector<std::uint32_t> visited(const BucketLists& lists, std::uint32_t bucket) {
    std::vector<std::uint32_t> items;
    lists.for_each_in(bucket, [&](std::uint32_t item) { items.push_back(item); });
    return items;
}

// gather() after `already` places, into room for every item and more; the
// places past the one after the last gathered must keep their mark.
std::vector<std::uint32_t> gathered(const BucketLists& lists, std::uint32_t bucket, std::uint32_t skipped,
                                    std::uint32_t items, std::size_t already) {
    constexpr std::uint32_t mark = 0xabcdef01U;
    std::vector<std::uint32_t> out(already + items + 8, mark);
    const std::size_t end = lists.gather(bucket, skipped, out.data(), already);
    CHECK(end >= already && end <= already + items);
    for (std::size_t k = end + 1; k < out.size(); ++k) CHECK_EQ(out[k], mark);
    return {out.begin() + static_cast<std::ptrdiff_t>(already), out.begin() + static_cast<std::ptrdiff_t>(end)};
}

void matches_model(std::uint32_t buckets, std::uint32_t items, std::uint64_t seed, int operations) {
    particlesim::SplitMix64 rng(seed);
    BucketLists lists(buckets, items);
    std::vector<std::vector<std::uint32_t>> model(buckets);
    std::vector<std::uint32_t> bucket_of(items);
    for (std::uint32_t item = 0; item < items; ++item) {
        bucket_of[item] = static_cast<std::uint32_t>(rng.next() % buckets);
        lists.insert(item, bucket_of[item]);
        model[bucket_of[item]].push_back(item);
    }
    std::uint64_t members_gathered = 0;
    for (int operation = 0; operation < operations; ++operation) {
        const auto item = static_cast<std::uint32_t>(rng.next() % items);
        const auto to = static_cast<std::uint32_t>(rng.next() % buckets);
        std::vector<std::uint32_t>& from = model[bucket_of[item]];
        from.erase(std::find(from.begin(), from.end(), item));
        lists.move(item, to);
        model[to].push_back(item);
        bucket_of[item] = to;
        CHECK_EQ(lists.bucket_of(item), to);

        const auto bucket = static_cast<std::uint32_t>(rng.next() % buckets);
        const std::vector<std::uint32_t> order = visited(lists, bucket);
        std::vector<std::uint32_t> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        std::vector<std::uint32_t> expected = model[bucket];
        std::sort(expected.begin(), expected.end());
        CHECK(sorted == expected);
        // The head names the first two.
        CHECK_EQ(lists.first(bucket), order.empty() ? BucketLists::none : order[0]);
        CHECK_EQ(lists.second(bucket), order.size() < 2 ? BucketLists::none : order[1]);

        // Skipping a member, an item elsewhere, and nothing.
        const std::uint32_t member = order.empty() ? BucketLists::none : order[rng.next() % order.size()];
        for (const std::uint32_t skipped : {member, item, BucketLists::none}) {
            std::vector<std::uint32_t> wanted;
            for (const std::uint32_t k : order) {
                if (k != skipped) wanted.push_back(k);
            }
            const std::size_t already = rng.next() % 3;
            CHECK(gathered(lists, bucket, skipped, items, already) == wanted);
            members_gathered += wanted.size();
        }
    }
    CHECK(members_gathered > 0);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_bucket_lists",
                      {{"linked buckets against a model; gather() lists what for_each_in() visits", [] {
                            // Mostly empty buckets and single items, as in the cells, and crowded ones.
                            matches_model(400, 150, 1, 20000);
                            matches_model(7, 60, 2, 20000);
                            matches_model(1, 5, 3, 2000);
                            matches_model(3, 1, 4, 200);
                        }}});
}
