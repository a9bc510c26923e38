// SPDX-License-Identifier: Apache-2.0
#include "spline/gram_matrix.h"

#include "numerics/gauss_legendre.h"

namespace enteron::spline {

void add_gram_matrix(std::size_t count, Derivative order, double scale, numerics::ScalarBandMatrix& out,
                     Ends ends, const LengthProfile* profile, double segment_length, std::size_t first) {
    constexpr auto rule = numerics::gauss_legendre<4>();
    for (std::size_t segment = 0; segment + 1 < count; ++segment) {
        for (const auto& node : rule) {
            const SegmentWeights sw = segment_weights(count, segment, node.t, order, ends);
            const double factor =
                profile != nullptr ? scale * profile->at(segment_length * (double(segment) + node.t)) : scale;
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k <= j; ++k)
                    out.lower(first + sw.first + j, first + sw.first + k) += factor * node.weight * sw.w[j] * sw.w[k];
        }
    }
}

}  // namespace enteron::spline
