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

#include "ExtractionFeature.h"
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
    // Wires on a dense cloud: thin lines vanish among the points.
    LineWidth.setValue(3.0f);
    PointSize.setValue(3.0f);
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
}

void ViewProviderExtraction::onChanged(const App::Property* prop)
{
    PartGui::ViewProviderPart::onChanged(prop);
    // A hidden object's view is rebuilt when it is shown again, with one colour.
    if (prop == &SharpColor || prop == &SmoothColor || prop == &BoundaryColor ||
        (prop == &Visibility && Visibility.getValue())) {
        colourByType();
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
    Gui::TaskView::TaskDialog* dialog = Gui::Control().activeDialog();
    if (auto* own = qobject_cast<TaskExtraction*>(dialog)) {
        if (own->getObject() == getObject()) {
            Gui::Control().showDialog(dialog);
            return true;
        }
    }
    if (dialog) {
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("A task is open"),
                             QObject::tr("Close the open task panel first (OK or Cancel), then "
                                         "edit the feature lines."));
        return false;
    }
    Gui::Selection().clearSelection();
    Gui::Control().showDialog(new TaskExtraction(this));
    return true;
}

void ViewProviderExtraction::unsetEdit(int ModNum)
{
    // ViewProviderDragger::unsetEdit closes the task dialog (deferred when it is the dialog's
    // own accept or reject that resets the edit).
    PartGui::ViewProviderPart::unsetEdit(ModNum);
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
