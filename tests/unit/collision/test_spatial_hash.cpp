// SPDX-License-Identifier: Apache-2.0
// The spatial hash (lib/collision/spatial_hash.h) finds exactly the pairs a brute-force
// search finds, whether built at once or refiled point by point.
#include "collision/spatial_hash.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory_resource>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

using enteron::collision::SpatialHash;

TEST(SpatialHash, CandidatePairsCoverBruteForceAndRepeatNone) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 20; ++trial) {
        const std::size_t count = 50 + 40 * trial;
        const double cell = 0.025;
        std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
        std::vector<double> points(3 * count);
        for (double& p : points) p = coordinate(random);
        SpatialHash grid(count, cell, std::pmr::new_delete_resource());
        grid.build(points.data(), count, 3);
        std::set<std::pair<std::size_t, std::size_t>> found;
        std::size_t visits = 0;
        grid.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
            ++visits;
            found.insert({std::min(i, j), std::max(i, j)});
        });
        EXPECT_EQ(visits, found.size()) << "a pair was visited twice";
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t j = i + 1; j < count; ++j) {
                const double* a = &points[3 * i];
                const double* b = &points[3 * j];
                const double d2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                  (a[2] - b[2]) * (a[2] - b[2]);
                if (d2 < cell * cell) {
                    EXPECT_TRUE(found.count({i, j})) << "missed pair " << i << ", " << j;
                }
            }
    }
}

TEST(SpatialHash, PointsRefiledOneByOneFindTheSamePairsAsARebuild) {
    // The self-contact refiles only the spheres that moved; after any sequence of moves the
    // grid must answer as one built from scratch at the new places.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-0.1, 0.1), step(-0.03, 0.03);
    const std::size_t count = 400;
    const double cell = 0.025;
    std::vector<double> points(3 * count);
    for (double& p : points) p = coordinate(random);
    SpatialHash moved(count, cell, std::pmr::new_delete_resource());
    moved.build(points.data(), count, 3);
    for (int round = 0; round < 10; ++round) {
        for (std::size_t i = round % 3; i < count; i += 2) {  // some move a little, some across cells
            for (int c = 0; c < 3; ++c) points[3 * i + c] += (i % 5 == 0 ? 4.0 : 1.0) * step(random);
            moved.move(i, enteron::point_at(points.data(), i));
        }
        SpatialHash rebuilt(count, cell, std::pmr::new_delete_resource());
        rebuilt.build(points.data(), count, 3);
        // Sorted lists, not sets: a pair visited twice (a point filed twice) must show.
        auto pairs_of = [](const SpatialHash& grid) {
            std::vector<std::pair<std::size_t, std::size_t>> pairs;
            grid.for_each_candidate_pair(
                [&](std::size_t i, std::size_t j) { pairs.emplace_back(std::min(i, j), std::max(i, j)); });
            std::sort(pairs.begin(), pairs.end());
            return pairs;
        };
        EXPECT_EQ(pairs_of(moved), pairs_of(rebuilt)) << "round " << round;
        for (std::size_t i = 0; i < count; i += 37) {
            std::vector<std::size_t> a, b;
            moved.for_each_neighbour(i, [&](std::size_t j) { a.push_back(j); });
            rebuilt.for_each_neighbour(i, [&](std::size_t j) { b.push_back(j); });
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            EXPECT_EQ(a, b) << "round " << round << ", point " << i;
        }
    }
}

}  // namespace
