// SPDX-License-Identifier: LGPL-2.1-or-later
// Typing by profile: a crease or a blend across every sharp line, from the faces' planes and
// the cloud's profile between them.
#include "FeatureLines/sharp/ProfileTyping.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "FeatureLines/network/NodeGraph.h"
#include "FeatureLines/sharp/PlaneFit.h"
#include "FeatureLines/sharp/SharpEdges.h"
#include "FeatureLines/support/IdleThreads.h"

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;
/// Spacings between the radii tried.
constexpr double radiusStep = 0.1;
/// Spacings between the chamfer setbacks tried, and how many (0 .. 10 spacings).
constexpr double setbackStep = 0.5;
constexpr int setbacks = 21;

/// The fit at one vertex of a sharp line.
struct Station
{
    bool valid = false;
    Eigen::Vector3d apex = Eigen::Vector3d::Zero();
    /// Unit directions from the apex into the two faces, across the line.
    Eigen::Vector3d side[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    /// Radians: the angle between side[0] and side[1].
    double opening = 0.0;
    /// Spacings: the distance from the line's vertex to the apex (0 for a line on its crease;
    /// several spacings at the middle of a blend whose faces meet at an acute angle).
    double apexDistance = 0.0;
    /// The profile's truncated squared residual per radius tried (radiusStep apart, from 0).
    std::vector<float> cost;
    /// The profile (spacings), in the frame of the side first found (x along it).
    std::vector<Eigen::Vector2d> profile;
    /// The sides were swapped to follow the line (side[0] is then the x axis's mirror).
    bool swapped = false;
    /// A face's plane passes near the vertex (the first face was found; the station may still
    /// lack a second).
    bool faced = false;
};

/// The profile model: two rays from the origin, along x and at `opening` from it, joined by
/// an arc of radius r tangent to both (r = 0: the crease itself).
class ProfileModel
{
public:
    explicit ProfileModel(double opening)
        : side2_(std::cos(opening), std::sin(opening)),
          normal2_(-std::sin(opening), std::cos(opening)),
          bisector_(std::cos(opening / 2.0), std::sin(opening / 2.0)),
          tanHalf_(std::tan(opening / 2.0)), sinHalf_(std::sin(opening / 2.0))
    {
    }

    /// Tangent length: from the apex to where the arc of radius r meets a ray.
    double tangentLength(double r) const { return r / tanHalf_; }

    double distance(const Eigen::Vector2d& q, double r) const
    {
        const double t = tangentLength(r);
        const double s1 = q.x();
        const double d1 = s1 >= t ? std::abs(q.y()) : (q - Eigen::Vector2d(t, 0.0)).norm();
        const double s2 = q.dot(side2_);
        const double d2 = s2 >= t ? std::abs(q.dot(normal2_)) : (q - t * side2_).norm();
        double d = std::min(d1, d2);
        if (r > 0.0) {
            const Eigen::Vector2d v = q - bisector_ * (r / sinHalf_);
            const double length = v.norm();
            // On the arc's side of the centre: within half the arc's angle (pi - opening) of the
            // direction back to the apex.
            if (length > 0.0 && -v.dot(bisector_) >= length * sinHalf_) {
                d = std::min(d, std::abs(length - r));
            }
        }
        return d;
    }

