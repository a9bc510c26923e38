// SPDX-License-Identifier: Apache-2.0
// ENTERON_HOT_KERNEL marks a function that the compiler builds twice, for the x86-64
// baseline and for x86-64-v3 (AVX2), the dynamic loader picking the one this processor runs
// (GCC's target_clones, an ifunc resolved by glibc). The library still runs on any x86-64,
// and the kernels that dominate a step (band updates, factorisation, solve) get twice the
// vector width where it exists. Both builds give the same bits: the library and everything
// built on its headers use -ffp-contract=off, so the wider one fuses no multiply-add that
// the baseline rounds twice, and neither reorders a sum (ctest dispatch.same_bits checks a
// whole trajectory against a baseline-only build). A plain function elsewhere: another
// compiler, GCC before 12 (no "arch=" clones), another architecture or C library, a build
// with ENTERON_CPU_DISPATCH=OFF or with sanitizers (both define ENTERON_HOT_KERNEL empty:
// the loader runs the version-picking resolvers before a sanitizer's runtime has started).
#pragma once

#include <cstddef>  // defines __GLIBC__ where glibc is the C library

#if defined(ENTERON_HOT_KERNEL)
// as the build says
#elif defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12 && defined(__x86_64__) && defined(__GLIBC__)
#define ENTERON_HOT_KERNEL __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define ENTERON_HOT_KERNEL
#endif
