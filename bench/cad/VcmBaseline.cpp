// SPDX-License-Identifier: LGPL-2.1-or-later
#include "VcmBaseline.h"

#include <array>
#include <cmath>
#include <stdexcept>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/vcm_estimate_edges.h>

namespace featurelines::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Covariance = std::array<double, 6>;

std::vector<Covariance> convolvedCovariances(const PointMatrix& P, const VcmOptions& options)
{
    if (P.rows() < 4) {
        throw std::invalid_argument("VCM needs at least 4 points.");
    }
    if (!(options.spacing > 0.0) || !std::isfinite(options.spacing) ||
        !(options.offsetRadius > 0.0) || !std::isfinite(options.offsetRadius) ||
        !(options.convolutionRadius >= 0.0) || !std::isfinite(options.convolutionRadius)) {
        throw std::invalid_argument("VCM needs a positive spacing and offset radius and a "
                                    "convolution radius of zero or more.");
    }
    std::vector<Kernel::Point_3> points;
    points.reserve(static_cast<std::size_t>(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        points.emplace_back(P(i, 0), P(i, 1), P(i, 2));
    }
    std::vector<Covariance> covariances;
    CGAL::compute_vcm(points, covariances, options.offsetRadius * options.spacing,
                      options.convolutionRadius * options.spacing,
                      CGAL::parameters::geom_traits(Kernel()));
    return covariances;
}

} // namespace

std::vector<double> vcmEdgeRatio(const PointMatrix& P, const VcmOptions& options)
{
    std::vector<Covariance> covariances = convolvedCovariances(P, options);
    std::vector<double> ratios(covariances.size(), 0.0);
    for (std::size_t i = 0; i < covariances.size(); ++i) {
        // The diagonalisation vcm_is_on_feature_edge makes (CGAL/vcm_estimate_edges.h).
        std::array<double, 3> eigenvalues;
        if (!CGAL::Default_diagonalize_traits<double, 3>::diagonalize_selfadjoint_covariance_matrix(
                covariances[i], eigenvalues)) {
            continue;
        }
        const double sum = eigenvalues[0] + eigenvalues[1] + eigenvalues[2];
        ratios[i] = sum > 0.0 ? eigenvalues[1] / sum : 0.0;
    }
    return ratios;
}

std::vector<char> vcmFeatureEdgeFlags(const PointMatrix& P, const VcmOptions& options,
                                      double threshold)
{
    std::vector<Covariance> covariances = convolvedCovariances(P, options);
    std::vector<char> flags(covariances.size(), 0);
    for (std::size_t i = 0; i < covariances.size(); ++i) {
        flags[i] = CGAL::vcm_is_on_feature_edge(covariances[i], threshold) ? 1 : 0;
    }
    return flags;
}

} // namespace featurelines::bench
