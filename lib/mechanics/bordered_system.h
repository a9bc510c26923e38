// SPDX-License-Identifier: Apache-2.0
// Bodies outside the bowel whose unknowns the implicit step solves together with the bowel's:
// a tool's proxy, a massless body held between the device and the bowel by its contacts.
// Each body b brings three unknowns e_b, and the linearised system gains a border:
//
//   [  A    -B ] [dv]   [ r  ]
//   [ -B^T   P ] [e ] = [ r_p]
//
// A is the bowel's banded system (3n x 3n), B the bodies' couplings to it (3n x 3 per body,
// non-zero only at the control points a body touches) and P the bodies' own blocks (3 x 3
// each). The whole matrix is symmetric positive semi-definite when each body is held by
// springs and dampers (its contacts) that also act on the bowel. The bodies are eliminated
// (the Schur complement, the Sherman-Morrison-Woodbury formula): with y = A^-1 r already
// solved and X = A^-1 B,
//
//   (P - B^T X) e = r_p + B^T y,     dv = y + X e.
//
// The bowel's answer to a load at a few control points fades within a few control points
// in one substep (a wave travels about c h: 18 mm in 1 ms along the default bowel), so X is
// solved on a window around them (BandedSpdMatrix::solve_window) to a relative tolerance of
// kWindowTolerance: a proxy touching one fold costs a few dozen rows, not two whole solves.
//
// A direction in which a body is not held (a frictionless contact does not hold it along
// the surface) is a zero pivot of P - B^T X; its unknown is set to zero (the body does not
// move that way in the substep), which solves the system whenever its right-hand side has
// no part along that direction (a body in equilibrium).
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "mechanics/system_matrix.h"
#include "spline/catmull_rom.h"

namespace enteron::mechanics {

class BorderedSystem {
public:
    // Relative size below which X is taken as zero outside its window.
    static constexpr double kWindowTolerance = 1e-18;

    explicit BorderedSystem(std::pmr::memory_resource* memory);

    // Makes room for up to `bodies` bodies on `coordinates` (3n) coordinates. Allocates; not
    // during a step.
    void reserve(std::size_t bodies, std::size_t coordinates);
    std::size_t capacity() const { return capacity_; }

    // Removes every body (before an evaluation adds them again).
    void clear();
    std::size_t size() const { return bodies_; }

    // Adds a body with its block P (symmetric) and its right-hand side r_p; returns its index
    // (0, 1, ... in order). At most capacity() bodies.
    std::size_t add_body(const Mat3& block, const Vec3& rhs);
    // Adds w (x) E to the body's rows of B at the four control points of a spline point: the
    // rows 3 (first + k) + c get w_k E(c, .).
    void add_coupling(std::size_t body, const spline::SegmentWeights& weights, const Mat3& coupling);
    // Zeroes row `coordinate` of B: a pinned coordinate, which the bodies must not move.
    void zero_row(std::size_t coordinate);

    // With `factored` = A factored and dv = y = A^-1 r: solves for the bodies' unknowns and
    // corrects dv to the bowel's part of the bordered system's solution. Allocates nothing.
    void solve(const SystemMatrix& factored, double* dv);
    // Body b's unknowns from the last solve.
    Vec3 solution(std::size_t body) const { return point_at(solution_.data(), body); }

private:
    struct Body {
        Mat3 block;
        Vec3 rhs;
        std::size_t first_row, last_row;  // rows of B it touches (first > last: none)
    };

    std::size_t capacity_ = 0;
    std::size_t bodies_ = 0;
    std::size_t coordinates_ = 0;
    std::pmr::vector<Body> body_;
    // B for every body, its 3 columns interleaved by row: columns_[b][3 k + c]; replaced by X
    // in solve, then zeroed again on the rows it used.
    std::pmr::vector<std::pmr::vector<double>> columns_;
    std::pmr::vector<std::pmr::vector<double>> couplings_;  // B again, kept while X is solved
    std::pmr::vector<double> schur_;     // P - B^T X, 3 bodies x 3 bodies, row-major
    std::pmr::vector<double> solution_;  // e, then r_p + B^T y before it is solved
    std::pmr::vector<std::size_t> window_first_, window_last_;  // rows of each body's X
};

}  // namespace enteron::mechanics
