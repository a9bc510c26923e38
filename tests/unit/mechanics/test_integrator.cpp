// SPDX-License-Identifier: Apache-2.0
// The integrators behind one interface (lib/mechanics/integrator.h): make_integrator builds
// the method each IntegratorKind names, with its stability interval, and each converges to
// the harmonic oscillator's closed form (oscillator.h) at its order: halving h divides the
// largest error over a period by 2^p (rk4 p = 4, bdf2 2, implicit and symplectic Euler 1;
// symplectic Euler's error at the period's end alone is second order, its shadow orbit
// being an ellipse tilted by O(h) that closes on itself).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "mechanics/bdf2.h"
#include "mechanics/implicit_euler.h"
#include "mechanics/integrator.h"
#include "mechanics/oscillator.h"
#include "mechanics/rk4.h"
#include "mechanics/symplectic_euler.h"

namespace enteron::mechanics {
namespace {

using mechanics_test::Oscillator;

TEST(Integrator, EachKindMakesItsMethod) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    const AxisModel model = mechanics_test::oscillator_model();
    const Owned<Integrator> rk4 = make_integrator(IntegratorKind::rk4, model, memory);
    const Owned<Integrator> symplectic = make_integrator(IntegratorKind::symplectic_euler, model, memory);
    const Owned<Integrator> euler = make_integrator(IntegratorKind::implicit_euler, model, memory);
    const Owned<Integrator> bdf2 = make_integrator(IntegratorKind::bdf2, model, memory);
    EXPECT_NE(dynamic_cast<const RungeKutta4*>(rk4.get()), nullptr);
    EXPECT_NE(dynamic_cast<const SymplecticEuler*>(symplectic.get()), nullptr);
    EXPECT_NE(dynamic_cast<const ImplicitEuler*>(euler.get()), nullptr);
    EXPECT_NE(dynamic_cast<const Bdf2*>(bdf2.get()), nullptr);
    EXPECT_EQ(rk4->stability_interval(), 2.7);
    EXPECT_EQ(symplectic->stability_interval(), 2.0);
    EXPECT_TRUE(std::isinf(euler->stability_interval()));
    EXPECT_TRUE(std::isinf(bdf2->stability_interval()));
    EXPECT_THROW(make_integrator(static_cast<IntegratorKind>(7), model, memory), Error);
}

// The largest error over one period of the oscillator in n substeps.
double error_over_a_period(IntegratorKind kind, int n) {
    Oscillator o(2.0 * kPi);  // a period of 1 s
    const Owned<Integrator> method = make_integrator(kind, mechanics_test::oscillator_model(), std::pmr::new_delete_resource());
    double largest = 0.0;
    for (int step = 0; step < n; ++step) {
        EXPECT_TRUE(o.run(*method, 1.0 / n, 1));
        largest = std::max(largest, o.error());
    }
    return largest;
}

TEST(Integrator, EachMethodConvergesAtItsOrder) {
    struct Order {
        IntegratorKind kind;
        double p;
    };
    for (const Order order : {Order{IntegratorKind::rk4, 4.0}, Order{IntegratorKind::bdf2, 2.0},
                              Order{IntegratorKind::implicit_euler, 1.0}, Order{IntegratorKind::symplectic_euler, 1.0}}) {
        SCOPED_TRACE("integrator " + std::to_string(static_cast<int>(order.kind)));
        const double coarse = error_over_a_period(order.kind, 200), fine = error_over_a_period(order.kind, 400);
        const double observed = std::log2(coarse / fine);
        EXPECT_NEAR(observed, order.p, 0.2) << "errors " << coarse << " and " << fine;
        EXPECT_LT(fine, order.p > 3.0 ? 1e-9 : 2e-3) << "and small in absolute terms (m, amplitudes of 1-2 cm)";
    }
}

}  // namespace
}  // namespace enteron::mechanics
