// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/CloudIO.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace featurelines {

void checkFinite(const PointMatrix& P, const std::string& what, Eigen::Index minimumPoints)
{
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (!P.row(i).allFinite()) {
            throw std::invalid_argument(what + ": point " + std::to_string(i + 1) +
                                        " has a coordinate that is not a finite number");
        }
    }
    if (P.rows() < minimumPoints) {
        throw std::invalid_argument(what + ": " + std::to_string(minimumPoints) +
                                    " points at least are needed, there are " +
                                    std::to_string(P.rows()));
    }
}

} // namespace featurelines
