// SPDX-License-Identifier: LGPL-2.1-or-later
// The view of a FeatureLines::Extraction: its wires drawn thick, coloured by type (sharp, smooth,
// boundary), the source cloud under it in the tree, and the task panel of the interactive
// thresholding on double click (setEdit).
#pragma once

#include <App/PropertyStandard.h>
#include <Mod/Part/Gui/ViewProvider.h>

#include <memory>

namespace FeatureLinesGui {

class PointPreview;

class ViewProviderExtraction : public PartGui::ViewProviderPart
{
    PROPERTY_HEADER_WITH_OVERRIDE(FeatureLinesGui::ViewProviderExtraction);

public:
    ViewProviderExtraction();

    /// Colours of the three kinds of line. Applied per edge of Shape, which holds the sharp
    /// wires first, then the smooth, then the boundary wires (FeatureLines::Extraction).
    App::PropertyColor SharpColor;
    App::PropertyColor SmoothColor;
    App::PropertyColor BoundaryColor;
    /// The source cloud drawn coloured by the extraction's per-point outputs: Nothing (the
    /// cloud as it is), Region, Patch, Label (Fig. 7 a colours) or Curvature (blue flat to red
    /// curved). Kept with the view; the commands Colour cloud by ... set it.
    App::PropertyEnumeration ColourPoints;

    ~ViewProviderExtraction() override;

    void updateData(const App::Property* prop) override;
    bool setEdit(int ModNum) override;
    void unsetEdit(int ModNum) override;
    void setupContextMenu(QMenu* menu, QObject* receiver, const char* member) override;
    /// The source cloud, as Part's features show the shape they were made from.
    std::vector<App::DocumentObject*> claimChildren() const override;
    QIcon getIcon() const override;

protected:
    void onChanged(const App::Property* prop) override;

private:
    /// Sets LineColorArray from the edges of each type, and the vertices (drawn as points) in
    /// their line's colour; does nothing while the outputs are half updated (their counts do
    /// not add up to Shape's).
    void colourByType();
    /// Shows the cloud in the ColourPoints colours (or removes them): not while the task panel
    /// shows its own preview.
    void colourPoints();

    std::unique_ptr<PointPreview> colouring;
    bool editing = false;
};

} // namespace FeatureLinesGui
