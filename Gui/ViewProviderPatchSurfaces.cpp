// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "ViewProviderPatchSurfaces.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoNormalBinding.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoPolygonOffset.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoSwitch.h>

#include <Base/Console.h>
#include <Base/Placement.h>
#include <Base/TimeInfo.h>
#include <Gui/BitmapFactory.h>
#include <Gui/Control.h>
#include <Gui/SoFCColorBar.h>
#include <Mod/Part/App/PartFeature.h>
#include <Mod/Part/Gui/SoBrepEdgeSet.h>
#include <Mod/Part/Gui/SoBrepFaceSet.h>
#include <Mod/Points/App/PointsFeature.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "ObjectPanel.h"
#include "TaskPatchSurfaces.h"

using namespace FeatureLinesGui;

PROPERTY_SOURCE(FeatureLinesGui::ViewProviderPatchSurfaces, PartGui::ViewProviderPartExt)

namespace {

const char* const deviationMode = "Deviation";

/// The source cloud of a PatchSurfaces object (its Source extraction's Source), or nullptr.
const Points::Feature* cloudOf(const App::DocumentObject* surfaces)
{
    auto* source = dynamic_cast<App::PropertyLink*>(surfaces->getPropertyByName("Source"));
    const App::DocumentObject* extraction = source ? source->getValue() : nullptr;
    auto* cloud = extraction ? dynamic_cast<App::PropertyLink*>(
                                   extraction->getPropertyByName("Source"))
                             : nullptr;
    return cloud ? dynamic_cast<const Points::Feature*>(cloud->getValue()) : nullptr;
}

double spacingOf(const App::DocumentObject* surfaces)
{
    auto* source = dynamic_cast<App::PropertyLink*>(surfaces->getPropertyByName("Source"));
    const App::DocumentObject* extraction = source ? source->getValue() : nullptr;
    auto* spacing = extraction ? dynamic_cast<App::PropertyFloat*>(
                                     extraction->getPropertyByName("Spacing"))
                               : nullptr;
    return spacing ? spacing->getValue() : 0.0;
}

/// Points in cells of a uniform grid: the points within `radius` of a position.
class PointGrid
{
public:
    PointGrid(std::vector<Base::Vector3d> points, double cell)
        : points(std::move(points)), cell(cell)
    {
        for (size_t i = 0; i < this->points.size(); ++i) {
            cells[key(this->points[i])].push_back(i);
        }
    }

    /// Calls f(index, distance) for every point within `radius` of x.
    template <typename F>
    void near(const Base::Vector3d& x, double radius, F f) const
    {
        const std::int64_t cx = coordinate(x.x);
        const std::int64_t cy = coordinate(x.y);
        const std::int64_t cz = coordinate(x.z);
        const auto reach = static_cast<std::int64_t>(std::ceil(radius / cell));
        for (std::int64_t i = cx - reach; i <= cx + reach; ++i) {
            for (std::int64_t j = cy - reach; j <= cy + reach; ++j) {
                for (std::int64_t k = cz - reach; k <= cz + reach; ++k) {
                    const auto found = cells.find(pack(i, j, k));
                    if (found == cells.end()) {
                        continue;
                    }
                    for (size_t p : found->second) {
                        const double d = Base::Distance(points[p], x);
                        if (d <= radius) {
                            f(p, d);
                        }
                    }
                }
            }
        }
    }

private:
    std::int64_t coordinate(double v) const
    {
        return static_cast<std::int64_t>(std::floor(v / cell));
    }
    static std::uint64_t pack(std::int64_t i, std::int64_t j, std::int64_t k)
    {
        // 21 bits per axis: cells wrap after two million spacings, which only merges buckets.
        const auto bits = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1fffff; };
        return bits(i) | bits(j) << 21 | bits(k) << 42;
    }
    std::uint64_t key(const Base::Vector3d& x) const
    {
        return pack(coordinate(x.x), coordinate(x.y), coordinate(x.z));
    }

    std::vector<Base::Vector3d> points;
    double cell;
    std::unordered_map<std::uint64_t, std::vector<size_t>> cells;
};

} // namespace

