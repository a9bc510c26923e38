/* SPDX-License-Identifier: Apache-2.0 */
/* Counting replacements of the C allocation functions for the no-allocation test. They forward
 * to glibc's own implementations (__libc_malloc and friends), so they can be defined in the
 * executable and interpose malloc for every shared library of the process, libenteron.so and
 * libstdc++.so included. Written in C so the declarations need no C++ exception specifiers. */
#include "alloc_counter.h"

#include <errno.h>
#include <stddef.h>

extern void* __libc_malloc(size_t size);
extern void* __libc_calloc(size_t count, size_t size);
extern void* __libc_realloc(void* memory, size_t size);
extern void __libc_free(void* memory);
extern void* __libc_memalign(size_t alignment, size_t size);

static volatile int counting = 0;
static volatile int one_thread = 0;     /* count only the thread that called _start_this_thread */
static __thread int counted_thread = 0;
static unsigned long counted = 0;
static void* callers[ALLOC_COUNTER_CALLERS];

void alloc_counter_note(void* caller) {
    if (!counting || (one_thread && !counted_thread)) return;
    /* One thread allocates during the counted part; the atomic add keeps it exact anyway. */
    unsigned long index = __atomic_fetch_add(&counted, 1ul, __ATOMIC_RELAXED);
    if (index < ALLOC_COUNTER_CALLERS) callers[index] = caller;
}

void alloc_counter_start(void) {
    __atomic_store_n(&counted, 0ul, __ATOMIC_RELAXED);
    one_thread = 0;
    counting = 1;
}

void alloc_counter_start_this_thread(void) {
    __atomic_store_n(&counted, 0ul, __ATOMIC_RELAXED);
    counted_thread = 1;
    one_thread = 1;
    counting = 1;
}

unsigned long alloc_counter_stop(void) {
    counting = 0;
    one_thread = 0;
    counted_thread = 0;
    return __atomic_load_n(&counted, __ATOMIC_RELAXED);
}

void* alloc_counter_caller(unsigned long index) {
    return index < ALLOC_COUNTER_CALLERS ? callers[index] : NULL;
}

void* alloc_counter_malloc(size_t size) { return __libc_malloc(size); }
void* alloc_counter_memalign(size_t alignment, size_t size) { return __libc_memalign(alignment, size); }
void alloc_counter_free(void* memory) { __libc_free(memory); }

void* malloc(size_t size) {
    alloc_counter_note(__builtin_return_address(0));
    return __libc_malloc(size);
}

void* calloc(size_t count, size_t size) {
    alloc_counter_note(__builtin_return_address(0));
    return __libc_calloc(count, size);
}

void* realloc(void* memory, size_t size) {
    alloc_counter_note(__builtin_return_address(0));
    return __libc_realloc(memory, size);
}

void free(void* memory) { __libc_free(memory); }

void* aligned_alloc(size_t alignment, size_t size) {
    alloc_counter_note(__builtin_return_address(0));
    return __libc_memalign(alignment, size);
}

void* memalign(size_t alignment, size_t size) {
    alloc_counter_note(__builtin_return_address(0));
    return __libc_memalign(alignment, size);
}

int posix_memalign(void** out, size_t alignment, size_t size) {
    void* memory;
    alloc_counter_note(__builtin_return_address(0));
    if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return EINVAL;
    memory = __libc_memalign(alignment, size);
    if (memory == NULL) return ENOMEM;
    *out = memory;
    return 0;
}
