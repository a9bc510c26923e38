// SPDX-License-Identifier: Apache-2.0
// The work behind a slow step that only the effects see, for ent_stats: what the last step
// did over all its attempts, and the slow paths taken so far. Effects add their part
// (Effect::add_work); the scene publishes the sum with its own counts of attempts and
// substeps.
#pragma once

#include <cstdint>

namespace enteron::mechanics {

struct StepWork {
    uint32_t proxy_iterations = 0;       // the most Newton iterations of one tool proxy's solve, last step
    uint32_t proxy_evaluations = 0;      // the proxies' balance evaluations (iterations, halvings), last step
    uint64_t proxy_unbalanced = 0;       // proxy solves that ran out of iterations unbalanced, so far
    uint64_t full_contact_searches = 0;  // self-contact near-pair lists remade for every sphere, so far
};

}  // namespace enteron::mechanics
