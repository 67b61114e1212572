// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines_Extract: adds a FeatureLines::Extraction reading the selected point cloud and opens
// its task panel. Every step goes through doCommand, so the macro recorder writes it and one undo
// removes it; the extraction itself is the document object's recompute (parametric).
#include <FCConfig.h>

#include <App/Document.h>
#include <App/PropertyUnits.h>
#include <Base/Console.h>
#include <Base/Exception.h>
#include <Base/Type.h>
#include <Gui/Application.h>
#include <Gui/Command.h>
#include <Gui/Control.h>
#include <Gui/MainWindow.h>
#include <Gui/Selection.h>
#include <Gui/SelectionObject.h>
#include <Mod/Points/App/PointsFeature.h>

#include <Mod/Part/App/PartFeature.h>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <QInputDialog>
#include <QMessageBox>
#include <QObject>

#include <algorithm>
#include <cstdlib>
#include <set>

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

namespace {

/// The FeatureLines::Extraction objects selected, each once (an object with edges selected is
/// in the selection once per edge).
std::vector<App::DocumentObject*> selectedExtractions()
{
    std::vector<App::DocumentObject*> unique;
    for (App::DocumentObject* obj :
         Gui::Selection().getObjectsOfType(Base::Type::fromName("FeatureLines::Extraction"))) {
        if (std::find(unique.begin(), unique.end(), obj) == unique.end()) {
            unique.push_back(obj);
        }
    }
    return unique;
}

/// The one FeatureLines::Extraction selected, or nullptr after a message saying what to select
/// (`what`: the command's name for the message).
App::DocumentObject* selectedExtraction(const QString& what)
{
    const std::vector<App::DocumentObject*> selected = selectedExtractions();
    if (selected.size() == 1) {
        return selected.front();
    }
    QMessageBox::warning(
        Gui::getMainWindow(), QObject::tr("Select feature lines"),
        selected.empty()
            ? QObject::tr("Select a FeatureLines object (made by Extract feature lines) in the "
                          "tree, then run %1 again.")
                  .arg(what)
            : QObject::tr("%1 FeatureLines objects are selected: select one, then run %2 again.")
                  .arg(selected.size())
                  .arg(what));
    return nullptr;
}

bool extractionSelected()
{
    return selectedExtractions().size() == 1;
}

} // namespace

// ---- Patch clouds ------------------------------------------------------------------------

DEF_STD_CMD_A(CmdFeatureLinesMakePatchClouds)

CmdFeatureLinesMakePatchClouds::CmdFeatureLinesMakePatchClouds()
    : Command("FeatureLines_MakePatchClouds")
{
    sAppModule = "FeatureLines";
    sGroup = QT_TR_NOOP("FeatureLines");
    sMenuText = QT_TR_NOOP("Make patch clouds");
    sToolTipText =
        QT_TR_NOOP("One point cloud per surface patch of the selected feature lines (the points\n"
                   "between the same two curvature levels, connected), in a new group: hand\n"
                   "them to surface fitting. Patches smaller than twice NeighbourCount are left\n"
                   "out.");
    sWhatsThis = "FeatureLines_MakePatchClouds";
    sStatusTip = sToolTipText;
}

void CmdFeatureLinesMakePatchClouds::activated(int)
{
    App::DocumentObject* lines = selectedExtraction(QObject::tr("Make patch clouds"));
    if (!lines) {
        return;
    }
    const char* doc = lines->getDocument()->getName();
    openCommand(QT_TRANSLATE_NOOP("Command", "Make patch clouds"));
    try {
        doCommand(Doc, "import FeatureLines");
        doCommand(Doc, "FeatureLines.makePatchClouds(App.getDocument('%s').getObject('%s'))", doc,
                  lines->getNameInDocument());
        commitCommand();
    } catch (const Base::Exception& e) {
        abortCommand();
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("No patch clouds"),
                             QString::fromUtf8(e.what()));
    }
}

bool CmdFeatureLinesMakePatchClouds::isActive()
{
    return hasActiveDocument() && !Gui::Control().activeDialog() && extractionSelected();
}

// ---- Surfaces ------------------------------------------------------------------------------

DEF_STD_CMD_A(CmdFeatureLinesFitSurfaces)

