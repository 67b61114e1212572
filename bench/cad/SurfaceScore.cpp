// SPDX-License-Identifier: LGPL-2.1-or-later
// Points inside the faces of both shapes (a grid over their parameters, classified), distances
// by BRepExtrema.
#include "SurfaceScore.h"

#include "RandomBenchmark.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <limits>
#include <vector>

#include "PointGrid.h"

namespace featurelines::bench {

namespace {

/// The kind a true face's surface is, in SurfaceKind's order (B-spline for the rest).
int kindOf(const TopoDS_Face& face)
{
    switch (BRepAdaptor_Surface(face).GetType()) {
    case GeomAbs_Plane:
        return static_cast<int>(surfaces::SurfaceKind::Plane);
    case GeomAbs_Sphere:
        return static_cast<int>(surfaces::SurfaceKind::Sphere);
    case GeomAbs_Cylinder:
        return static_cast<int>(surfaces::SurfaceKind::Cylinder);
    case GeomAbs_Cone:
        return static_cast<int>(surfaces::SurfaceKind::Cone);
    case GeomAbs_Torus:
        return static_cast<int>(surfaces::SurfaceKind::Torus);
    default:
        return static_cast<int>(surfaces::SurfaceKind::BSpline);
    }
}

/// About `count` points inside the face: a grid over its parameter bounds, jittered by a
/// fixed pattern, kept where the face's classifier finds them inside.
std::vector<gp_Pnt> facePoints(const TopoDS_Face& face, int count)
{
    std::vector<gp_Pnt> points;
    double u0 = 0.0;
    double u1 = 0.0;
    double v0 = 0.0;
    double v1 = 0.0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (!(u1 > u0) || !(v1 > v0)) {
        return points;
    }
    const BRepAdaptor_Surface surface(face);
    // Four times as many grid points as wanted: the face may fill a quarter of its bounds.
    const int side = std::max(3, static_cast<int>(std::ceil(std::sqrt(4.0 * count))));
    const double tolerance = 1e-7 * std::max(u1 - u0, v1 - v0);
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            // Golden-ratio offsets: no sample on the grid of a neighbouring face's.
            const double fu = (i + std::fmod(0.618034 * (j + 1), 1.0)) / side;
            const double fv = (j + std::fmod(0.381966 * (i + 1), 1.0)) / side;
            const gp_Pnt2d uv(u0 + fu * (u1 - u0), v0 + fv * (v1 - v0));
            BRepClass_FaceClassifier classifier(face, uv, tolerance);
            if (classifier.State() == TopAbs_IN) {
                points.push_back(surface.Value(uv.X(), uv.Y()));
            }
        }
    }
    if (static_cast<int>(points.size()) > count) {
        std::vector<gp_Pnt> kept;
        const double step = static_cast<double>(points.size()) / count;
        for (int k = 0; k < count; ++k) {
            kept.push_back(points[static_cast<size_t>(k * step)]);
        }
        points.swap(kept);
    }
    return points;
}

/// The distance from p to `shape` and the face it is nearest (null when none).
double distanceTo(const gp_Pnt& p, const TopoDS_Shape& shape, TopoDS_Face* nearest = nullptr)
{
    BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(p).Vertex(), shape);
    if (!distance.IsDone() || distance.NbSolution() == 0) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    if (nearest != nullptr) {
        nearest->Nullify();
        for (int s = 1; s <= distance.NbSolution(); ++s) {
            TopoDS_Shape support = distance.SupportOnShape2(s);
            if (support.ShapeType() == TopAbs_FACE) {
                *nearest = TopoDS::Face(support);
                break;
            }
            // On an edge or vertex: the first face holding it.
            for (TopExp_Explorer f(shape, TopAbs_FACE); f.More() && nearest->IsNull(); f.Next()) {
                for (TopExp_Explorer e(f.Current(), support.ShapeType()); e.More(); e.Next()) {
                    if (e.Current().IsSame(support)) {
                        *nearest = TopoDS::Face(f.Current());
                        break;
                    }
                }
            }
        }
    }
    return distance.Value();
}

void meanAndP95(std::vector<double> values, double spacing, double& mean, double& p95)
{
    if (values.empty()) {
        mean = p95 = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    double sum = 0.0;
    for (double v : values) {
        sum += v;
    }
    mean = sum / static_cast<double>(values.size()) / spacing;
    const size_t k = std::min(values.size() - 1, static_cast<size_t>(0.95 * values.size()));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k),
                     values.end());
    p95 = values[k] / spacing;
}

} // namespace

