// SPDX-License-Identifier: LGPL-2.1-or-later
// Fuzz entry point of the whole extraction on tiny clouds: byte 0 picks k (3 to 10), each
// further 6 bytes are a point of three 16-bit coordinates, scaled by a power of two from
// byte 1 (2^-40 to 2^40) so that clouds of every size, coincident points, lines and planes
// come up. A refusal is a std::invalid_argument; anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "FeatureLines/Extraction.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    constexpr std::size_t maxPoints = 400;
    if (size < 2) {
        return 0;
    }
    const std::size_t n = std::min((size - 2) / 6, maxPoints);
    const double scale = std::ldexp(1.0, int(data[1] % 81) - 40);
    featurelines::PointMatrix P(static_cast<Eigen::Index>(n), 3);
    for (std::size_t i = 0; i < n; ++i) {
        for (int d = 0; d < 3; ++d) {
            std::int16_t value;
            std::memcpy(&value, data + 2 + 6 * i + 2 * d, sizeof value);
            P(static_cast<Eigen::Index>(i), d) = value * scale;
        }
    }
    featurelines::ExtractionOptions options;
    options.neighbours.k = 3 + data[0] % 8;
    options.neighbours.threads = 1;
    try {
        featurelines::extractFeatureLines(P, options);
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
