// SPDX-License-Identifier: LGPL-2.1-or-later
// The task panel of a FeatureLines::PatchSurfaces, the step "Fit surfaces" after the lines are
// done (TaskExtraction's button, the command Fit surfaces, or a double click): what the fit
// made (faces by kind, a solid or not, the sewing tolerance), per patch its surface and its
// points' RMS and largest deviation, the patches left out and why, and the deviation colour
// map's switch and range (ViewProviderPatchSurfaces). Smallest patch changes MinPoints and
// refits. Every change is a macro line inside the panel's one transaction: OK commits it,
// Cancel aborts it.
#pragma once

#include <App/DocumentObserver.h>
#include <Gui/TaskView/TaskDialog.h>

#include <string>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace FeatureLinesGui {

class ViewProviderPatchSurfaces;

class TaskPatchSurfaces : public Gui::TaskView::TaskDialog
{
    Q_OBJECT

public:
    explicit TaskPatchSurfaces(ViewProviderPatchSurfaces* view);

    /// The edited object; nullptr once it is deleted.
    App::DocumentObject* getObject() const;

    bool accept() override;
    bool reject() override;
    bool isAllowedAlterDocument() const override { return false; }
    QDialogButtonBox::StandardButtons getStandardButtons() const override
    {
        return QDialogButtonBox::Ok | QDialogButtonBox::Cancel;
    }

private:
    void refresh();
    ViewProviderPatchSurfaces* view() const;
    bool runLine(const std::string& command, bool gui = false);
    std::string objectCommand(bool gui) const;

    App::DocumentObjectT object;
    std::string documentName;
    QLabel* summary = nullptr;
    QTableWidget* table = nullptr;
    QLabel* problems = nullptr;
    QCheckBox* colourMap = nullptr;
    QDoubleSpinBox* range = nullptr;
    QLabel* rangeNote = nullptr;
    QSpinBox* minPoints = nullptr;
};

} // namespace FeatureLinesGui