    /// The distance to the two rays joined by a flat cut from s1 along the first to s2 along
    /// the second (a chamfer, or a third face between the two).
    double chamferDistance(const Eigen::Vector2d& q, double s1, double s2) const
    {
        const Eigen::Vector2d a(s1, 0.0);
        const Eigen::Vector2d b = s2 * side2_;
        const double d1 = q.x() >= s1 ? std::abs(q.y()) : (q - a).norm();
        const double d2 = q.dot(side2_) >= s2 ? std::abs(q.dot(normal2_)) : (q - b).norm();
        const Eigen::Vector2d ab = b - a;
        const double t =
            ab.squaredNorm() > 0.0 ? std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        return std::min({d1, d2, (q - a - t * ab).norm()});
    }

private:
    Eigen::Vector2d side2_;
    Eigen::Vector2d normal2_;
    Eigen::Vector2d bisector_;
    double tanHalf_;
    double sinHalf_;
};

/// The points near the sharp lines, in a grid for the stations' radius queries.
struct NearbyPoints
{
    std::vector<Eigen::Vector3d> centres;
    std::vector<int> index;
};

NearbyPoints pointsNearLines(const PointMatrix& P, const std::vector<char>& boundary,
                             const LineNetwork& network, double cell)
{
    auto cellKey = [cell](const Eigen::Vector3d& x) {
        const Eigen::Vector3i c = (x / cell).array().floor().cast<int>();
        const auto part = [](int v) { return static_cast<std::int64_t>(v & 0x1FFFFF); };
        return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
    };
    std::unordered_set<std::int64_t> cells;
    for (const Polyline& line : network.lines) {
        if (line.label != sharpLineLabel) {
            continue;
        }
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            const Eigen::Vector3d x = line.points.row(i).transpose();
            for (int dx = -1; dx <= 1; ++dx) {
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dz = -1; dz <= 1; ++dz) {
                        cells.insert(cellKey(x + cell * Eigen::Vector3d(dx, dy, dz)));
                    }
                }
            }
        }
    }
    NearbyPoints near;
    if (cells.empty()) {
        return near;
    }
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if ((boundary.empty() || !boundary[i]) && cells.count(cellKey(P.row(i).transpose()))) {
            near.centres.push_back(P.row(i).transpose());
            near.index.push_back(static_cast<int>(i));
        }
    }
    return near;
}