ViewProviderPatchSurfaces::ViewProviderPatchSurfaces()
{
    static const App::PropertyFloatConstraint::Constraints range = {0.0, 1e9, 0.01};
    ADD_PROPERTY_TYPE(DeviationRange, (0.0), "Deviation", App::Prop_None,
                      "The colour map's half range (mm): blue at -range, green on the face, red "
                      "at +range. 0: automatic (the 95th percentile of the deviations' sizes, "
                      "at least a twentieth of the spacing).");
    DeviationRange.setConstraints(&range);
    deviationMaterial = new SoMaterial();
    deviationMaterial->ref();
    mapCoordinates = new SoCoordinate3();
    mapCoordinates->ref();
    mapNormals = new SoNormal();
    mapNormals->ref();
    mapFaces = new SoIndexedFaceSet();
    mapFaces->ref();
    colourBar = new Gui::SoFCColorBar();
    colourBar->ref();
    colourBar->Attach(this);
    colourBar->setRange(-1.0f, 1.0f, 3);
    barSwitch = new SoSwitch();
    barSwitch->ref();
    barSwitch->addChild(colourBar);
    barSwitch->whichChild = SO_SWITCH_NONE;
    frontRoot = new SoSeparator();
    frontRoot->ref();
    frontRoot->addChild(barSwitch);
}

ViewProviderPatchSurfaces::~ViewProviderPatchSurfaces()
{
    colourBar->Detach(this);
    colourBar->unref();
    barSwitch->unref();
    frontRoot->unref();
    deviationMaterial->unref();
    mapCoordinates->unref();
    mapNormals->unref();
    mapFaces->unref();
    if (deviationRoot) {
        deviationRoot->unref();
    }
}

void ViewProviderPatchSurfaces::attach(App::DocumentObject* object)
{
    PartGui::ViewProviderPartExt::attach(object);
    // Part's edges, then (a polygon offset behind them) the colour map's own finer mesh of the
    // faces, not pickable, and Part's faces, which selection picks as in Part's modes.
    deviationRoot = new SoSeparator();
    deviationRoot->ref();
    auto* edges = new SoSeparator();
    edges->addChild(pcLineBind);
    edges->addChild(pcLineMaterial);
    edges->addChild(pcLineStyle);
    edges->addChild(lineset);
    deviationRoot->addChild(edges);
    auto* nearOffset = new SoPolygonOffset();
    deviationRoot->addChild(nearOffset);
    auto* map = new SoSeparator();
    auto* unpickable = new SoPickStyle();
    unpickable->style = SoPickStyle::UNPICKABLE;
    map->addChild(unpickable);
    map->addChild(pShapeHints);
    auto* materialBinding = new SoMaterialBinding();
    materialBinding->value = SoMaterialBinding::PER_VERTEX_INDEXED;
    map->addChild(materialBinding);
    map->addChild(deviationMaterial);
    auto* normalBinding = new SoNormalBinding();
    normalBinding->value = SoNormalBinding::PER_VERTEX_INDEXED;
    map->addChild(normalBinding);
    map->addChild(mapNormals);
    map->addChild(mapCoordinates);
    map->addChild(mapFaces);
    deviationRoot->addChild(map);
    // Part's faces, not drawn (they would fight the map's mesh in the depth buffer) but there
    // for selection and its highlight.
    auto* faces = new SoSeparator();
    auto* invisible = new SoDrawStyle();
    invisible->style = SoDrawStyle::INVISIBLE;
    faces->addChild(invisible);
    faces->addChild(pShapeHints);
    faces->addChild(pcFaceBind);
    faces->addChild(pcShapeMaterial);
    faces->addChild(norm);
    faces->addChild(normb);
    faces->addChild(faceset);
    deviationRoot->addChild(faces);
    addDisplayMaskMode(deviationRoot, deviationMode);
}

std::vector<std::string> ViewProviderPatchSurfaces::getDisplayModes() const
{
    std::vector<std::string> modes = PartGui::ViewProviderPartExt::getDisplayModes();
    modes.insert(modes.begin(), deviationMode);
    return modes;
}

const char* ViewProviderPatchSurfaces::getDefaultDisplayMode() const
{
    return deviationMode;
}

void ViewProviderPatchSurfaces::setDisplayMode(const char* mode)
{
    if (std::string(mode) == deviationMode) {
        setDisplayMaskMode(deviationMode);
    }
    PartGui::ViewProviderPartExt::setDisplayMode(mode);
    computeDeviations();
    showColourBar();
}

