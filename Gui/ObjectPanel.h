// SPDX-License-Identifier: LGPL-2.1-or-later
// How the view providers' setEdit opens their object's task panel (the lines' and the
// surfaces'): one panel at a time, the open one shown again for its own object.
#pragma once

#include <Gui/Control.h>
#include <Gui/MainWindow.h>
#include <Gui/Selection.h>
#include <Gui/TaskView/TaskDialog.h>

#include <QMessageBox>
#include <QObject>
#include <QString>

namespace App {
class DocumentObject;
}

namespace FeatureLinesGui {

/// The task panel `Panel` of `object`: the one already open for it is shown again; with another
/// panel open, a warning asks to close that first ("..., then `what`.") and false; else the
/// selection is cleared and `open()` makes and shows a new one. True when the object's panel
/// shows.
template <typename Panel, typename Open>
bool showObjectPanel(const App::DocumentObject* object, const QString& what, Open open)
{
    Gui::TaskView::TaskDialog* dialog = Gui::Control().activeDialog();
    auto* own = qobject_cast<Panel*>(dialog);
    if (own && own->getObject() == object) {
        Gui::Control().showDialog(dialog);
        return true;
    }
    if (dialog) {
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("A task is open"),
                             QObject::tr("Close the open task panel first (OK or Cancel), then "
                                         "%1.")
                                 .arg(what));
        return false;
    }
    Gui::Selection().clearSelection();
    open();
    return true;
}

} // namespace FeatureLinesGui
