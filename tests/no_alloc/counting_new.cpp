// SPDX-License-Identifier: Apache-2.0
// Every global operator new and delete of C++17 replaced by counting ones (alloc_counter.h),
// for the no-allocation tests; alloc_counter.c does the same for malloc and friends.
#include <cstddef>
#include <new>

#include "alloc_counter.h"

namespace {
void* counted_new(std::size_t size, void* caller) {
    alloc_counter_note(caller);
    return alloc_counter_malloc(size == 0 ? 1 : size);
}
void* counted_aligned_new(std::size_t size, std::align_val_t alignment, void* caller) {
    alloc_counter_note(caller);
    return alloc_counter_memalign(static_cast<std::size_t>(alignment), size == 0 ? 1 : size);
}
}  // namespace

void* operator new(std::size_t size) {
    void* p = counted_new(size, __builtin_return_address(0));
    if (p == nullptr) throw std::bad_alloc();
    return p;
}
void* operator new[](std::size_t size) {
    void* p = counted_new(size, __builtin_return_address(0));
    if (p == nullptr) throw std::bad_alloc();
    return p;
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return counted_new(size, __builtin_return_address(0));
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return counted_new(size, __builtin_return_address(0));
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    void* p = counted_aligned_new(size, alignment, __builtin_return_address(0));
    if (p == nullptr) throw std::bad_alloc();
    return p;
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    void* p = counted_aligned_new(size, alignment, __builtin_return_address(0));
    if (p == nullptr) throw std::bad_alloc();
    return p;
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return counted_aligned_new(size, alignment, __builtin_return_address(0));
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return counted_aligned_new(size, alignment, __builtin_return_address(0));
}

void operator delete(void* p) noexcept { alloc_counter_free(p); }
void operator delete[](void* p) noexcept { alloc_counter_free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { alloc_counter_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { alloc_counter_free(p); }
void operator delete(void* p, std::size_t) noexcept { alloc_counter_free(p); }
void operator delete[](void* p, std::size_t) noexcept { alloc_counter_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { alloc_counter_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { alloc_counter_free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { alloc_counter_free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { alloc_counter_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { alloc_counter_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { alloc_counter_free(p); }
