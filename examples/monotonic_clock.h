/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The two clock helpers the threaded examples share: seconds elapsed on CLOCK_MONOTONIC,
 * and an absolute deadline for clock_nanosleep(..., TIMER_ABSTIME, ...). Plain C99 with
 * POSIX; define _POSIX_C_SOURCE before including it.
 */
#ifndef ENTERON_EXAMPLES_MONOTONIC_CLOCK_H
#define ENTERON_EXAMPLES_MONOTONIC_CLOCK_H

#include <math.h>
#include <time.h>

/* Seconds from *start to now. */
static double seconds_since(const struct timespec* start) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + 1e-9 * (double)(now.tv_nsec - start->tv_nsec);
}

/* The instant `seconds` after *start. */
static struct timespec after(const struct timespec* start, double seconds) {
    struct timespec t = *start;
    const double whole = floor(seconds);
    t.tv_sec += (time_t)whole;
    t.tv_nsec += (long)((seconds - whole) * 1e9);
    if (t.tv_nsec >= 1000000000L) {
        t.tv_sec += 1;
        t.tv_nsec -= 1000000000L;
    }
    return t;
}

#endif
