// SPDX-License-Identifier: Apache-2.0
// Memory for one scene: every buffer a scene owns comes from its memory resource, so the
// caller's allocator callbacks (ent_callbacks) see every byte, and a step can be checked to
// allocate nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <new>
#include <type_traits>
#include <utility>

namespace enteron {

// A memory resource that forwards to C allocate/release callbacks.
class CallbackMemoryResource final : public std::pmr::memory_resource {
public:
    using AllocateFn = void* (*)(void* user, std::size_t size, std::size_t alignment);
    using ReleaseFn = void (*)(void* user, void* memory, std::size_t size, std::size_t alignment);

    CallbackMemoryResource(AllocateFn allocate, ReleaseFn release, void* user)
        : allocate_(allocate), release_(release), user_(user) {}

private:
    void* do_allocate(std::size_t bytes, std::size_t alignment) override {
        void* p = allocate_(user_, bytes, alignment);
        if (p == nullptr) throw std::bad_alloc();
        return p;
    }
    void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
        release_(user_, p, bytes, alignment);
    }
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
        return this == &other;
    }

    AllocateFn allocate_;
    ReleaseFn release_;
    void* user_;
};

// Deletes an object made by make_owned with the resource it came from. It remembers the
// size of the object really made, so an Owned<Derived> may become an Owned<Base> (with a
// virtual destructor) and still be released with the right size.
template <class T>
struct ResourceDeleter {
    std::pmr::memory_resource* resource = nullptr;
    std::size_t size = sizeof(T);
    std::size_t alignment = alignof(T);

    ResourceDeleter() = default;
    explicit ResourceDeleter(std::pmr::memory_resource* r) : resource(r) {}
    template <class U, class = std::enable_if_t<std::is_convertible_v<U*, T*>>>
    ResourceDeleter(const ResourceDeleter<U>& other)
        : resource(other.resource), size(other.size), alignment(other.alignment) {}

    void operator()(T* p) const {
        if (p == nullptr) return;
        // The object may be a derived one: free the address of the complete object.
        void* complete = dynamic_cast_to_complete(p);
        p->~T();
        resource->deallocate(complete, size, alignment);
    }

private:
    static void* dynamic_cast_to_complete(T* p) {
        if constexpr (std::is_polymorphic_v<T>) return dynamic_cast<void*>(p);
        else return p;
    }
};

template <class T>
using Owned = std::unique_ptr<T, ResourceDeleter<T>>;

// Like std::make_unique, but the object lives in `resource`.
template <class T, class... Args>
Owned<T> make_owned(std::pmr::memory_resource* resource, Args&&... args) {
    void* p = resource->allocate(sizeof(T), alignof(T));
    try {
        return Owned<T>(new (p) T(std::forward<Args>(args)...), ResourceDeleter<T>(resource));
    } catch (...) {
        resource->deallocate(p, sizeof(T), alignof(T));
        throw;
    }
}

}  // namespace enteron
