// SPDX-License-Identifier: LGPL-2.1-or-later
// The view of a FeatureLines::PatchSurfaces: Part's display modes and one more, "Deviation"
// (the default): the faces coloured by how far the scan lies from them, the colour of a
// vertex of a mesh of the faces about a spacing fine being the mean signed deviation
// (PointDeviations) of the cloud's points near it, blue below the face through green to red above it, with FreeCAD's
// colour bar beside the view; grey where no point of a face is near. Its double click opens
// the surfaces' task panel (TaskPatchSurfaces.h).
#pragma once

#include <App/PropertyStandard.h>
#include <Base/Observer.h>
#include <Mod/Part/Gui/ViewProviderExt.h>

#include <vector>

class SoCoordinate3;
class SoIndexedFaceSet;
class SoMaterial;
class SoNormal;
class SoSeparator;
class SoSwitch;

namespace Gui {
class SoFCColorBar;
}

namespace FeatureLinesGui {

class ViewProviderPatchSurfaces : public PartGui::ViewProviderPartExt,
                                  public Base::Observer<int>
{
    PROPERTY_HEADER_WITH_OVERRIDE(FeatureLinesGui::ViewProviderPatchSurfaces);

public:
    ViewProviderPatchSurfaces();
    ~ViewProviderPatchSurfaces() override;

    /// The colour map's half range (mm): deviations from -DeviationRange (blue) to
    /// +DeviationRange (red). 0: automatic, the 95th percentile of the deviations' sizes but
    /// at least a twentieth of the cloud's spacing.
    App::PropertyFloatConstraint DeviationRange;

    void attach(App::DocumentObject* object) override;
    void setDisplayMode(const char* mode) override;
    std::vector<std::string> getDisplayModes() const override;
    const char* getDefaultDisplayMode() const override;
    void updateData(const App::Property* prop) override;
    SoSeparator* getFrontRoot() const override;
    bool setEdit(int ModNum) override;
    void unsetEdit(int ModNum) override;
    bool doubleClicked() override;
    QIcon getIcon() const override;

    /// The colour bar's range or colours changed (Base::Observer).
    void OnChange(Base::Subject<int>& caller, int reason) override;

    /// The half range the colour map uses now (mm; DeviationRange or the automatic one).
    double deviationRange() const;
    /// Per vertex of the colour map's mesh: its deviation (mm; NaN: no point near), as
    /// last coloured. For the task panel and the tests.
    const std::vector<float>& vertexDeviations() const { return deviations; }

protected:
    void onChanged(const App::Property* prop) override;

private:
    /// The deviation at every vertex of the tessellation, from PointDeviations and the
    /// source cloud; then colourVertices().
    void computeDeviations();
    /// The vertices' colours from their deviations and the colour bar.
    void colourVertices();
    /// The colour map's mesh: Part's triangles of the faces cut into triangles of about a
    /// `spacing`'s side (a plane's few long triangles would carry its colours only at its
    /// border), their normals interpolated.
    void refineFaces(double spacing);
    void showColourBar();

    SoSeparator* deviationRoot = nullptr;
    SoMaterial* deviationMaterial = nullptr;
    SoCoordinate3* mapCoordinates = nullptr;
    SoNormal* mapNormals = nullptr;
    SoIndexedFaceSet* mapFaces = nullptr;
    SoSeparator* frontRoot = nullptr;
    SoSwitch* barSwitch = nullptr;
    Gui::SoFCColorBar* colourBar = nullptr;
    std::vector<float> deviations;
    double automaticRange = 0.0;
    /// The tessellation the deviations were computed for (its vertex count), to redo them
    /// when Part's view tessellates again.
    int computedFor = -1;
    bool deviationsStale = true;
};

} // namespace FeatureLinesGui
