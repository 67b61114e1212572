// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "PointPreview.h"

#include <App/DocumentObject.h>
#include <Gui/Document.h>
#include <Gui/DocumentObserver.h>
#include <Gui/View3DInventor.h>
#include <Gui/View3DInventorViewer.h>
#include <Gui/ViewProviderDocumentObject.h>

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace FeatureLinesGui {

struct PointPreview::Private
{
    Private(Gui::Document* doc, Gui::ViewProviderDocumentObject* view)
        : document(doc), sourceView(view)
    {
    }

    /// The scene roots of the document's 3D views that exist now.
    std::vector<SoGroup*> sceneRoots() const
    {
        std::vector<SoGroup*> roots;
        if (document.expired())
            return roots;
        for (Gui::MDIView* view : document->getMDIViews()) {
            auto* view3d = dynamic_cast<Gui::View3DInventor*>(view);
            if (!view3d || !view3d->getViewer())
                continue;
            SoNode* root = view3d->getViewer()->getSceneGraph();
            if (root && root->isOfType(SoGroup::getClassTypeId()))
                roots.push_back(static_cast<SoGroup*>(root));
        }
        return roots;
    }

    Gui::DocumentWeakPtrT document;
    /// Null once the source object is deleted (or its document closed).
    Gui::ViewProviderWeakPtrT sourceView;
    /// Our own reference keeps the nodes alive while no view holds them.
    SoSeparator* root = nullptr;
    SoDrawStyle* style = nullptr;
    SoMaterial* material = nullptr;
    SoCoordinate3* coordinates = nullptr;
    bool shown = false;
    /// The preview switched the source's display off (and must switch it on again).
    bool sourceHidden = false;
};

PointPreview::PointPreview(Gui::Document* document, App::DocumentObject* source)
{
    Gui::ViewProviderDocumentObject* view = nullptr;
    if (document && source)
        view = dynamic_cast<Gui::ViewProviderDocumentObject*>(document->getViewProvider(source));
    d = std::make_unique<Private>(document, view);

    d->root = new SoSeparator;
    d->root->ref();
    d->root->setName("FeatureLinesPointPreview");
    // Unpickable: selection and preselection keep going to the document's objects.
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    d->root->addChild(pick);
    // The colours as given, not shaded: points have no normals, and a label colour must read
    // the same from every side.
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;
    d->root->addChild(light);
    d->style = new SoDrawStyle;
    d->style->style = SoDrawStyle::POINTS;
    d->root->addChild(d->style);
    auto* binding = new SoMaterialBinding;
    binding->value = SoMaterialBinding::PER_VERTEX;
    d->root->addChild(binding);
    d->material = new SoMaterial;
    d->root->addChild(d->material);
    d->coordinates = new SoCoordinate3;
    d->root->addChild(d->coordinates);
    d->root->addChild(new SoPointSet);
}

PointPreview::~PointPreview()
{
    remove();
    d->root->unref();
}

void PointPreview::show(const std::vector<Base::Vector3f>& points,
                        const std::vector<Base::Vector3f>& colours, float pointSize)
{
    if (points.size() != colours.size())
        throw std::invalid_argument("Point preview: " + std::to_string(points.size()) +
                                    " points but " + std::to_string(colours.size()) +
                                    " colours; give one colour per point.");
    if (!std::isfinite(pointSize) || pointSize <= 0.f)
        throw std::invalid_argument("Point preview: the point size must be a positive number "
                                    "of pixels.");

    const int n = static_cast<int>(points.size());
    d->coordinates->point.setNum(n);
    SbVec3f* xyz = d->coordinates->point.startEditing();
    for (int i = 0; i < n; ++i)
        xyz[i].setValue(points[i].x, points[i].y, points[i].z);
    d->coordinates->point.finishEditing();
    d->material->diffuseColor.setNum(n);
    SbColor* rgb = d->material->diffuseColor.startEditing();
    for (int i = 0; i < n; ++i)
        rgb[i].setValue(colours[i].x, colours[i].y, colours[i].z);
    d->material->diffuseColor.finishEditing();
    d->style->pointSize = pointSize;

    // Every 3D view of the document, including one opened since the last call.
    for (SoGroup* root : d->sceneRoots()) {
        if (root->findChild(d->root) < 0)
            root->addChild(d->root);
    }

    // Hide the cloud's display only (see the class comment): the base class's hide() switches
    // the display mode off without the Visibility property that ViewProviderDocumentObject's
    // override would set (and record in an open transaction).
    Gui::ViewProviderDocumentObject* source = *d->sourceView;
    if (source && source->isShow()) {
        source->Gui::ViewProvider::hide();
        d->sourceHidden = true;
    }
    d->shown = true;
}

void PointPreview::remove()
{
    for (SoGroup* root : d->sceneRoots()) {
        const int index = root->findChild(d->root);
        if (index >= 0)
            root->removeChild(index);
    }
    Gui::ViewProviderDocumentObject* source = *d->sourceView;
    if (d->sourceHidden && source && source->Visibility.getValue() && !source->isShow())
        source->Gui::ViewProvider::show();
    d->sourceHidden = false;
    d->shown = false;
}

bool PointPreview::isShown() const
{
    return d->shown;
}

Base::Vector3f PointPreview::labelColour(int label)
{
    switch (label) {
    case 0: // low points: blue
        return Base::Vector3f(0.15f, 0.35f, 1.0f);
    case 1: // inner points: green
        return Base::Vector3f(0.1f, 0.75f, 0.15f);
    case 2: // border points: black
        return Base::Vector3f(0.0f, 0.0f, 0.0f);
    case 3: // noisy isolated high points: red
        return Base::Vector3f(0.95f, 0.1f, 0.1f);
    default: // outside every region
        return Base::Vector3f(0.6f, 0.6f, 0.6f);
    }
}

Base::Vector3f PointPreview::patchColour(int patch)
{
    if (patch < 0)
        return Base::Vector3f(0.6f, 0.6f, 0.6f);
    // Successive hues a golden angle (360 / phi^2 degrees) apart never repeat and stay far
    // from the hues of the patches numbered just before; brightness alternates in three steps
    // so that patches of close hues still differ.
    const double goldenAngle = 137.50776405003785;
    const double hue = std::fmod(patch * goldenAngle, 360.0) / 60.0;
    const double saturation = 0.75;
    const double value = 0.95 - 0.15 * (patch % 3);
    const double chroma = value * saturation;
    const double x = chroma * (1.0 - std::abs(std::fmod(hue, 2.0) - 1.0));
    const double m = value - chroma;
    double r = 0, g = 0, b = 0;
    switch (static_cast<int>(hue) % 6) {
    case 0:
        r = chroma, g = x;
        break;
    case 1:
        r = x, g = chroma;
        break;
    case 2:
        g = chroma, b = x;
        break;
    case 3:
        g = x, b = chroma;
        break;
    case 4:
        r = x, b = chroma;
        break;
    default:
        r = chroma, b = x;
        break;
    }
    return Base::Vector3f(float(r + m), float(g + m), float(b + m));
}

} // namespace FeatureLinesGui