CmdFeatureLinesFitSurfaces::CmdFeatureLinesFitSurfaces()
    : Command("FeatureLines_FitSurfaces")
{
    sAppModule = "FeatureLines";
    sGroup = QT_TR_NOOP("FeatureLines");
    sMenuText = QT_TR_NOOP("Fit surfaces");
    sToolTipText =
        QT_TR_NOOP("A surface for every patch of the selected feature lines whose border the\n"
                   "lines close (plane, sphere, cylinder, cone, torus, else a B-spline),\n"
                   "trimmed by that border; the faces sewn, a solid where they close, coloured\n"
                   "by the scan's deviation from them. The new Surfaces object follows the\n"
                   "lines when they recompute.");
    sWhatsThis = "FeatureLines_FitSurfaces";
    sStatusTip = sToolTipText;
}

void CmdFeatureLinesFitSurfaces::activated(int)
{
    App::DocumentObject* lines = selectedExtraction(QObject::tr("Fit surfaces"));
    if (!lines) {
        return;
    }
    const char* doc = lines->getDocument()->getName();
    openCommand(QT_TRANSLATE_NOOP("Command", "Fit surfaces"));
    try {
        doCommand(Doc, "import FeatureLines");
        doCommand(Doc,
                  "_surfaces = FeatureLines.makeSurfaces(App.getDocument('%s').getObject('%s'))",
                  doc, lines->getNameInDocument());
        doCommand(Doc, "App.getDocument('%s').recompute()", doc);
        commitCommand();
    } catch (const Base::Exception& e) {
        abortCommand();
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("No surfaces"),
                             QString::fromUtf8(e.what()));
        return;
    }
    // The surfaces' panel: what was fitted, the deviations, what was left out and why.
    try {
        doCommand(Gui, "Gui.getDocument('%s').setEdit(_surfaces.Name)", doc);
    } catch (const Base::Exception& e) {
        Base::Console().Error("FeatureLines: %s\n", e.what());
    }
}

bool CmdFeatureLinesFitSurfaces::isActive()
{
    return hasActiveDocument() && !Gui::Control().activeDialog() && extractionSelected();
}

/// A command on the one FeatureLines object selected, named and described by its arguments;
/// apply() does its work.
class CmdFeatureLinesOnLines : public Gui::Command
{
public:
    CmdFeatureLinesOnLines(const char* name, const char* menuText, const char* toolTip)
        : Command(name)
    {
        sAppModule = "FeatureLines";
        sGroup = QT_TR_NOOP("FeatureLines");
        sMenuText = menuText;
        sToolTipText = toolTip;
        sWhatsThis = name;
        sStatusTip = toolTip;
    }

protected:
    virtual void apply(App::DocumentObject* lines) = 0;
    void activated(int) override
    {
        if (App::DocumentObject* lines = selectedExtraction(QString::fromUtf8(sMenuText))) {
            apply(lines);
        }
    }
    bool isActive() override
    {
        return hasActiveDocument() && !Gui::Control().activeDialog() && extractionSelected();
    }
};

// ---- Colouring the cloud -----------------------------------------------------------------

/// Colour the selected feature lines' cloud by one of its per-point outputs (the view's
/// ColourPoints), or back to the plain cloud.
class CmdFeatureLinesColourPoints : public CmdFeatureLinesOnLines
{
public:
    CmdFeatureLinesColourPoints(const char* name, const char* mode, const char* menuText,
                                const char* toolTip)
        : CmdFeatureLinesOnLines(name, menuText, toolTip), mode(mode)
    {
    }
    const char* className() const override { return "CmdFeatureLinesColourPoints"; }

protected:
    void apply(App::DocumentObject* lines) override
    {
        // A view property: a macro line, kept with the document's view; "Plain cloud" removes it.
        doCommand(Gui, "Gui.getDocument('%s').getObject('%s').ColourPoints = '%s'",
                  lines->getDocument()->getName(), lines->getNameInDocument(), mode);
    }

private:
    const char* mode;
};

