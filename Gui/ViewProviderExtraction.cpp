// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "ViewProviderExtraction.h"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>

#include <Mod/Part/Gui/SoBrepPointSet.h>

#include <Base/Tools.h>
#include <Gui/BitmapFactory.h>
#include <Gui/Control.h>
#include <Gui/MainWindow.h>
#include <Gui/Selection.h>

#include <QAction>
#include <QMenu>
#include <QMessageBox>

#include <Gui/Application.h>
#include <Gui/Document.h>
#include <Mod/Points/App/PointsFeature.h>

#include <cmath>

#include "ExtractionFeature.h"
#include "ObjectPanel.h"
#include "PointPreview.h"
#include "TaskExtraction.h"

using namespace FeatureLinesGui;

PROPERTY_SOURCE(FeatureLinesGui::ViewProviderExtraction, PartGui::ViewProviderPart)

namespace {

int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum kind)
{
    if (shape.IsNull()) {
        return 0;
    }
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, kind, map);
    return map.Extent();
}

/// Per sub-shape of Shape (edges or vertices, in TopExp order: the sharp wires' first), its
/// type's colour; empty when the counts do not add up.
std::vector<App::Color> coloursOf(const FeatureLines::Extraction& e, TopAbs_ShapeEnum kind,
                                  const App::Color& sharp, const App::Color& smooth,
                                  const App::Color& boundary)
{
    const int nSharp = countOf(e.SharpWires.getValue(), kind);
    const int nSmooth = countOf(e.SmoothWires.getValue(), kind);
    const int nBoundary = countOf(e.BoundaryWires.getValue(), kind);
    const int all = countOf(e.Shape.getValue(), kind);
    if (all == 0 || nSharp + nSmooth + nBoundary != all) {
        return {};
    }
    std::vector<App::Color> colours;
    colours.reserve(static_cast<size_t>(all));
    colours.insert(colours.end(), static_cast<size_t>(nSharp), sharp);
    colours.insert(colours.end(), static_cast<size_t>(nSmooth), smooth);
    colours.insert(colours.end(), static_cast<size_t>(nBoundary), boundary);
    return colours;
}

/// Sets a colour list property, or re-applies it when it holds these colours already: PartGui
/// rebuilds the Coin nodes of a hidden object when it is shown (a document opened with the
/// lines hidden, say) without applying the lists again, and the lines would show in LineColor.
/// Re-applying the same values must not mark the document modified.
void applyColours(App::PropertyColorList& property, const std::vector<App::Color>& colours)
{
    if (colours != property.getValues()) {
        property.setValues(colours);
        return;
    }
    Base::ObjectStatusLocker<App::Property::Status, App::Property> guard(App::Property::NoModify,
                                                                         &property);
    property.touch();
}

const char* colourPointsModes[] = {"Nothing", "Region", "Patch", "Label", "Curvature", nullptr};

/// Blue (flat) to green to red (curved) over the 2nd..98th percentile of the finite values;
/// grey for NaN (points off every region).
std::vector<Base::Vector3f> curvatureColours(const std::vector<double>& values)
{
    std::vector<double> finite;
    for (double v : values) {
        if (std::isfinite(v)) {
            finite.push_back(v);
        }
    }
    std::sort(finite.begin(), finite.end());
    const double lo = finite.empty() ? 0.0 : finite[finite.size() / 50];
    const double hi = finite.empty() ? 1.0 : finite[finite.size() - 1 - finite.size() / 50];
    std::vector<Base::Vector3f> colours;
    colours.reserve(values.size());
    for (double v : values) {
        if (!std::isfinite(v)) {
            colours.emplace_back(0.6f, 0.6f, 0.6f);
            continue;
        }
        const float t = hi > lo ? float(std::clamp((v - lo) / (hi - lo), 0.0, 1.0)) : 0.f;
        colours.emplace_back(t, 1.f - std::abs(2.f * t - 1.f), 1.f - t);
    }
    return colours;
}