/// The points (rows of P) split into the two groups of normals that turn from each other by
/// more than asin(minSine), or left whole when their normals do not: each group's normal is the
/// dominant direction of its normals (unoriented), a point joins the nearer.
std::vector<std::vector<int>> splitNormals(const NormalMatrix& N, const std::vector<int>& points,
                                           double minSine)
{
    auto dominant = [&](const std::vector<int>& group) {
        Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
        for (int i : group) {
            const Eigen::Vector3d n = N.row(i).transpose();
            m += n * n.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(m);
        return Eigen::Vector3d(solver.eigenvectors().col(2));
    };
    if (N.rows() == 0 || points.size() < 2) {
        return {points};
    }
    Eigen::Vector3d a = dominant(points);
    // The normal farthest from the dominant one seeds the other group.
    int far = points.front();
    for (int i : points) {
        if (std::abs(N.row(i).dot(a)) < std::abs(N.row(far).dot(a))) {
            far = i;
        }
    }
    Eigen::Vector3d b = N.row(far).transpose();
    std::vector<std::vector<int>> groups(2);
    for (int pass = 0; pass < 2; ++pass) {
        if (a.cross(b).norm() < minSine) {
            return {points};
        }
        groups[0].clear();
        groups[1].clear();
        for (int i : points) {
            groups[std::abs(N.row(i).dot(a)) >= std::abs(N.row(i).dot(b)) ? 0 : 1].push_back(i);
        }
        if (groups[1].empty()) {
            return {points};
        }
        a = dominant(groups[0]);
        b = dominant(groups[1]);
    }
    return a.cross(b).norm() < minSine ? std::vector<std::vector<int>>{points} : groups;
}

class StationFitter
{
public:
    StationFitter(const PointMatrix& P, const NormalMatrix& normals,
                  const FirstOrderSegmentation& seg, const NearbyPoints& near,
                  const clustergraph::NodeGrid& grid, double spacing,
                  const ProfileTypingOptions& options)
        : P_(P), normals_(normals), seg_(seg), near_(near), grid_(grid), spacing_(spacing),
          options_(options), radii_(static_cast<int>(options.maxRadius / radiusStep) + 1)
    {
    }

    /// The fit at `centre`, a vertex of a line running along the unit `direction` there.
    Station fit(const Eigen::Vector3d& centre, const Eigen::Vector3d& direction) const;

private:
    const PointMatrix& P_;
    const NormalMatrix& normals_;
    const FirstOrderSegmentation& seg_;
    const NearbyPoints& near_;
    const clustergraph::NodeGrid& grid_;
    double spacing_;
    const ProfileTypingOptions& options_;
    int radii_;
};

Station StationFitter::fit(const Eigen::Vector3d& centre, const Eigen::Vector3d& direction) const
{
    Station station;
    std::vector<int> ball;
    grid_.forEachWithin(centre, options_.reach * spacing_,
                        [&](int i) { ball.push_back(near_.index[i]); });
    std::sort(ball.begin(), ball.end());
    // The faces: the large clusters' points away from the line (nearer, the segmentation may
    // give a face the start of a blend, which would tilt its plane towards it), each cluster
    // split in two by its normals where noise let the growing run round a blend.
    const double clear2 = std::pow(options_.faceClearance * spacing_, 2);
    std::map<int, std::vector<int>> byCluster;
    for (int i : ball) {
        const Eigen::Vector3d x = P_.row(i).transpose() - centre;
        if (!seg_.smallCluster[seg_.cluster[i]] &&
            (x - x.dot(direction) * direction).squaredNorm() >= clear2) {
            byCluster[seg_.cluster[i]].push_back(i);
        }
    }
    const double minSine = std::sin(options_.minTurn * pi / 180.0);
    std::vector<std::vector<int>> faces;
    for (auto& [c, members] : byCluster) {
        for (std::vector<int>& part : splitNormals(normals_, members, minSine)) {
            if (static_cast<int>(part.size()) >= options_.minFacePoints) {
                faces.push_back(std::move(part));
            }
        }
    }
    // By decreasing size, ties to the lower first point: the largest face, and the largest
    // after it that turns from it by minTurn, each a face whose plane passes within
    // maxFaceOffset of the vertex (the line lies on both of its faces; a plane farther off is
    // the other sheet of a thin wall or a face beyond a step).
    std::sort(faces.begin(), faces.end(), [](const auto& u, const auto& v) {
        return u.size() != v.size() ? u.size() > v.size() : u.front() < v.front();
    });
    int face[2] = {-1, -1};
    Plane plane[2];
    Eigen::Vector3d centroid[2];
    for (size_t f = 0; f < faces.size(); ++f) {
        std::vector<Eigen::Vector3d> points;
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (int i : faces[f]) {
            points.push_back(P_.row(i).transpose());
            mean += points.back();
        }
        const Plane p = fitPlane(points, options_.minFacePoints);
        if (std::abs(p.normal.dot(centre) - p.offset) > options_.maxFaceOffset * spacing_) {
            continue;
        }
        if (face[0] < 0) {
            face[0] = static_cast<int>(f);
            plane[0] = p;
            centroid[0] = mean / static_cast<double>(points.size());
        } else if (plane[0].normal.cross(p.normal).norm() >= minSine) {
            face[1] = static_cast<int>(f);
            plane[1] = p;
            centroid[1] = mean / static_cast<double>(points.size());
            break;
        }
    }
    station.faced = face[0] >= 0;
    if (face[1] < 0) {
        return station;
    }
    const Eigen::Vector3d cross = plane[0].normal.cross(plane[1].normal);
    const Eigen::Vector3d along = cross.normalized();
    station.apex = closestOnIntersection(plane[0], plane[1], centre);
    station.apexDistance = (station.apex - centre).norm() / spacing_;
    for (int f = 0; f < 2; ++f) {
        Eigen::Vector3d s = along.cross(plane[f].normal).normalized();
        if (s.dot(centroid[f] - station.apex) < 0.0) {
            s = -s;
        }
        station.side[f] = s;
    }
    station.opening = std::acos(std::clamp(station.side[0].dot(station.side[1]), -1.0, 1.0));
    if (!(station.opening > 2.0 * pi / 180.0 && station.opening < pi - 1e-6)) {
        return station;
    }
    // The profile: the two faces' points and the candidates between them, near the plane
    // across the line, in the frame of the first side.
    const Eigen::Vector3d e1 = station.side[0];
    const Eigen::Vector3d e2 = (station.side[1] - station.side[1].dot(e1) * e1).normalized();
    std::vector<Eigen::Vector2d> profile;
    for (int i : ball) {
        const int c = seg_.cluster[i];
        if (!(c == seg_.cluster[faces[face[0]].front()] ||
              c == seg_.cluster[faces[face[1]].front()] || seg_.smallCluster[c])) {
            continue;
        }
        const Eigen::Vector3d x = P_.row(i).transpose() - station.apex;
        if (std::abs(x.dot(along)) <= options_.slab * spacing_) {
            profile.emplace_back(x.dot(e1) / spacing_, x.dot(e2) / spacing_);
        }
    }
    const ProfileModel model(station.opening);
    const double limit2 = options_.residualLimit * options_.residualLimit;
    station.cost.assign(static_cast<size_t>(radii_), 0.0f);
    for (int j = 0; j < radii_; ++j) {
        double sum = 0.0;
        for (const Eigen::Vector2d& q : profile) {
            const double d = model.distance(q, j * radiusStep);
            sum += std::min(d * d, limit2);
        }
        station.cost[j] = static_cast<float>(sum);
    }
    station.valid = !profile.empty();
    station.profile = std::move(profile);
    return station;
}

double median(std::vector<double> values)
{
    if (values.empty()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid),
                     values.end());
    return values[mid];
}

