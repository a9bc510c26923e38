// SPDX-License-Identifier: Apache-2.0
// A scene's memory (lib/base/memory.h): CallbackMemoryResource hands every allocation and
// release to the caller's callbacks with its size and alignment, and a null from the
// callback is std::bad_alloc; make_owned puts an object in a resource and its Owned
// releases it there with the size really made, also through a pointer to a base class;
// a constructor that throws leaves nothing allocated.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <new>
#include <stdexcept>

#include "base/memory.h"

namespace enteron {
namespace {

// The caller's side: counts what is allocated and released, by size and alignment.
struct Ledger {
    std::map<void*, std::pair<std::size_t, std::size_t>> live;
    std::size_t allocations = 0, releases = 0;
    bool refuse = false;
    bool mismatch = false;  // a release with another size or alignment than its allocation

    static void* allocate(void* user, std::size_t size, std::size_t alignment) {
        auto* ledger = static_cast<Ledger*>(user);
        if (ledger->refuse) return nullptr;
        void* p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
        ledger->live[p] = {size, alignment};
        ledger->allocations += 1;
        return p;
    }
    static void release(void* user, void* memory, std::size_t size, std::size_t alignment) {
        auto* ledger = static_cast<Ledger*>(user);
        const auto at = ledger->live.find(memory);
        if (at == ledger->live.end() || at->second != std::make_pair(size, alignment)) ledger->mismatch = true;
        else ledger->live.erase(at);
        ledger->releases += 1;
        std::free(memory);
    }
};

struct Base {
    virtual ~Base() = default;
    int base_value = 1;
};
struct Derived final : Base {
    explicit Derived(bool* destroyed) : destroyed(destroyed) {}
    ~Derived() override { *destroyed = true; }
    bool* destroyed;
    alignas(32) double payload[9] = {};
};
struct Throws {
    Throws() { throw std::runtime_error("no"); }
    double value[4];
};

TEST(Memory, EveryAllocationGoesThroughTheCallbacks) {
    Ledger ledger;
    CallbackMemoryResource resource(Ledger::allocate, Ledger::release, &ledger);
    {
        std::pmr::vector<double> values(1000, 1.0, &resource);
        values.resize(5000);
        EXPECT_GE(ledger.allocations, 2u);
    }
    EXPECT_TRUE(ledger.live.empty());
    EXPECT_EQ(ledger.allocations, ledger.releases);
    EXPECT_FALSE(ledger.mismatch);
    ledger.refuse = true;
    EXPECT_THROW(static_cast<void>(resource.allocate(64, 8)), std::bad_alloc);
    CallbackMemoryResource other(Ledger::allocate, Ledger::release, &ledger);
    EXPECT_TRUE(resource.is_equal(resource));
    EXPECT_FALSE(resource.is_equal(other)) << "two resources never share their blocks";
}

TEST(Memory, AnOwnedDerivedObjectIsReleasedWithTheSizeItWasMadeWith) {
    Ledger ledger;
    CallbackMemoryResource resource(Ledger::allocate, Ledger::release, &ledger);
    bool destroyed = false;
    {
        Owned<Base> base = make_owned<Derived>(&resource, &destroyed);  // the deleter converts
        ASSERT_EQ(ledger.live.size(), 1u);
        EXPECT_EQ(ledger.live.begin()->second, std::make_pair(sizeof(Derived), alignof(Derived)));
        EXPECT_EQ(base->base_value, 1);
    }
    EXPECT_TRUE(destroyed);
    EXPECT_TRUE(ledger.live.empty());
    EXPECT_FALSE(ledger.mismatch) << "released with Derived's size and alignment, not Base's";
    Owned<Base> empty;  // a null Owned releases nothing
    empty.reset();
    EXPECT_EQ(ledger.releases, 1u);
}

TEST(Memory, AConstructorThatThrowsLeavesNothingAllocated) {
    Ledger ledger;
    CallbackMemoryResource resource(Ledger::allocate, Ledger::release, &ledger);
    EXPECT_THROW(make_owned<Throws>(&resource), std::runtime_error);
    EXPECT_EQ(ledger.allocations, 1u);
    EXPECT_TRUE(ledger.live.empty());
    EXPECT_FALSE(ledger.mismatch);
}

}  // namespace
}  // namespace enteron