/// Per point of the cloud its colour by `mode` (ColourPoints), from the extraction's per-point
/// outputs; empty when they do not match the cloud (not computed yet).
std::vector<Base::Vector3f> pointColours(const FeatureLines::Extraction& e, int mode, size_t count)
{
    std::vector<Base::Vector3f> colours;
    if (mode == 4) {
        const std::vector<double>& h = e.PointCurvature.getValues();
        return h.size() == count ? curvatureColours(h) : colours;
    }
    const std::vector<long>& values = mode == 1   ? e.PointRegion.getValues()
                                      : mode == 2 ? e.PointPatch.getValues()
                                                  : e.PointLabel.getValues();
    if (values.size() != count) {
        return colours;
    }
    colours.reserve(count);
    for (long v : values) {
        colours.push_back(mode == 3 ? PointPreview::labelColour(int(v))
                                    : PointPreview::patchColour(int(v)));
    }
    return colours;
}

} // namespace

ViewProviderExtraction::ViewProviderExtraction()
{
    // Red sharp edges, orange fillet borders, blue boundary: apart from each other and from the
    // preview's label colours (blue, green, black, red points).
    ADD_PROPERTY_TYPE(SharpColor, (App::Color(0.85f, 0.10f, 0.10f)), "Feature lines",
                      App::Prop_None, "Colour of the sharp edges.");
    ADD_PROPERTY_TYPE(SmoothColor, (App::Color(1.00f, 0.55f, 0.00f)), "Feature lines",
                      App::Prop_None, "Colour of the smooth edges (fillet borders).");
    ADD_PROPERTY_TYPE(BoundaryColor, (App::Color(0.00f, 0.45f, 0.90f)), "Feature lines",
                      App::Prop_None, "Colour of the boundary of an open cloud.");
    ADD_PROPERTY_TYPE(ColourPoints, (0L), "Feature lines", App::Prop_None,
                      "Draw the source cloud coloured by the extraction: Nothing, Region, "
                      "Patch, Label (low blue, inner green, border black, noisy red) or "
                      "Curvature (blue flat to red curved).");
    ColourPoints.setEnums(colourPointsModes);
    // Wires on a dense cloud: thin lines vanish among the points.
    LineWidth.setValue(3.0f);
    PointSize.setValue(3.0f);
}

ViewProviderExtraction::~ViewProviderExtraction() = default;

void ViewProviderExtraction::colourPoints()
{
    const auto* e = dynamic_cast<const FeatureLines::Extraction*>(getObject());
    const auto* cloud = e ? dynamic_cast<const Points::Feature*>(e->Source.getValue()) : nullptr;
    const int mode = ColourPoints.getValue();
    if (mode == 0 || editing || !cloud || !e->getDocument()) {
        colouring.reset();
        return;
    }
    const Points::PointKernel& kernel = cloud->Points.getValue();
    std::vector<Base::Vector3f> points;
    points.reserve(kernel.size());
    for (auto it = kernel.begin(); it != kernel.end(); ++it) {
        points.emplace_back(float(it->x), float(it->y), float(it->z));
    }
    const std::vector<Base::Vector3f> colours = pointColours(*e, mode, points.size());
    if (colours.empty()) {
        colouring.reset(); // not computed yet: the cloud as it is
        return;
    }
    Gui::Document* document = Gui::Application::Instance->getDocument(e->getDocument());
    if (!document) {
        return;
    }
    if (!colouring) {
        colouring = std::make_unique<PointPreview>(document, e->Source.getValue());
    }
    colouring->show(points, colours);
}