/// The radius index of least summed cost over the stations `which` (valid ones), at most
/// `last`; `summed` receives the sums.
int bestRadius(const std::vector<Station>& stations, const std::vector<int>& which, int last,
               std::vector<double>* summed = nullptr)
{
    std::vector<double> sum(static_cast<size_t>(last + 1), 0.0);
    for (int s : which) {
        for (int j = 0; j <= last; ++j) {
            sum[j] += stations[s].cost[j];
        }
    }
    const int best = static_cast<int>(std::min_element(sum.begin(), sum.end()) - sum.begin());
    if (summed != nullptr) {
        *summed = std::move(sum);
    }
    return best;
}

/// The blend of radius index `best`'s mean squared residual per point (each term capped at
/// residualLimit^2) over the profile points of the stations `which` that lie within the tangent
/// length plus `window` (spacings) of their apex: near the arc, where the blend and the crease
/// differ. NaN when no point lies there.
double residualNearArc(const std::vector<Station>& stations, const std::vector<int>& which,
                       int best, double window, double residualLimit)
{
    const double r = best * radiusStep;
    const double limit2 = residualLimit * residualLimit;
    double sum = 0.0;
    int count = 0;
    for (int s : which) {
        const ProfileModel model(stations[s].opening);
        const double reach = model.tangentLength(r) + window;
        for (const Eigen::Vector2d& q : stations[s].profile) {
            if (q.norm() <= reach) {
                const double d = model.distance(q, r);
                sum += std::min(d * d, limit2);
                ++count;
            }
        }
    }
    return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

/// Side directions that follow the line: at every valid station after the first, the sides are
/// swapped when that matches the previous valid station better.
void alignSides(std::vector<Station>& stations)
{
    const Station* previous = nullptr;
    for (Station& s : stations) {
        if (!s.valid) {
            continue;
        }
        if (previous != nullptr) {
            const double keep = s.side[0].dot(previous->side[0]) + s.side[1].dot(previous->side[1]);
            const double swap = s.side[0].dot(previous->side[1]) + s.side[1].dot(previous->side[0]);
            if (swap > keep) {
                std::swap(s.side[0], s.side[1]);
                s.swapped = true;
            }
        }
        previous = &s;
    }
}

/// The best flat cut across the corner over the stations `which`: its summed squared residual
/// and its setbacks (spacings) along side[0] and side[1].
struct FlatCut
{
    double cost = 0.0;
    double setback[2] = {0.0, 0.0};
};

/// The least summed residual of a flat cut (a chamfer, or a third face between the two): cuts
/// set back equally on both sides, radiusStep apart up to radius index `last`, and cuts of
/// setbacks setbackStep apart on each side independently.
FlatCut bestFlatCut(const std::vector<Station>& stations, const std::vector<int>& which, int last,
                    const ProfileTypingOptions& options)
{
    const double limit2 = options.residualLimit * options.residualLimit;
    const int even = last + 1;
    const int cells = even + setbacks * setbacks;
    const int count = static_cast<int>(which.size());
    std::vector<std::vector<double>> perStation(static_cast<size_t>(count));
#pragma omp parallel for schedule(dynamic, 8) num_threads(threadCount(options.threads))
    for (int w = 0; w < count; ++w) {
        const Station& st = stations[which[w]];
        const ProfileModel model(st.opening);
        std::vector<double>& cost = perStation[w];
        cost.assign(static_cast<size_t>(cells), 0.0);
        auto sum = [&](double s1, double s2) {
            double total = 0.0;
            for (const Eigen::Vector2d& q : st.profile) {
                const double d = model.chamferDistance(q, s1, s2);
                total += std::min(d * d, limit2);
            }
            return total;
        };
        for (int j = 0; j < even; ++j) {
            cost[j] = sum(j * radiusStep, j * radiusStep);
        }
        for (int a = 0; a < setbacks; ++a) {
            for (int b = 0; b < setbacks; ++b) {
                // In the line's order of sides: a swapped station's first side is its second.
                const int cell = st.swapped ? b * setbacks + a : a * setbacks + b;
                cost[even + cell] = sum(a * setbackStep, b * setbackStep);
            }
        }
    }
    std::vector<double> total(static_cast<size_t>(cells), 0.0);
    for (const std::vector<double>& cost : perStation) {
        for (int c = 0; c < cells; ++c) {
            total[c] += cost[c];
        }
    }
    const int best = static_cast<int>(std::min_element(total.begin(), total.end()) - total.begin());
    FlatCut cut;
    cut.cost = total[best];
    if (best < even) {
        cut.setback[0] = cut.setback[1] = best * radiusStep;
    } else {
        cut.setback[0] = ((best - even) / setbacks) * setbackStep;
        cut.setback[1] = ((best - even) % setbacks) * setbackStep;
    }
    return cut;
}

/// The unit direction of a line at vertex i: from the vertex before to the one after (the
/// neighbouring vertex at an open end).
Eigen::Vector3d lineDirection(const Polyline& line, Eigen::Index i)
{
    const Eigen::Index m = line.points.rows();
    Eigen::Index before = i - 1;
    Eigen::Index after = i + 1;
    if (line.closed) {
        before = (before + m) % m;
        after = after % m;
    } else {
        before = std::max<Eigen::Index>(before, 0);
        after = std::min(after, m - 1);
    }
    const Eigen::Vector3d d = (line.points.row(after) - line.points.row(before)).transpose();
    return d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
}

/// Arc length of every vertex from the line's start.
std::vector<double> arcLengths(const PointMatrix& points)
{
    std::vector<double> arc(static_cast<size_t>(points.rows()), 0.0);
    for (Eigen::Index i = 1; i < points.rows(); ++i) {
        arc[i] = arc[i - 1] + (points.row(i) - points.row(i - 1)).norm();
    }
    return arc;
}

/// The two borders of a blend line: at every vertex the tangent points of the radius fitted
/// over the stations within the window, the vertices near an open end left out (there the
/// third face's points enter the fit) so that the borders run straight to the line's ends.
std::vector<Polyline> blendBorders(const Polyline& line, const std::vector<Station>& stations,
                                   const LineProfile& profile, int last, double spacing,
                                   const ProfileTypingOptions& options)
{
    const Eigen::Index m = line.points.rows();
    const std::vector<double> arc = arcLengths(line.points);
    const double total =
        arc.back() + (line.closed ? (line.points.row(m - 1) - line.points.row(0)).norm() : 0.0);
    const double window = options.radiusWindow * spacing;
    const double tangent = profile.radius / std::tan(profile.angle * pi / 360.0);
    const double endReach = tangent + spacing;
    std::vector<Eigen::Vector3d> offset[2];
    std::vector<char> have(static_cast<size_t>(m), 0);
    offset[0].assign(static_cast<size_t>(m), Eigen::Vector3d::Zero());
    offset[1].assign(static_cast<size_t>(m), Eigen::Vector3d::Zero());
    for (Eigen::Index i = 0; i < m; ++i) {
        const Station& s = stations[i];
        if (!s.valid) {
            continue;
        }
        // The valid stations within the window along the line, walking out both ways.
        std::vector<int> which = {static_cast<int>(i)};
        for (int direction : {-1, 1}) {
            for (Eigen::Index step = 1; step < m; ++step) {
                Eigen::Index j = i + direction * step;
                if (line.closed) {
                    j = (j + m) % m;
                } else if (j < 0 || j >= m) {
                    break;
                }
                double gap = std::abs(arc[j] - arc[i]);
                if (line.closed) {
                    gap = std::min(gap, total - gap);
                }
                if (gap > window || (line.closed && 2 * step >= m)) {
                    break;
                }
                if (stations[j].valid) {
                    which.push_back(static_cast<int>(j));
                }
            }
        }
        const double r = bestRadius(stations, which, last) * radiusStep * spacing;
        const double t = r / std::tan(s.opening / 2.0);
        const Eigen::Vector3d vertex = line.points.row(i).transpose();
        offset[0][i] = s.apex + t * s.side[0] - vertex;
        offset[1][i] = s.apex + t * s.side[1] - vertex;
        have[i] = 1;
    }
    int kept = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
        kept += have[i] && (line.closed || (arc[i] >= endReach && total - arc[i] >= endReach));
    }
    // Too short a blend to have borders of its own, beside its ends: it stays a sharp line.
    if (kept < (line.closed ? 3 : 2)) {
        return {};
    }
    std::vector<Polyline> borders(2);
    for (int b = 0; b < 2; ++b) {
        std::vector<Eigen::Vector3d> points;
        if (!line.closed) {
            points.push_back(line.points.row(0).transpose());
        }
        for (Eigen::Index i = 0; i < m; ++i) {
            if (!have[i] || (!line.closed && (arc[i] < endReach || total - arc[i] < endReach))) {
                continue;
            }
            points.push_back(line.points.row(i).transpose() + offset[b][i]);
        }
        if (!line.closed) {
            points.push_back(line.points.row(m - 1).transpose());
        }
        PointMatrix matrix(static_cast<Eigen::Index>(points.size()), 3);
        for (size_t i = 0; i < points.size(); ++i) {
            matrix.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
        }
        Polyline border = line;
        border.label = blendBorderLabel;
        border.points =
            resamplePolyline(smoothPolyline(matrix, line.closed, spacing), line.closed, spacing);
        borders[b] = std::move(border);
    }
    return borders;
}

