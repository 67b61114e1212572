// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines_Extract: adds a FeatureLines::Extraction reading the selected point cloud and opens
// its task panel. Every step goes through doCommand, so the macro recorder writes it and one undo
// removes it; the extraction itself is the document object's recompute (parametric).
#include <FCConfig.h>

#include <App/Document.h>
#include <Gui/Application.h>
#include <Gui/Command.h>
#include <Gui/Control.h>
#include <Gui/MainWindow.h>
#include <Gui/Selection.h>
#include <Mod/Points/App/PointsFeature.h>

#include <QMessageBox>
#include <QObject>

#include <string>
#include <vector>

DEF_STD_CMD_A(CmdFeatureLinesExtract)

CmdFeatureLinesExtract::CmdFeatureLinesExtract() : Command("FeatureLines_Extract")
{
    sAppModule = "FeatureLines";
    sGroup = QT_TR_NOOP("FeatureLines");
    sMenuText = QT_TR_NOOP("Extract feature lines...");
    sToolTipText =
        QT_TR_NOOP("Extracts the closed feature lines (sharp edges, fillet borders, the\n"
                   "boundary) of the selected point cloud, choosing the curvature\n"
                   "thresholds on its histogram in the task panel.");
    sWhatsThis = "FeatureLines_Extract";
    sStatusTip = sToolTipText;
    sPixmap = "FeatureLines_Extract";
}

void CmdFeatureLinesExtract::activated(int)
{
    const std::vector<App::DocumentObject*> clouds =
        Gui::Selection().getObjectsOfType(Points::Feature::getClassTypeId());
    if (clouds.size() != 1) {
        const QString text =
            clouds.empty()
                ? QObject::tr("Select a point cloud (a Points object, e.g. from File > Import of "
                              "an .xyz, .asc, .ply or .pcd file) in the tree or the 3D view, "
                              "then run Extract feature lines again.")
                : QObject::tr("%1 point clouds are selected: select one, then run Extract "
                              "feature lines again.")
                      .arg(clouds.size());
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("Select a point cloud"), text);
        return;
    }
    App::DocumentObject* cloud = clouds.front();
    const std::string name = getUniqueObjectName("FeatureLines", cloud);
    const char* doc = cloud->getDocument()->getName();

    openCommand(QT_TRANSLATE_NOOP("Command", "Extract feature lines"));
    doCommand(Doc, "import FeatureLines");
    doCommand(Doc, "App.getDocument('%s').addObject('FeatureLines::Extraction', '%s')", doc,
              name.c_str());
    doCommand(
        Doc, "App.getDocument('%s').getObject('%s').Source = App.getDocument('%s').getObject('%s')",
        doc, name.c_str(), doc, cloud->getNameInDocument());
    // The task panel runs the analysis, proposes the thresholds and recomputes; it commits
    // this transaction on OK and aborts it (the object goes) on Cancel.
    doCommand(Gui, "Gui.getDocument('%s').setEdit('%s', 0)", doc, name.c_str());
}

bool CmdFeatureLinesExtract::isActive()
{
    return hasActiveDocument() && !Gui::Control().activeDialog();
}

void CreateFeatureLinesCommands()
{
    Gui::CommandManager& manager = Gui::Application::Instance->commandManager();
    manager.addCommand(new CmdFeatureLinesExtract());
}