void ViewProviderExtraction::updateData(const App::Property* prop)
{
    PartGui::ViewProviderPart::updateData(prop);
    const auto* e = dynamic_cast<const FeatureLines::Extraction*>(getObject());
    // Shape is set before the wires by type: the colours follow once all four are new.
    if (e && (prop == &e->Shape || prop == &e->SharpWires || prop == &e->SmoothWires ||
              prop == &e->BoundaryWires)) {
        colourByType();
    }
    if (e && ColourPoints.getValue() != 0 &&
        (prop == &e->PointRegion || prop == &e->PointPatch || prop == &e->PointLabel ||
         prop == &e->PointCurvature)) {
        colourPoints();
    }
}

void ViewProviderExtraction::onChanged(const App::Property* prop)
{
    PartGui::ViewProviderPart::onChanged(prop);
    // A hidden object's view is rebuilt when it is shown again, with one colour.
    if (prop == &SharpColor || prop == &SmoothColor || prop == &BoundaryColor ||
        (prop == &Visibility && Visibility.getValue())) {
        colourByType();
    }
    if (prop == &ColourPoints) {
        colourPoints();
    }
}

void ViewProviderExtraction::colourByType()
{
    const auto* e = dynamic_cast<const FeatureLines::Extraction*>(getObject());
    if (!e) {
        return;
    }
    const App::Color sharp = SharpColor.getValue();
    const App::Color smooth = SmoothColor.getValue();
    const App::Color boundary = BoundaryColor.getValue();
    const std::vector<App::Color> edges = coloursOf(*e, TopAbs_EDGE, sharp, smooth, boundary);
    if (!edges.empty()) {
        applyColours(LineColorArray, edges);
    }
    // The wires' vertices are drawn as points too, one every resampling step: in the colour of
    // their line they thicken it instead of dotting it. Their point set indexes its materials
    // like its coordinates, from its start index (the edges' nodes come first).
    const std::vector<App::Color> vertices = coloursOf(*e, TopAbs_VERTEX, sharp, smooth, boundary);
    if (!vertices.empty() && nodeset) {
        // Through PartGui's own property rather than its Coin material, so that the colours
        // are saved with the view and applyColours re-applies them after a rebuild.
        const auto offset = static_cast<size_t>(std::max(0, nodeset->startIndex.getValue()));
        std::vector<App::Color> colours(offset, smooth);
        colours.insert(colours.end(), vertices.begin(), vertices.end());
        applyColours(PointColorArray, colours);
    }
}

bool ViewProviderExtraction::setEdit(int ModNum)
{
    if (ModNum != ViewProvider::Default) {
        return PartGui::ViewProviderPart::setEdit(ModNum);
    }
    return showObjectPanel<TaskExtraction>(getObject(), QObject::tr("edit the feature lines"),
                                           [this] {
                                               // The panel shows its own colours of the cloud
                                               // meanwhile.
                                               editing = true;
                                               colourPoints();
                                               Gui::Control().showDialog(new TaskExtraction(this));
                                           });
}

void ViewProviderExtraction::unsetEdit(int ModNum)
{
    // ViewProviderDragger::unsetEdit closes the task dialog (deferred when it is the dialog's
    // own accept or reject that resets the edit).
    PartGui::ViewProviderPart::unsetEdit(ModNum);
    if (ModNum == ViewProvider::Default && editing) {
        editing = false;
        colourPoints();
    }
}

void ViewProviderExtraction::setupContextMenu(QMenu* menu, QObject* receiver, const char* member)
{
    QAction* edit = menu->addAction(QObject::tr("Edit feature lines"), receiver, member);
    edit->setData(QVariant(int(ViewProvider::Default)));
    PartGui::ViewProviderPart::setupContextMenu(menu, receiver, member);
}

std::vector<App::DocumentObject*> ViewProviderExtraction::claimChildren() const
{
    const auto* e = dynamic_cast<const FeatureLines::Extraction*>(getObject());
    if (e && e->Source.getValue()) {
        return {e->Source.getValue()};
    }
    return {};
}

QIcon ViewProviderExtraction::getIcon() const
{
    return Gui::BitmapFactory().pixmap("FeatureLines_Extract");
}