/// The colouring commands: name, ColourPoints value, menu text, tool tip.
const char* const colourCommands[][4] = {
    {"FeatureLines_ColourByRegion", "Region", QT_TR_NOOP("Colour cloud by part (region)"),
     QT_TR_NOOP("Draw the cloud of the selected feature lines with one colour per part between "
                "sharp edges (smooth region); grey on the sharp edges.")},
    {"FeatureLines_ColourByPatch", "Patch", QT_TR_NOOP("Colour cloud by surface patch"),
     QT_TR_NOOP("Draw the cloud of the selected feature lines with one colour per surface patch "
                "(connected points between the same two curvature levels).")},
    {"FeatureLines_ColourByLabel", "Label", QT_TR_NOOP("Colour cloud by flat / curved (label)"),
     QT_TR_NOOP("Draw the cloud of the selected feature lines as the panel does: flatter blue "
                "(low), curved green (inner), change black (border), isolated red (noisy).")},
    {"FeatureLines_ColourByCurvature", "Curvature", QT_TR_NOOP("Colour cloud by curvature"),
     QT_TR_NOOP("Draw the cloud of the selected feature lines from blue (flat) to red (most "
                "curved) by its mean curvature.")},
    {"FeatureLines_ColourNothing", "Nothing", QT_TR_NOOP("Plain cloud"),
     QT_TR_NOOP("Draw the cloud of the selected feature lines as it is again.")},
};

// ---- Cleaning the lines ------------------------------------------------------------------

namespace {

/// Runs FeatureLines.cleanLines(<lines>, <arguments>) and recomputes, as one undo step named
/// `step`; a refusal aborts the step and is shown.
void runCleanLines(Gui::Command& command, App::DocumentObject* lines, const char* step,
                   const std::string& arguments)
{
    const char* doc = lines->getDocument()->getName();
    command.openCommand(step);
    try {
        Gui::Command::doCommand(Gui::Command::Doc, "import FeatureLines");
        Gui::Command::doCommand(
            Gui::Command::Doc, "FeatureLines.cleanLines(App.getDocument('%s').getObject('%s'), %s)",
            doc, lines->getNameInDocument(), arguments.c_str());
        Gui::Command::doCommand(Gui::Command::Doc, "App.getDocument('%s').recompute()", doc);
        command.commitCommand();
    } catch (const Base::Exception& e) {
        command.abortCommand();
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("Lines not cleaned"),
                             QString::fromUtf8(e.what()));
    }
}

/// The wires (0-based, in Shape's order) holding the edges selected of `lines`.
std::vector<int> selectedWires(App::DocumentObject* lines)
{
    const TopoDS_Shape& shape = static_cast<Part::Feature*>(lines)->Shape.getValue();
    TopTools_IndexedMapOfShape edges, wires;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    TopExp::MapShapes(shape, TopAbs_WIRE, wires);
    std::set<int> picked;
    for (const Gui::SelectionObject& s : Gui::Selection().getSelectionEx()) {
        if (s.getObject() != lines) {
            continue;
        }
        for (const std::string& sub : s.getSubNames()) {
            if (sub.rfind("Edge", 0) != 0) {
                continue;
            }
            const int edge = std::atoi(sub.c_str() + 4);
            if (edge < 1 || edge > edges.Extent()) {
                continue;
            }
            for (int w = 1; w <= wires.Extent(); ++w) {
                TopTools_IndexedMapOfShape wireEdges;
                TopExp::MapShapes(wires(w), TopAbs_EDGE, wireEdges);
                if (wireEdges.Contains(edges(edge))) {
                    picked.insert(w - 1);
                    break;
                }
            }
        }
    }
    return {picked.begin(), picked.end()};
}

} // namespace

DEF_STD_CMD_A(CmdFeatureLinesDropShortLines)

CmdFeatureLinesDropShortLines::CmdFeatureLinesDropShortLines()
    : Command("FeatureLines_DropShortLines")
{
    sAppModule = "FeatureLines";
    sGroup = QT_TR_NOOP("FeatureLines");
    sMenuText = QT_TR_NOOP("Drop short lines...");
    sToolTipText = QT_TR_NOOP("Drops the lines of the selected feature lines shorter than a "
                              "length you give\n(kept as its MinLineLength: 0 brings them back).");
    sWhatsThis = "FeatureLines_DropShortLines";
    sStatusTip = sToolTipText;
}

void CmdFeatureLinesDropShortLines::activated(int)
{
    App::DocumentObject* lines = selectedExtraction(QObject::tr("Drop short lines"));
    if (!lines) {
        return;
    }
    auto* current = dynamic_cast<App::PropertyLength*>(lines->getPropertyByName("MinLineLength"));
    auto* spacing = dynamic_cast<App::PropertyLength*>(lines->getPropertyByName("Spacing"));
    const double proposed = current && current->getValue() > 0.0 ? current->getValue()
                            : spacing                            ? 10.0 * spacing->getValue()
                                                                 : 1.0;
    bool ok = false;
    const double length = QInputDialog::getDouble(
        Gui::getMainWindow(), QObject::tr("Drop short lines"),
        QObject::tr("Drop the lines shorter than (mm; 0 keeps every line):"), proposed, 0.0, 1e9, 3,
        &ok);
    if (!ok) {
        return;
    }
    runCleanLines(*this, lines, QT_TRANSLATE_NOOP("Command", "Drop short lines"),
                  "minLength=" + std::to_string(length));
}

