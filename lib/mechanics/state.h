// SPDX-License-Identifier: Apache-2.0
// The mechanical state of the axis: control point positions q and velocities v (x y z per
// point, m and m/s) and the simulated time.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory_resource>
#include <vector>

namespace enteron::mechanics {

struct State {
    explicit State(std::pmr::memory_resource* memory = std::pmr::get_default_resource())
        : q(memory), v(memory) {}

    void resize(std::size_t control_points) {
        q.assign(3 * control_points, 0.0);
        v.assign(3 * control_points, 0.0);
    }
    std::size_t count() const { return q.size() / 3; }

    // Copies another state of the same size without allocating.
    void assign(const State& other) {
        std::copy(other.q.begin(), other.q.end(), q.begin());
        std::copy(other.v.begin(), other.v.end(), v.begin());
        time = other.time;
    }

    std::pmr::vector<double> q;
    std::pmr::vector<double> v;
    double time = 0.0;
};

}  // namespace enteron::mechanics