void ViewProviderPatchSurfaces::updateData(const App::Property* prop)
{
    PartGui::ViewProviderPartExt::updateData(prop);
    const std::string name = prop->getName() ? prop->getName() : "";
    if (name == "Shape" || name == "PointDeviations" || name == "Placement") {
        deviationsStale = true;
        computeDeviations();
    }
}

void ViewProviderPatchSurfaces::onChanged(const App::Property* prop)
{
    PartGui::ViewProviderPartExt::onChanged(prop);
    if (prop == &DeviationRange) {
        colourVertices();
    } else if (prop == &Visibility || prop == &Deviation || prop == &AngularDeflection) {
        // Part tessellates again when shown or when its accuracy changes.
        computeDeviations();
        showColourBar();
    }
}

SoSeparator* ViewProviderPatchSurfaces::getFrontRoot() const
{
    return frontRoot;
}

void ViewProviderPatchSurfaces::showColourBar()
{
    const bool shown = Visibility.getValue() && std::string(getActiveDisplayMode()) == deviationMode;
    barSwitch->whichChild = shown ? 0 : SO_SWITCH_NONE;
}

void ViewProviderPatchSurfaces::computeDeviations()
{
    const App::DocumentObject* object = getObject();
    // Only for the map on view: Part's modes do without it (setDisplayMode computes it then).
    if (!object || !Visibility.getValue() || getActiveDisplayMode() != deviationMode) {
        return;
    }
    const int vertices = coords->point.getNum();
    if (!deviationsStale && computedFor == vertices) {
        return;
    }
    deviationsStale = false;
    computedFor = vertices;
    Base::TimeInfo start;
    deviations.clear();
    automaticRange = 0.0;
    const double spacing = spacingOf(object);
    refineFaces(spacing);
    deviations.assign(static_cast<size_t>(mapCoordinates->point.getNum()),
                      std::numeric_limits<float>::quiet_NaN());
    auto* values =
        dynamic_cast<App::PropertyFloatList*>(object->getPropertyByName("PointDeviations"));
    const Points::Feature* cloud = cloudOf(object);
    if (!values || !cloud || !(spacing > 0.0)) {
        colourVertices();
        return;
    }
    const std::vector<double>& perPoint = values->getValues();
    const Points::PointKernel& kernel = cloud->Points.getValue();
    if (perPoint.size() != kernel.size()) {
        // The cloud changed since the surfaces were fitted: nothing to show until a recompute.
        colourVertices();
        return;
    }
    // The cloud's points (world) in the shape's own coordinates, where the tessellation is.
    Base::Placement placement;
    if (auto* feature = dynamic_cast<const Part::Feature*>(object)) {
        placement = feature->Placement.getValue().inverse();
    }
    std::vector<Base::Vector3d> points;
    std::vector<double> pointValues;
    std::vector<double> sizes;
    for (size_t i = 0; i < perPoint.size(); ++i) {
        if (std::isfinite(perPoint[i])) {
            Base::Vector3d p = kernel.getPoint(i);
            placement.multVec(p, p);
            points.push_back(p);
            pointValues.push_back(perPoint[i]);
            sizes.push_back(std::abs(perPoint[i]));
        }
    }
    if (!sizes.empty()) {
        const size_t k = std::min(sizes.size() - 1, sizes.size() * 95 / 100);
        std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(k),
                         sizes.end());
        automaticRange = sizes[k];
    }
    automaticRange = std::max(automaticRange, 0.05 * spacing);
    // A vertex takes the mean of the points within 1.5 spacings, weighted down with distance;
    // where there are none (a gap of the scan; along the lines, whose points belong to no
    // patch), of those within 3 spacings.
    const double radius = 1.5 * spacing;
    const PointGrid grid(std::move(points), radius);
    const SbVec3f* xyz = mapCoordinates->point.getValues(0);
    for (size_t v = 0; v < deviations.size(); ++v) {
        const Base::Vector3d x(xyz[v][0], xyz[v][1], xyz[v][2]);
        double sum = 0.0;
        double weights = 0.0;
        for (double r = radius; weights == 0.0 && r <= 2.0 * radius; r += radius) {
            grid.near(x, r, [&](size_t p, double d) {
                const double w = 1.0 - d / (1.01 * r);
                sum += w * pointValues[p];
                weights += w;
            });
        }
        if (weights > 0.0) {
            deviations[v] = static_cast<float>(sum / weights);
        }
    }
    colourVertices();
    Base::Console().Log("FeatureLines: the deviation colour map of %s: %d vertices from %d points "
                        "in %.2f s\n",
                        object->Label.getValue(), static_cast<int>(deviations.size()),
                        static_cast<int>(pointValues.size()),
                        Base::TimeInfo::diffTimeF(start, Base::TimeInfo()));
}

