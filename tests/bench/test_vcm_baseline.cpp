// SPDX-License-Identifier: LGPL-2.1-or-later
// The VCM baseline (bench/cad/VcmBaseline.h) on a sampled cube, whose 12 sharp edges are
// known exactly.
#include <stdexcept>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <gp_Pnt.hxx>

#include <gtest/gtest.h>

#include "LineScore.h"
#include "ShapeSampling.h"
#include "VcmBaseline.h"

using featurelines::PointMatrix;
using namespace featurelines::bench;

namespace {

struct SampledCube
{
    SampledCloud cloud;
    double spacing;
    std::vector<TypedPolyline> truth;
};

SampledCube sampledCube(double points)
{
    const TopoDS_Shape cube = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 40, 40).Shape();
    SamplingOptions sampling;
    sampling.radius = radiusForPointCount(shapeArea(cube), points);
    SampledCube s;
    s.cloud = sampleShape(cube, sampling);
    s.spacing = meanNearestSpacing(s.cloud.points);
    TruthOptions truth;
    truth.step = 0.5 * s.spacing;
    s.truth = truthEdges(cube, truth);
    return s;
}

PointMatrix flaggedPoints(const PointMatrix& P, const std::vector<double>& ratio, double t)
{
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (ratio[static_cast<size_t>(i)] >= t) {
            rows.push_back(i);
        }
    }
    PointMatrix F(static_cast<Eigen::Index>(rows.size()), 3);
    for (size_t k = 0; k < rows.size(); ++k) {
        F.row(static_cast<Eigen::Index>(k)) = P.row(rows[k]);
    }
    return F;
}

} // namespace

TEST(VcmBaseline, FlagsTheCubesEdgesAndFewFacePoints)
{
    const SampledCube cube = sampledCube(20000);
    ASSERT_EQ(cube.truth.size(), 12u);
    VcmOptions options;
    options.spacing = cube.spacing;
    const std::vector<double> ratio = vcmEdgeRatio(cube.cloud.points, options);
    ASSERT_EQ(ratio.size(), static_cast<size_t>(cube.cloud.points.rows()));
    LineScoreOptions scoring;
    scoring.spacing = cube.spacing;
    const LineScore score = scoreFlaggedPoints(
        flaggedPoints(cube.cloud.points, ratio, vcmDefaultThreshold), cube.truth, scoring);
    const TypeScore& sharp = score.types[static_cast<size_t>(LineType::Sharp)];
    EXPECT_GT(sharp.precision, 0.8);
    EXPECT_GT(sharp.recall, 0.8);
}

TEST(VcmBaseline, RatioAgreesWithCgalsFeatureEdgeTest)
{
    const SampledCube cube = sampledCube(3000);
    VcmOptions options;
    options.spacing = cube.spacing;
    const std::vector<double> ratio = vcmEdgeRatio(cube.cloud.points, options);
    for (double t : {0.05, 0.1, 0.2}) {
        const std::vector<char> flags = vcmFeatureEdgeFlags(cube.cloud.points, options, t);
        ASSERT_EQ(flags.size(), ratio.size());
        int flagged = 0;
        for (size_t i = 0; i < flags.size(); ++i) {
            EXPECT_EQ(flags[i] != 0, ratio[i] >= t);
            flagged += flags[i];
        }
        EXPECT_GT(flagged, 0);
    }
}

TEST(VcmBaseline, BadInputThrows)
{
    PointMatrix P(3, 3);
    P.setRandom();
    EXPECT_THROW(vcmEdgeRatio(P, VcmOptions{}), std::invalid_argument);
    P.resize(10, 3);
    P.setRandom();
    VcmOptions options;
    options.spacing = 0.0;
    EXPECT_THROW(vcmEdgeRatio(P, options), std::invalid_argument);
}
