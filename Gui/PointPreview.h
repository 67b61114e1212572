// SPDX-License-Identifier: LGPL-2.1-or-later
// Coloured points over a document's 3D views, for previewing a labelling or a segmentation
// before anything is added to the document.
#pragma once

#include <Base/Vector3D.h>
#include <memory>
#include <vector>

namespace App {
class DocumentObject;
}
namespace Gui {
class Document;
}

namespace FeatureLinesGui {

/// Coloured points drawn over a document's 3D views (its own SoSeparator added to the views'
/// scene graphs, not a document object: nothing in the document changes), hiding the source
/// cloud's own view provider while shown and restoring its visibility when removed/destroyed.
///
/// The source is hidden in the 3D views only (its view provider's display switch, as
/// ViewObject.isVisible() reports it); its Visibility property stays as it was, so the tree,
/// the document's modified flag and the undo stack are untouched, and what remove() restores
/// is whatever Visibility says then (a user who hid the cloud meanwhile keeps it hidden).
/// The points are unpickable: clicks and preselection go to the objects underneath.
/// 3D views opened after show() get the points at the next show(). A source or document
/// deleted meanwhile is noticed (weak pointers): remove() then only forgets the points.
class PointPreview
{
public:
    /// `source` may be null: nothing is hidden then.
    PointPreview(Gui::Document* document, App::DocumentObject* source);
    ~PointPreview(); // calls remove()
    PointPreview(const PointPreview&) = delete;
    PointPreview& operator=(const PointPreview&) = delete;

    /// points in world coordinates, one colour per point (RGB 0..1), point size in pixels.
    /// Replaces what an earlier call showed. Throws std::invalid_argument when the counts
    /// differ or the point size is not a positive number of pixels.
    void show(const std::vector<Base::Vector3f>& points, const std::vector<Base::Vector3f>& colours,
              float pointSize = 3.f);
    /// Takes the points out of the views and shows the source again. Safe to call twice.
    void remove();
    bool isShown() const;

    /// Fig. 7 a colours: low, inner, border, noisy (and "outside every region" grey).
    static Base::Vector3f labelColour(int label); // 0 low, 1 inner, 2 border, 3 noisy, <0 none
    /// A distinct colour per patch number (golden-angle hues); <0 grey.
    static Base::Vector3f patchColour(int patch);

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace FeatureLinesGui