void ViewProviderPatchSurfaces::refineFaces(double spacing)
{
    // Part's triangles: the coordinate indices of each, ended by -1; a normal per face node.
    const int nodes = coords->point.getNum();
    const SbVec3f* xyz = coords->point.getValues(0);
    const int normals = norm->vector.getNum();
    const SbVec3f* normal = norm->vector.getValues(0);
    const int32_t* index = faceset->coordIndex.getValues(0);
    const int indices = faceset->coordIndex.getNum();
    std::vector<SbVec3f> points(xyz, xyz + nodes);
    std::vector<SbVec3f> pointNormals(static_cast<size_t>(nodes), SbVec3f(0.0f, 0.0f, 0.0f));
    for (int k = 0; k < std::min(nodes, normals); ++k) {
        pointNormals[static_cast<size_t>(k)] = normal[k];
    }
    std::vector<std::array<int32_t, 3>> triangles;
    double area = 0.0;
    for (int i = 0; i + 2 < indices; i += 4) {
        const int32_t a = index[i], b = index[i + 1], c = index[i + 2];
        if (a < 0 || b < 0 || c < 0 || a >= nodes || b >= nodes || c >= nodes) {
            continue;
        }
        triangles.push_back({a, b, c});
        area += 0.5 * ((xyz[b] - xyz[a]).cross(xyz[c] - xyz[a])).length();
    }
    // Edges longer than about a spacing are halved, each edge once for both its triangles (a
    // triangle split on one, two or all three of its edges), until none is: the mesh stays
    // without cracks. Some half a million triangles at most in all.
    const double side = std::max(spacing > 0.0 ? spacing : 1.0, std::sqrt(2.0 * area / 5.0e5));
    for (int round = 0; round < 24; ++round) {
        std::unordered_map<std::uint64_t, int32_t> middles;
        bool split = false;
        const auto middle = [&](int32_t a, int32_t b) -> int32_t {
            const SbVec3f& pa = points[static_cast<size_t>(a)];
            const SbVec3f& pb = points[static_cast<size_t>(b)];
            if (!((pb - pa).length() > side)) {
                return -1;
            }
            const std::uint64_t key = static_cast<std::uint64_t>(std::min(a, b)) << 32 |
                                      static_cast<std::uint32_t>(std::max(a, b));
            const auto found = middles.find(key);
            if (found != middles.end()) {
                return found->second;
            }
            const int32_t m = static_cast<int32_t>(points.size());
            points.push_back((pa + pb) * 0.5f);
            SbVec3f n = pointNormals[static_cast<size_t>(a)] + pointNormals[static_cast<size_t>(b)];
            if (n.length() > 0.0f) {
                n.normalize();
            }
            pointNormals.push_back(n);
            middles.emplace(key, m);
            return m;
        };
        std::vector<std::array<int32_t, 3>> next;
        next.reserve(triangles.size() * 2);
        for (const std::array<int32_t, 3>& t : triangles) {
            const int32_t m[3] = {middle(t[0], t[1]), middle(t[1], t[2]), middle(t[2], t[0])};
            const int count = (m[0] >= 0) + (m[1] >= 0) + (m[2] >= 0);
            if (count == 0) {
                next.push_back(t);
                continue;
            }
            split = true;
            if (count == 3) {
                next.push_back({t[0], m[0], m[2]});
                next.push_back({m[0], t[1], m[1]});
                next.push_back({m[2], m[1], t[2]});
                next.push_back({m[0], m[1], m[2]});
                continue;
            }
            // Turned so that the edge after the first vertex is split (one split) or the edge
            // before it is whole (two splits): (a, b, c) with a middle on a-b.
            int r = 0;
            if (count == 1) {
                while (m[r] < 0) {
                    ++r;
                }
            } else {
                while (m[(r + 2) % 3] >= 0) {
                    ++r;
                }
            }
            const int32_t a = t[static_cast<size_t>(r)];
            const int32_t b = t[static_cast<size_t>((r + 1) % 3)];
            const int32_t c = t[static_cast<size_t>((r + 2) % 3)];
            const int32_t mab = m[r];
            if (count == 1) {
                next.push_back({a, mab, c});
                next.push_back({mab, b, c});
            } else {
                const int32_t mbc = m[(r + 1) % 3];
                next.push_back({mab, b, mbc});
                next.push_back({a, mab, mbc});
                next.push_back({a, mbc, c});
            }
        }
        triangles = std::move(next);
        if (!split) {
            break;
        }
    }
    std::vector<int32_t> faces;
    faces.reserve(triangles.size() * 4);
    for (const std::array<int32_t, 3>& t : triangles) {
        faces.insert(faces.end(), {t[0], t[1], t[2], -1});
    }
    mapCoordinates->point.setValues(0, static_cast<int>(points.size()), points.data());
    mapCoordinates->point.setNum(static_cast<int>(points.size()));
    mapNormals->vector.setValues(0, static_cast<int>(pointNormals.size()), pointNormals.data());
    mapNormals->vector.setNum(static_cast<int>(pointNormals.size()));
    mapFaces->coordIndex.setValues(0, static_cast<int>(faces.size()), faces.data());
    mapFaces->coordIndex.setNum(static_cast<int>(faces.size()));
}

