// SPDX-License-Identifier: Apache-2.0
// Doubles that take the same operations together: four (a Quad) or two (a Pair) in one SIMD
// register where the processor has one (GCC/Clang vector extensions; elsewhere the compiler
// lowers them to scalar code). Each lane rounds exactly as the scalar code would (the library
// builds with -ffp-contract=off: no fused multiply-add), so a loop rewritten in lanes gives the
// bits of the loop it replaces; in a ENTERON_HOT_KERNEL's x86-64-v3 build a Quad is one AVX
// register. The helpers take pointers, not vectors: a 32-byte vector in a signature changes
// the calling convention between the baseline and the AVX builds.
#pragma once

#include <cstring>

namespace enteron::numerics {

typedef double Pair __attribute__((vector_size(2 * sizeof(double))));
typedef double Quad __attribute__((vector_size(4 * sizeof(double))));

// out[i] += x0 * a[i] + x1 * b[i] for the lanes of one Lanes (a Quad or a Pair).
template <typename Lanes>
inline void add_two_products_in_lanes(double* out, double x0, const double* a, double x1, const double* b) {
    constexpr int kLanes = static_cast<int>(sizeof(Lanes) / sizeof(double));
    Lanes s0, s1, va, vb, vo;
    for (int i = 0; i < kLanes; ++i) s0[i] = x0, s1[i] = x1;
    std::memcpy(&va, a, sizeof va);
    std::memcpy(&vb, b, sizeof vb);
    std::memcpy(&vo, out, sizeof vo);
    vo += s0 * va + s1 * vb;
    std::memcpy(out, &vo, sizeof vo);
}

// out[c] += x0 * a[c] + x1 * b[c] for c < Count: Quads, then a Pair, then one.
template <int Count>
inline void add_two_products(double* out, double x0, const double* a, double x1, const double* b) {
    int c = 0;
    for (; c + 4 <= Count; c += 4) add_two_products_in_lanes<Quad>(out + c, x0, a + c, x1, b + c);
    if constexpr (Count % 4 >= 2) {
        add_two_products_in_lanes<Pair>(out + c, x0, a + c, x1, b + c);
        c += 2;
    }
    if constexpr (Count % 2 == 1) out[c] += x0 * a[c] + x1 * b[c];
}

}  // namespace enteron::numerics
