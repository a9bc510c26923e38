// SPDX-License-Identifier: Apache-2.0
// Futex calls of Wakeup (Linux).
#include "lcm/wakeup.h"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

namespace enteron::lcm {

static_assert(sizeof(std::atomic<uint32_t>) == sizeof(uint32_t), "a futex is a 32-bit word");

void Wakeup::notify() {
    counter_.fetch_add(1, std::memory_order_seq_cst);
    if (sleeping_.load(std::memory_order_seq_cst))
        syscall(SYS_futex, reinterpret_cast<uint32_t*>(&counter_), FUTEX_WAKE_PRIVATE, 1, nullptr, nullptr, 0);
}

void Wakeup::sleep(uint32_t seen, int64_t timeout_ns) {
    const timespec timeout{static_cast<time_t>(timeout_ns / 1000000000), static_cast<long>(timeout_ns % 1000000000)};
    // Returns at once if the counter moved since `seen` (EAGAIN), on a wake, or at the timeout.
    syscall(SYS_futex, reinterpret_cast<uint32_t*>(&counter_), FUTEX_WAIT_PRIVATE, seen, &timeout, nullptr, 0);
}

}  // namespace enteron::lcm