double ViewProviderPatchSurfaces::deviationRange() const
{
    return DeviationRange.getValue() > 0.0 ? DeviationRange.getValue() : automaticRange;
}

void ViewProviderPatchSurfaces::colourVertices()
{
    const double range = deviationRange();
    if (range > 0.0) {
        // The colour bar's observers (this) recolour on its change: not again from here.
        colourBar->Detach(this);
        colourBar->setRange(static_cast<float>(-range), static_cast<float>(range),
                            range < 0.01 ? 4 : 3);
        colourBar->Attach(this);
    }
    // A colour for every vertex Part drew, known or not: the faces index them all.
    const int n = std::max(static_cast<int>(deviations.size()), mapCoordinates->point.getNum());
    deviationMaterial->diffuseColor.setNum(std::max(n, 1));
    SbColor* colours = deviationMaterial->diffuseColor.startEditing();
    colours[0].setValue(0.6f, 0.6f, 0.6f);
    const float lo = colourBar->getMinValue();
    const float hi = colourBar->getMaxValue();
    for (int v = 0; v < n; ++v) {
        const float d = static_cast<size_t>(v) < deviations.size()
                            ? deviations[static_cast<size_t>(v)]
                            : std::numeric_limits<float>::quiet_NaN();
        if (!std::isfinite(d)) {
            colours[v].setValue(0.6f, 0.6f, 0.6f);
            continue;
        }
        const App::Color c = colourBar->getColor(std::clamp(d, lo, hi));
        colours[v].setValue(c.r, c.g, c.b);
    }
    deviationMaterial->diffuseColor.finishEditing();
}

void ViewProviderPatchSurfaces::OnChange(Base::Subject<int>&, int)
{
    colourVertices();
}

bool ViewProviderPatchSurfaces::doubleClicked()
{
    return setEdit(ViewProvider::Default);
}

bool ViewProviderPatchSurfaces::setEdit(int ModNum)
{
    if (ModNum != ViewProvider::Default) {
        return PartGui::ViewProviderPartExt::setEdit(ModNum);
    }
    return showObjectPanel<TaskPatchSurfaces>(getObject(), QObject::tr("edit the surfaces"), [this] {
        Gui::Control().showDialog(new TaskPatchSurfaces(this));
    });
}

void ViewProviderPatchSurfaces::unsetEdit(int ModNum)
{
    if (ModNum != ViewProvider::Default) {
        PartGui::ViewProviderPartExt::unsetEdit(ModNum);
        return;
    }
    Gui::Control().closeDialog();
}

QIcon ViewProviderPatchSurfaces::getIcon() const
{
    return Gui::BitmapFactory().pixmap("FeatureLines_Workbench");
}