/// The sharp lines to drop: those whose vertices see a face at fewer than `minShare` of them
/// (`faced`: per line of `network`, its vertices that do), then, again and again, the open
/// sharp lines shorter than `spur` with an end on a junction that a dropped line touches and
/// no other kept line does.
std::vector<char> linesWithoutFaces(const LineNetwork& network, const std::vector<int>& faced,
                                    double minShare, double spur)
{
    const size_t n = network.lines.size();
    std::vector<char> dropped(n, 0);
    // Open sharp lines short enough to go with a dropped line they hang on.
    std::vector<char> spurLike(n, 0);
    for (size_t l = 0; l < n; ++l) {
        const Polyline& line = network.lines[l];
        const bool sharp = line.label == sharpLineLabel;
        dropped[l] = sharp && faced[l] < minShare * static_cast<double>(line.points.rows());
        spurLike[l] = sharp && !line.closed && line.points.rows() >= 2 &&
                      arcLengths(line.points).back() < spur;
    }
    // Per junction: the lines that end on it (a line with both ends on it twice).
    std::vector<std::vector<size_t>> touching(static_cast<size_t>(network.junctions.rows()));
    for (size_t l = 0; l < n; ++l) {
        for (int j : {network.lines[l].startJunction, network.lines[l].endJunction}) {
            if (j >= 0 && j < static_cast<int>(touching.size())) {
                touching[static_cast<size_t>(j)].push_back(l);
            }
        }
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t l = 0; l < n; ++l) {
            const Polyline& line = network.lines[l];
            if (dropped[l] || !spurLike[l]) {
                continue;
            }
            for (int j : {line.startJunction, line.endJunction}) {
                if (j < 0 || j >= static_cast<int>(touching.size())) {
                    continue;
                }
                bool onDropped = false;
                bool onKept = false;
                for (size_t o : touching[static_cast<size_t>(j)]) {
                    if (o != l) {
                        (dropped[o] ? onDropped : onKept) = true;
                    }
                }
                if (onDropped && !onKept) {
                    dropped[l] = 1;
                    changed = true;
                    break;
                }
            }
        }
    }
    return dropped;
}

} // namespace

