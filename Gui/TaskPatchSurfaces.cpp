// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "TaskPatchSurfaces.h"

#include <App/Document.h>
#include <App/DocumentObject.h>
#include <App/PropertyStandard.h>
#include <Base/Console.h>
#include <Base/Exception.h>
#include <Gui/Application.h>
#include <Gui/Document.h>
#include <Gui/BitmapFactory.h>
#include <Gui/Command.h>
#include <Gui/TaskView/TaskView.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

#include "ViewProviderPatchSurfaces.h"

using namespace FeatureLinesGui;

namespace {

template <typename P>
const P* propertyOf(const App::DocumentObject* o, const char* name)
{
    return o ? dynamic_cast<const P*>(o->getPropertyByName(name)) : nullptr;
}

/// A length in mm with three significant digits.
QString millimetres(double v)
{
    return QString::number(v, 'g', 3);
}

/// A deviation in mm, short enough for the table's narrow columns: two significant digits.
QString deviation(double v)
{
    return QString::number(v, 'g', 2);
}

} // namespace

TaskPatchSurfaces::TaskPatchSurfaces(ViewProviderPatchSurfaces* view)
    : object(view->getObject()), documentName(view->getObject()->getDocument()->getName())
{
    auto* widget = new QWidget();
    widget->setWindowTitle(tr("Surfaces"));
    widget->setObjectName(QStringLiteral("TaskPatchSurfaces"));
    auto* layout = new QVBoxLayout(widget);
    layout->setContentsMargins(0, 0, 0, 0);

    summary = new QLabel();
    summary->setObjectName(QStringLiteral("labelSummary"));
    summary->setWordWrap(true);
    layout->addWidget(summary);

    table = new QTableWidget(0, 4);
    table->setObjectName(QStringLiteral("tableSurfaces"));
    table->setHorizontalHeaderLabels({tr("Patch"), tr("Surface"), tr("RMS"), tr("Largest")});
    table->horizontalHeaderItem(2)->setToolTip(
        tr("The root mean square distance of the patch's points from its surface (mm)."));
    table->horizontalHeaderItem(3)->setToolTip(
        tr("The largest distance of a point of the patch from its surface (mm)."));
    table->verticalHeader()->setVisible(false);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setMinimumHeight(160);
    layout->addWidget(table);

    problems = new QLabel();
    problems->setObjectName(QStringLiteral("labelProblems"));
    problems->setWordWrap(true);
    layout->addWidget(problems);

    auto* form = new QFormLayout();
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    colourMap = new QCheckBox(tr("Colour by deviation"));
    colourMap->setObjectName(QStringLiteral("checkColourMap"));
    colourMap->setToolTip(
        tr("Colour the faces by how far the scan lies from them: red where the points lie "
           "above a face (outside the solid), blue below it, green on it; grey where no point "
           "is near. The colour bar beside the view gives the values."));
    form->addRow(colourMap);
    range = new QDoubleSpinBox();
    range->setObjectName(QStringLiteral("spinColourRange"));
    range->setDecimals(4);
    range->setRange(0.0, 1e6);
    range->setSingleStep(0.01);
    range->setSuffix(tr(" mm"));
    range->setToolTip(tr("The colours run from blue at minus this to red at plus this. "
                         "0: automatic, the 95th percentile of the deviations."));
    range->setSpecialValueText(tr("automatic"));
    form->addRow(tr("Colour range \u00b1"), range);
    rangeNote = new QLabel();
    rangeNote->setObjectName(QStringLiteral("labelColourRange"));
    rangeNote->setWordWrap(true);
    form->addRow(rangeNote);
    minPoints = new QSpinBox();
    minPoints->setObjectName(QStringLiteral("spinMinPoints"));
    minPoints->setRange(0, 100000000);
    minPoints->setSpecialValueText(tr("automatic"));
    minPoints->setToolTip(tr("Patches of fewer points get no surface (automatic: twice the "
                             "lines' neighbour count). A change fits the surfaces again."));
    form->addRow(tr("Smallest patch (points)"), minPoints);
    layout->addLayout(form);

    auto* box = new Gui::TaskView::TaskBox(Gui::BitmapFactory().pixmap("FeatureLines_Workbench"),
                                           widget->windowTitle(), true, nullptr);
    box->groupLayout()->addWidget(widget);
    Content.push_back(box);

    // A panel opened by setEdit from a script has no transaction of its own.
    if (!Gui::Command::hasPendingCommand()) {
        Gui::Command::openCommand(QT_TRANSLATE_NOOP("Command", "Edit surfaces"));
    }

    connect(colourMap, &QCheckBox::toggled, this, [this](bool on) {
        runLine(objectCommand(true) + ".DisplayMode = '" +
                    (on ? std::string("Deviation") : std::string("Flat Lines")) + "'",
                true);
        refresh();
    });
    connect(range, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        runLine(objectCommand(true) + ".DeviationRange = " + QString::number(v, 'g', 10).toStdString(),
                true);
        refresh();
    });
    connect(minPoints, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        if (runLine(objectCommand(false) + ".MinPoints = " + std::to_string(v))) {
            runLine("App.getDocument('" + documentName + "').recompute()");
        }
        refresh();
    });
    refresh();
}

App::DocumentObject* TaskPatchSurfaces::getObject() const
{
    return object.getObject();
}

ViewProviderPatchSurfaces* TaskPatchSurfaces::view() const
{
    App::DocumentObject* o = getObject();
    auto* doc = o ? Gui::Application::Instance->getDocument(o->getDocument()) : nullptr;
    return doc ? dynamic_cast<ViewProviderPatchSurfaces*>(doc->getViewProvider(o)) : nullptr;
}