SurfaceQuality measureSurfaces(const surfaces::PatchSurfaces& fitted, const TopoDS_Shape& truth,
                               const PointMatrix& cloud, double spacing, int samples)
{
    SurfaceQuality q;
    q.patches = static_cast<int>(fitted.faces.size());
    for (const surfaces::PatchFace& f : fitted.faces) {
        if (!f.face.IsNull()) {
            ++q.faces;
            ++q.kinds[static_cast<size_t>(f.surface.kind)];
            q.plates += f.plate ? 1 : 0;
        }
    }
    q.solid = fitted.solid;
    q.valid = fitted.valid;
    q.toTruthMean = q.toTruthP95 = q.fromTruthMean = q.fromTruthP95 =
        std::numeric_limits<double>::quiet_NaN();
    if (fitted.shape.IsNull() || q.faces == 0) {
        return q;
    }
    // The fitted faces' kinds, found again in the sewn shape by their surfaces.
    TopTools_IndexedMapOfShape sewnFaces;
    TopExp::MapShapes(fitted.shape, TopAbs_FACE, sewnFaces);
    std::vector<int> sewnKind(static_cast<size_t>(sewnFaces.Extent()) + 1, -1);
    for (int i = 1; i <= sewnFaces.Extent(); ++i) {
        sewnKind[static_cast<size_t>(i)] = kindOf(TopoDS::Face(sewnFaces(i)));
    }

    // Fitted -> truth.
    std::vector<double> to;
    const int perFace = std::max(1, samples / std::max(1, sewnFaces.Extent()));
    for (int i = 1; i <= sewnFaces.Extent(); ++i) {
        for (const gp_Pnt& p : facePoints(TopoDS::Face(sewnFaces(i)), perFace)) {
            const double d = distanceTo(p, truth);
            if (std::isfinite(d)) {
                to.push_back(d);
            }
        }
    }
    meanAndP95(to, spacing, q.toTruthMean, q.toTruthP95);

    // Truth -> fitted, over the true faces the cloud saw; each face's kind by its samples'
    // nearest fitted faces.
    PointGrid grid(2.0 * spacing);
    for (Eigen::Index i = 0; i < cloud.rows(); ++i) {
        grid.insert(cloud.row(i).transpose(), static_cast<int>(i));
    }
    TopTools_IndexedMapOfShape trueFaces;
    TopExp::MapShapes(truth, TopAbs_FACE, trueFaces);
    std::vector<double> from;
    const int perTrueFace = std::max(5, samples / std::max(1, trueFaces.Extent()));
    for (int i = 1; i <= trueFaces.Extent(); ++i) {
        const TopoDS_Face face = TopoDS::Face(trueFaces(i));
        int seen = 0;
        int right = 0;
        const int kind = kindOf(face);
        for (const gp_Pnt& p : facePoints(face, perTrueFace)) {
            if (!grid.anyWithin(Eigen::Vector3d(p.X(), p.Y(), p.Z()), 2.0 * spacing)) {
                continue;
            }
            ++seen;
            TopoDS_Face nearest;
            const double d = distanceTo(p, fitted.shape, &nearest);
            if (!std::isfinite(d)) {
                continue;
            }
            from.push_back(d);
            if (d <= spacing && !nearest.IsNull()) {
                const int index = sewnFaces.FindIndex(nearest);
                right += index > 0 && sewnKind[static_cast<size_t>(index)] == kind ? 1 : 0;
            }
        }
        if (seen >= 3) {
            ++q.trueFaces;
            q.rightKind += 2 * right > seen ? 1 : 0;
        }
    }
    meanAndP95(from, spacing, q.fromTruthMean, q.fromTruthP95);
    return q;
}

double SurfaceTotals::rightKindShare() const
{
    return trueFaces > 0 ? static_cast<double>(rightKind) / trueFaces
                         : std::numeric_limits<double>::quiet_NaN();
}

SurfaceTotals surfaceTotals(const std::vector<SurfaceQuality>& parts)
{
    SurfaceTotals t;
    double sum = 0.0;
    int withFaces = 0;
    for (const SurfaceQuality& q : parts) {
        ++t.parts;
        t.validSolids += q.solid && q.valid ? 1 : 0;
        t.trueFaces += q.trueFaces;
        t.rightKind += q.rightKind;
        if (std::isfinite(q.toTruthMean)) {
            sum += q.toTruthMean;
            ++withFaces;
        }
    }
    if (withFaces > 0) {
        t.toTruthMean = sum / withFaces;
    }
    return t;
}

SurfaceFloors parseSurfaceFloors(const std::string& text)
{
    SurfaceFloors floors;
    for (const auto& [name, value] :
         parseNamedNumbers(text, "--surface-floor", {"kinds", "solids", "truth"})) {
        (name == "kinds" ? floors.kinds : name == "solids" ? floors.solids : floors.toTruth) =
            value;
    }
    return floors;
}

std::vector<std::string> surfaceFloorFailures(const SurfaceTotals& totals,
                                              const SurfaceFloors& floors)
{
    std::vector<std::string> failures;
    const double share = totals.rightKindShare();
    if (!std::isnan(floors.kinds) && !(share >= floors.kinds)) {
        failures.push_back("the share of true faces of their kind " + formatNumber(share) +
                           " is below its floor " + formatNumber(floors.kinds) + ".");
    }
    if (!std::isnan(floors.solids) && !(totals.validSolids >= floors.solids)) {
        failures.push_back(std::to_string(totals.validSolids) +
                           " valid solids are fewer than the floor's " +
                           formatNumber(floors.solids, 0) + ".");
    }
    if (!std::isnan(floors.toTruth) && !(totals.toTruthMean <= floors.toTruth)) {
        failures.push_back("the faces' mean distance to the truth " +
                           formatNumber(totals.toTruthMean, 3) + " spacing is above its limit " +
                           formatNumber(floors.toTruth, 3) + ".");
    }
    return failures;
}

} // namespace featurelines::bench