ProfileTyping typeByProfile(const PointMatrix& P, const NormalMatrix& normals,
                            const FirstOrderSegmentation& seg, const std::vector<char>& boundary,
                            const LineNetwork& network, double spacing,
                            const ProfileTypingOptions& options)
{
    ProfileTyping result;
    result.network.junctions = network.junctions;
    const NearbyPoints near = pointsNearLines(P, boundary, network, options.reach * spacing);
    const clustergraph::NodeGrid grid(near.centres, options.reach * spacing);
    const StationFitter fitter(P, normals, seg, near, grid, spacing, options);

    // Every vertex of every sharp line is a station.
    std::vector<std::pair<int, int>> where;
    for (size_t l = 0; l < network.lines.size(); ++l) {
        if (network.lines[l].label == sharpLineLabel) {
            for (Eigen::Index i = 0; i < network.lines[l].points.rows(); ++i) {
                where.emplace_back(static_cast<int>(l), static_cast<int>(i));
            }
        }
    }
    std::vector<Station> all(where.size());
    const int count = static_cast<int>(where.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threadCount(options.threads))
    for (int s = 0; s < count; ++s) {
        const Polyline& line = network.lines[where[s].first];
        all[s] = fitter.fit(line.points.row(where[s].second).transpose(),
                            lineDirection(line, where[s].second));
    }

    // Sharp lines over a surface with no face in reach.
    std::vector<char> dropped(network.lines.size(), 0);
    if (options.minFaceShare > 0.0) {
        std::vector<int> faced(network.lines.size(), 0);
        for (size_t s = 0; s < where.size(); ++s) {
            faced[where[s].first] += all[s].faced ? 1 : 0;
        }
        dropped = linesWithoutFaces(network, faced, options.minFaceShare,
                                    options.maxSpurLength * spacing);
    }

    size_t next = 0;
    for (size_t l = 0; l < network.lines.size(); ++l) {
        const Polyline& line = network.lines[l];
        LineProfile profile;
        int last = 0;
        if (dropped[l]) {
            next += line.label == sharpLineLabel ? static_cast<size_t>(line.points.rows()) : 0;
            continue;
        }
        if (line.label != sharpLineLabel) {
            result.network.lines.push_back(line);
            result.profiles.push_back(profile);
            continue;
        }
        const size_t m = static_cast<size_t>(line.points.rows());
        std::vector<Station> stations(std::make_move_iterator(all.begin() + next),
                                      std::make_move_iterator(all.begin() + next + m));
        next += m;
        alignSides(stations);
        // The line's profile from its stations away from open ends: there a third face (at a
        // corner) or the rim enters the fit.
        const std::vector<double> arc = arcLengths(line.points);
        const double clear =
            line.closed ? 0.0 : std::min(options.reach * spacing, 0.25 * arc.back());
        std::vector<int> valid;
        std::vector<double> openings;
        std::vector<double> apexDistances;
        for (size_t i = 0; i < m; ++i) {
            if (stations[i].valid && arc[i] >= clear && arc.back() - arc[i] >= clear) {
                valid.push_back(static_cast<int>(i));
                openings.push_back(stations[i].opening);
                apexDistances.push_back(stations[i].apexDistance);
            }
        }
        profile.stations = static_cast<int>(valid.size());
        if (!valid.empty()) {
            const double opening = median(openings);
            profile.angle = opening * 180.0 / pi;
            // Radii whose tangent points stay a spacing and a half inside the reach of the
            // line's vertices: a tangent point lies r / tan(opening / 2) from the apex, and
            // the vertices lie about the median apex distance from it towards the faces (at
            // the middle of a blend between faces at an acute angle, the apex is far out).
            const int radii = static_cast<int>(stations[valid[0]].cost.size());
            const double largest =
                (options.reach - 1.5 + median(apexDistances)) * std::tan(opening / 2.0);
            last = std::clamp(static_cast<int>(largest / radiusStep), 0, radii - 1);
            std::vector<double> summed;
            const int best = bestRadius(stations, valid, last, &summed);
            profile.radius = best * radiusStep * spacing;
            profile.gain = summed[0] > 0.0 ? (summed[0] - summed[best]) / summed[0] : 0.0;
            int points = 0;
            for (int v : valid) {
                points += static_cast<int>(stations[v].profile.size());
            }
            // The unit: the blend's mean squared residual per point, over the whole profile or
            // near the arc when smaller (faces that are not planes leave a residual far out).
            double unit = summed[best] / points;
            if (best > 0 && options.significanceWindow > 0.0) {
                const double nearArc = residualNearArc(stations, valid, best,
                                                       options.significanceWindow,
                                                       options.residualLimit);
                if (nearArc > 0.0 && nearArc < unit) {
                    unit = nearArc;
                }
            }
            profile.significance = unit > 0.0 ? (summed[0] - summed[best]) / unit : 0.0;
            // A round wide and significant enough is weighed against the best flat cut.
            const bool significant = profile.radius >= options.minNarrowRadius * spacing &&
                                     profile.significance >= options.minSignificance;
            if (significant) {
                const FlatCut cut = bestFlatCut(stations, valid, last, options);
                profile.chamferGain = summed[0] > 0.0 ? (summed[0] - cut.cost) / summed[0] : 0.0;
                profile.setback[0] = cut.setback[0] * spacing;
                profile.setback[1] = cut.setback[1] * spacing;
            }
            const bool round = valid.size() >= 3 && significant &&
                               profile.gain >= options.minShareOfCut * profile.chamferGain;
            profile.blend = options.splitBlends && round;
            profile.narrow = profile.blend && profile.radius < options.minBlendRadius * spacing;
        }
        if (profile.narrow) {
            // Too narrow for two borders: one smooth line where the sharp line ran.
            Polyline narrow = line;
            narrow.label = blendBorderLabel;
            result.network.lines.push_back(std::move(narrow));
            result.profiles.push_back(profile);
            continue;
        }
        if (!profile.blend) {
            result.network.lines.push_back(line);
            result.profiles.push_back(profile);
            continue;
        }
        std::vector<Polyline> borders =
            blendBorders(line, stations, profile, last, spacing, options);
        if (borders.empty()) {
            profile.blend = false;
            result.network.lines.push_back(line);
            result.profiles.push_back(profile);
            continue;
        }
        for (Polyline& border : borders) {
            result.network.lines.push_back(std::move(border));
            result.profiles.push_back(profile);
        }
    }
    return result;
}

} // namespace featurelines