std::string TaskPatchSurfaces::objectCommand(bool gui) const
{
    return std::string(gui ? "Gui" : "App") + ".getDocument('" + documentName + "').getObject('" +
           object.getObjectName() + "')";
}

bool TaskPatchSurfaces::runLine(const std::string& command, bool gui)
{
    try {
        Gui::Command::doCommand(gui ? Gui::Command::Gui : Gui::Command::Doc, "%s", command.c_str());
        return true;
    } catch (const Base::Exception& e) {
        problems->setText(QString::fromUtf8(e.what()));
        Base::Console().Error("FeatureLines: %s\n", e.what());
        return false;
    }
}

void TaskPatchSurfaces::refresh()
{
    const App::DocumentObject* o = getObject();
    const auto* patches = propertyOf<App::PropertyIntegerList>(o, "FacePatches");
    const auto* kinds = propertyOf<App::PropertyStringList>(o, "FaceKinds");
    const auto* rms = propertyOf<App::PropertyFloatList>(o, "FaceRmsDeviations");
    const auto* largest = propertyOf<App::PropertyFloatList>(o, "FaceMaxDeviations");
    const auto* left = propertyOf<App::PropertyStringList>(o, "Problems");
    const auto* solid = propertyOf<App::PropertyBool>(o, "IsSolid");
    const auto* valid = propertyOf<App::PropertyBool>(o, "IsValid");
    const auto* tolerance = propertyOf<App::PropertyFloat>(o, "SewingTolerance");
    if (!patches || !kinds || !rms || !largest || !left || !solid || !valid || !tolerance) {
        summary->setText(tr("The surfaces object is gone."));
        return;
    }
    const size_t n = std::min({patches->getValues().size(), kinds->getValues().size(),
                               rms->getValues().size(), largest->getValues().size()});
    std::map<std::string, int> byKind;
    int faces = 0;
    QSignalBlocker blockTable(table);
    table->setRowCount(static_cast<int>(n));
    for (size_t i = 0; i < n; ++i) {
        const std::string& kind = kinds->getValues()[i];
        const bool fitted = !kind.empty();
        faces += fitted ? 1 : 0;
        if (fitted) {
            ++byKind[kind];
        }
        const int row = static_cast<int>(i);
        table->setItem(row, 0, new QTableWidgetItem(QString::number(patches->getValues()[i])));
        table->setItem(row, 1, new QTableWidgetItem(fitted ? QString::fromStdString(kind)
                                                           : tr("no face")));
        table->setItem(row, 2, new QTableWidgetItem(fitted ? deviation(rms->getValues()[i])
                                                           : QString()));
        table->setItem(row, 3, new QTableWidgetItem(fitted ? deviation(largest->getValues()[i])
                                                           : QString()));
    }
    QStringList counts;
    for (const auto& [kind, count] : byKind) {
        counts << QStringLiteral("%1 %2").arg(count).arg(QString::fromStdString(kind));
    }
    QString shape = solid->getValue()
                        ? (valid->getValue() ? tr("a valid closed solid") : tr("a solid that is not valid"))
                        : tr("not closed into a solid");
    summary->setText(tr("<b>%1 face(s) of %2 patch(es)</b>: %3. Sewn: %4; the faces' borders "
                        "meet within %5 mm.")
                         .arg(faces)
                         .arg(n)
                         .arg(counts.isEmpty() ? tr("none") : counts.join(QLatin1String(", ")))
                         .arg(shape)
                         .arg(millimetres(tolerance->getValue())));
    const std::vector<std::string>& why = left->getValues();
    QStringList lines;
    for (size_t i = 0; i < why.size() && i < 6; ++i) {
        lines << QString::fromStdString(why[i]).toHtmlEscaped();
    }
    if (why.size() > 6) {
        lines << tr("... and %1 more (the object's Problems)").arg(why.size() - 6);
    }
    problems->setText(lines.isEmpty() ? QString()
                                      : tr("Left out:") + QStringLiteral("<br>") +
                                            lines.join(QStringLiteral("<br>")));
    problems->setVisible(!lines.isEmpty());

    ViewProviderPatchSurfaces* v = view();
    if (v) {
        QSignalBlocker b1(colourMap);
        QSignalBlocker b2(range);
        QSignalBlocker b3(minPoints);
        colourMap->setChecked(std::string(v->DisplayMode.getValueAsString()) == "Deviation");
        range->setValue(v->DeviationRange.getValue());
        range->setEnabled(colourMap->isChecked());
        rangeNote->setText(colourMap->isChecked()
                               ? tr("Colours from blue at \u2212%1 mm to red at +%1 mm.")
                                     .arg(millimetres(v->deviationRange()))
                               : QString());
        rangeNote->setVisible(colourMap->isChecked());
    }
    if (const auto* m = propertyOf<App::PropertyIntegerConstraint>(o, "MinPoints")) {
        QSignalBlocker b(minPoints);
        minPoints->setValue(static_cast<int>(m->getValue()));
    }
}

bool TaskPatchSurfaces::accept()
{
    Gui::Command::commitCommand();
    runLine("Gui.getDocument('" + documentName + "').resetEdit()", true);
    return true;
}

bool TaskPatchSurfaces::reject()
{
    // Before resetEdit, which commits the transaction still open (Gui::Document::resetEdit).
    Gui::Command::abortCommand();
    runLine("Gui.getDocument('" + documentName + "').resetEdit()", true);
    return true;
}