bool CmdFeatureLinesDropShortLines::isActive()
{
    return hasActiveDocument() && !Gui::Control().activeDialog() && extractionSelected();
}

DEF_STD_CMD_A(CmdFeatureLinesDeleteLines)

CmdFeatureLinesDeleteLines::CmdFeatureLinesDeleteLines() : Command("FeatureLines_DeleteLines")
{
    sAppModule = "FeatureLines";
    sGroup = QT_TR_NOOP("FeatureLines");
    sMenuText = QT_TR_NOOP("Delete selected lines");
    sToolTipText = QT_TR_NOOP("Deletes the lines of the feature lines whose edges are selected in "
                              "the 3D view\n(kept as its RemovedLines: empty it to bring them "
                              "back).");
    sWhatsThis = "FeatureLines_DeleteLines";
    sStatusTip = sToolTipText;
}

void CmdFeatureLinesDeleteLines::activated(int)
{
    App::DocumentObject* lines = selectedExtraction(QObject::tr("Delete selected lines"));
    if (!lines) {
        return;
    }
    const std::vector<int> wires = selectedWires(lines);
    if (wires.empty()) {
        QMessageBox::warning(Gui::getMainWindow(), QObject::tr("Select lines"),
                             QObject::tr("Select the lines to delete in the 3D view (click on "
                                         "them, Ctrl+click for more), then run Delete selected "
                                         "lines again."));
        return;
    }
    std::string list;
    for (int w : wires) {
        list += (list.empty() ? "" : ", ") + std::to_string(w);
    }
    runCleanLines(*this, lines, QT_TRANSLATE_NOOP("Command", "Delete selected lines"),
                  "remove=[" + list + "]");
    Gui::Selection().clearSelection();
}

bool CmdFeatureLinesDeleteLines::isActive()
{
    return hasActiveDocument() && !Gui::Control().activeDialog() && extractionSelected();
}

/// A cleaning of the selected feature lines with fixed arguments of cleanLines.
class CmdFeatureLinesCleanLines : public CmdFeatureLinesOnLines
{
public:
    CmdFeatureLinesCleanLines(const char* name, const char* arguments, const char* menuText,
                              const char* toolTip)
        : CmdFeatureLinesOnLines(name, menuText, toolTip), arguments(arguments)
    {
    }
    const char* className() const override { return "CmdFeatureLinesCleanLines"; }

protected:
    void apply(App::DocumentObject* lines) override
    {
        runCleanLines(*this, lines, sMenuText, arguments);
    }

private:
    const char* arguments;
};

/// The cleanings with fixed arguments: name, cleanLines arguments, menu text, tool tip.
const char* const cleaningCommands[][4] = {
    {"FeatureLines_MergeLines", "mergeEndToEnd=True", QT_TR_NOOP("Merge lines meeting end to end"),
     QT_TR_NOOP("Joins two lines of the selected feature lines whose ends meet at a point\nwhere "
                "no other line ends into one line (kept as its MergeEndToEnd).")},
    {"FeatureLines_RestoreLines", "restore=True", QT_TR_NOOP("Restore all lines"),
     QT_TR_NOOP("Brings back every line of the selected feature lines: no line deleted, dropped "
                "or merged.")},
};

void CreateFeatureLinesCommands()
{
    Gui::CommandManager& manager = Gui::Application::Instance->commandManager();
    manager.addCommand(new CmdFeatureLinesExtract());
    manager.addCommand(new CmdFeatureLinesMakePatchClouds());
    manager.addCommand(new CmdFeatureLinesFitSurfaces());
    manager.addCommand(new CmdFeatureLinesDropShortLines());
    manager.addCommand(new CmdFeatureLinesDeleteLines());
    for (const auto& c : cleaningCommands) {
        manager.addCommand(new CmdFeatureLinesCleanLines(c[0], c[1], c[2], c[3]));
    }
    for (const auto& c : colourCommands) {
        manager.addCommand(new CmdFeatureLinesColourPoints(c[0], c[1], c[2], c[3]));
    }
}
