/* SPDX-License-Identifier: Apache-2.0 */
/* The allocation counter shared by alloc_counter.c (malloc and friends) and no_alloc.cpp
 * (operator new and delete). */
#ifndef ENTERON_TESTS_ALLOC_COUNTER_H
#define ENTERON_TESTS_ALLOC_COUNTER_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define ALLOC_COUNTER_CALLERS 16

/* Counts one allocation made from `caller` if counting is on. */
void alloc_counter_note(void* caller);
/* Resets the count to zero and starts counting. */
void alloc_counter_start(void);
/* The same, counting only what the calling thread allocates (other threads may allocate). */
void alloc_counter_start_this_thread(void);
/* Stops counting and returns the number of allocations since alloc_counter_start. */
unsigned long alloc_counter_stop(void);
/* The return address of the index-th counted allocation (the first ALLOC_COUNTER_CALLERS). */
void* alloc_counter_caller(unsigned long index);

/* glibc's allocator itself, uncounted. */
void* alloc_counter_malloc(size_t size);
void* alloc_counter_memalign(size_t alignment, size_t size);
void alloc_counter_free(void* memory);

#ifdef __cplusplus
}
#endif

#endif
