// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "TaskExtraction.h"

#include <BRep_Tool.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include <App/Application.h>
#include <App/Document.h>
#include <Base/Console.h>
#include <Base/Exception.h>
#include <Gui/Application.h>
#include <Gui/BitmapFactory.h>
#include <Gui/Command.h>
#include <Gui/Control.h>
#include <Gui/Document.h>
#include <Gui/Selection.h>
#include <Gui/TaskView/TaskView.h>
#include <Mod/Points/App/PointsFeature.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "AnalysisRun.h"
#include "ExtractionFeature.h"
#include "ExtractionParameters.h"
#include "FeatureLines/cli/Progress.h"
#include "HistogramWidget.h"
#include "PointPreview.h"
#include "ViewProviderExtraction.h"
#include "ui_TaskExtractionOptions.h"
#include "ui_TaskExtractionThresholds.h"

using namespace FeatureLinesGui;
using FeatureLines::Parameter;
using FeatureLines::ParameterKind;

namespace {

constexpr double none = std::numeric_limits<double>::quiet_NaN();

/// The options shown in the panel: the ones that decide the regions and their histograms. The
/// others are in the property editor (their defaults scale with the cloud). Each with its name
/// and meaning in plain words; the tooltip adds the property's name and documentation.
struct PanelOption
{
    const char* property;
    const char* label;
    const char* meaning;
};
const PanelOption panelOptions[] = {
    {"NeighbourCount", QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction", "Neighbours per point"),
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction",
                       "How many nearby points describe the surface at each point. More: "
                       "smoother, slower, small details lost.")},
    {"GrowAngle", QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction", "Sharp-edge angle"),
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction",
                       "How far the surface may turn between neighbouring points before the "
                       "fold counts as a sharp edge.")},
    {"MinFilletRadius", QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction", "Smallest fillet"),
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction",
                       "Rounded edges tighter than this radius are treated as sharp edges, wider "
                       "ones as fillets whose borders become smooth lines.")},
    {"Smoothing", QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction", "Smooth noisy scans"),
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction",
                       "Whether noisy parts of the cloud are smoothed before their curvature is "
                       "measured (Taubin smoothing, Sec. 2.4).")},
    {"HistogramBins", QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction", "Histogram bars"),
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction",
                       "How many bars the curvature histogram starts with (L_start, Sec. 2.2).")},
    {"OutlierPercent",
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction", "Ignore most curved (%)"),
     QT_TRANSLATE_NOOP("FeatureLinesGui::TaskExtraction",
                       "Share of the most curved points left out of the histogram, as scan noise "
                       "(outliers, Sec. 2.4); -1: 1 % in smoothed parts, none elsewhere.")},
};

/// A number as Python writes it back exactly.
std::string pythonNumber(double v)
{
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

QString shortNumber(double v)
{
    return std::isfinite(v) ? QString::number(v, 'g', 4) : QString::fromUtf8("\u2014");
}

std::string pythonValue(const Parameter& p, double v)
{
    switch (p.kind) {
    case ParameterKind::Integer:
        return std::to_string(std::lround(v));
    case ParameterKind::Switch:
        return v != 0.0 ? "True" : "False";
    case ParameterKind::Choice:
        return std::string("'") + p.choices[std::lround(v)] + "'";
    case ParameterKind::Float:
    case ParameterKind::Spacing:
    case ParameterKind::Angle:
        break;
    }
    return pythonNumber(v);
}

/// A new object (touched by its constructor) or one with changed properties.
bool needsRecompute(const App::DocumentObject& object)
{
    return object.isTouched() || object.mustExecute() != 0;
}

QString colourName(const Base::Vector3f& c)
{
    return QColor::fromRgbF(c.x, c.y, c.z).name();
}

/// Smooth wires of one region and how many of them are closed.
std::pair<int, int> regionLines(const FeatureLines::Extraction& e, int region)
{
    const std::vector<long>& regions = e.SmoothLineRegions.getValues();
    const TopoDS_Shape& shape = e.SmoothWires.getShape().getShape();
    int lines = 0;
    int closed = 0;
    if (shape.IsNull()) {
        return {0, 0};
    }
    size_t i = 0;
    for (TopoDS_Iterator it(shape); it.More(); it.Next(), ++i) {
        if (i < regions.size() && regions[i] == region && it.Value().ShapeType() == TopAbs_WIRE) {
            ++lines;
            closed += BRep_Tool::IsClosed(TopoDS::Wire(it.Value())) ? 1 : 0;
        }
    }
    return {lines, closed};
}

} // namespace

TaskExtraction::TaskExtraction(ViewProviderExtraction* view)
    : object(view->getObject()), documentName(view->getObject()->getDocument()->getName()),
      optionsUi(std::make_unique<Ui_TaskExtractionOptions>()),
      thresholdsUi(std::make_unique<Ui_TaskExtractionThresholds>())
{
    const QPixmap icon = Gui::BitmapFactory().pixmap("FeatureLines_Extract");
    optionsWidget = new QWidget();
    optionsUi->setupUi(optionsWidget);
    auto* optionsBox =
        new Gui::TaskView::TaskBox(icon, optionsWidget->windowTitle(), true, nullptr);
    optionsBox->groupLayout()->addWidget(optionsWidget);
    Content.push_back(optionsBox);

    thresholdsWidget = new QWidget();
    thresholdsUi->setupUi(thresholdsWidget);
    auto* thresholdsBox =
        new Gui::TaskView::TaskBox(QPixmap(), thresholdsWidget->windowTitle(), true, nullptr);
    thresholdsBox->groupLayout()->addWidget(thresholdsWidget);
    Content.push_back(thresholdsBox);

    run = new AnalysisRun(this);
    FeatureLines::Extraction* e = extraction();
    Gui::Document* guiDocument = Gui::Application::Instance->getDocument(e->getDocument());
    preview = std::make_unique<PointPreview>(guiDocument, e->Source.getValue());

    // A panel opened by setEdit from a script has no transaction of its own: every change it
    // makes belongs to one, so that Cancel can abort it and one undo reverts it.
    if (!Gui::Command::hasPendingCommand()) {
        Gui::Command::openCommand(QT_TRANSLATE_NOOP("Command", "Edit feature lines"));
    }

    buildOptions();
    connectWidgets();
    setRunning(false);
    setRunState("idle");
    optionsUi->progressBar->setVisible(false);
    thresholdsWidget->setEnabled(false);
    thresholdsUi->labelRegion->setVisible(false);
    thresholdsUi->comboRegion->setVisible(false);
    refresh();
}

TaskExtraction::~TaskExtraction()
{
    run->cancelAndWait();
    // The widgets outlive this object's members (TaskDialog deletes them): no signal of theirs
    // may reach a slot of it any more.
    for (QWidget* w : {optionsWidget, thresholdsWidget}) {
        for (QObject* child : w->findChildren<QObject*>()) {
            disconnect(child, nullptr, this, nullptr);
        }
    }
    closePreview();
}

App::DocumentObject* TaskExtraction::getObject() const
{
    return object.getObject();
}

FeatureLines::Extraction* TaskExtraction::extraction() const
{
    return dynamic_cast<FeatureLines::Extraction*>(object.getObject());
}

void TaskExtraction::buildOptions()
{
    FeatureLines::Extraction* e = extraction();
    const FeatureLines::ParameterValues values = e->parameterValues();
    const App::DocumentObject* source = e->Source.getValue();
    if (const auto* cloud = dynamic_cast<const Points::Feature*>(source)) {
        optionsUi->labelSource->setText(tr("Cloud: %1 (%2 points)")
                                            .arg(QString::fromUtf8(cloud->Label.getValue()))
                                            .arg(cloud->Points.getValue().size()));
    } else {
        optionsUi->labelSource->setText(tr("No point cloud: set the Source property."));
    }
    for (const PanelOption& option : panelOptions) {
        const char* name = option.property;
        const Parameter* p = FeatureLines::findParameter(name);
        if (!p) {
            continue;
        }
        const double value = values.scalars.at(name);
        QWidget* widget = nullptr;
        switch (p->kind) {
        case ParameterKind::Integer: {
            auto* box = new QSpinBox();
            box->setRange(int(p->minimum), int(std::min(p->maximum, 1e9)));
            box->setSingleStep(std::max(1, int(p->step)));
            box->setValue(int(std::lround(value)));
            widget = box;
            break;
        }
        case ParameterKind::Float:
        case ParameterKind::Spacing:
        case ParameterKind::Angle: {
            auto* box = new QDoubleSpinBox();
            box->setDecimals(p->kind == ParameterKind::Angle ? 1 : 2);
            box->setRange(p->minimum, p->maximum);
            box->setSingleStep(p->step > 0.0 ? p->step : 0.1);
            box->setValue(value);
            if (p->kind == ParameterKind::Spacing) {
                box->setSuffix(tr(" \u00d7 spacing"));
            } else if (p->kind == ParameterKind::Angle) {
                box->setSuffix(QString::fromUtf8(" \u00b0"));
            }
            widget = box;
            break;
        }
        case ParameterKind::Switch: {
            auto* box = new QCheckBox();
            box->setChecked(value != 0.0);
            widget = box;
            break;
        }
        case ParameterKind::Choice: {
            auto* box = new QComboBox();
            for (int i = 0; p->choices[i]; ++i) {
                box->addItem(QString::fromLatin1(p->choices[i]));
            }
            box->setCurrentIndex(int(std::lround(value)));
            widget = box;
            break;
        }
        }
        widget->setObjectName(QString::fromLatin1(name));
        widget->setToolTip(
            tr(option.meaning) + QLatin1String("\n\n") +
            tr("Property %1: %2").arg(QString::fromLatin1(name), QString::fromUtf8(p->doc)));
        auto* label = new QLabel(tr(option.label) + QLatin1String(":"));
        label->setToolTip(widget->toolTip());
        optionsUi->optionsForm->addRow(label, widget);
        optionWidgets[name] = widget;
    }
}

FeatureLines::ParameterValues TaskExtraction::changedOptions() const
{
    FeatureLines::ParameterValues changes;
    const FeatureLines::ParameterValues values = extraction()->parameterValues();
    for (const auto& [name, widget] : optionWidgets) {
        double v = 0.0;
        if (auto* spin = qobject_cast<QSpinBox*>(widget)) {
            v = spin->value();
        } else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(widget)) {
            v = dspin->value();
        } else if (auto* check = qobject_cast<QCheckBox*>(widget)) {
            v = check->isChecked() ? 1.0 : 0.0;
        } else if (auto* combo = qobject_cast<QComboBox*>(widget)) {
            v = combo->currentIndex();
        }
        const double old = values.scalars.at(name);
        // Spin boxes round to their decimals: a value they only show rounded is no change.
        const auto* dspin = qobject_cast<QDoubleSpinBox*>(widget);
        const double tolerance = dspin ? 0.5 * std::pow(10.0, -dspin->decimals()) : 0.0;
        if (std::abs(v - old) > tolerance) {
            changes.scalars[name] = v;
        }
    }
    return changes;
}

void TaskExtraction::connectWidgets()
{
    Ui_TaskExtractionOptions& o = *optionsUi;
    Ui_TaskExtractionThresholds& t = *thresholdsUi;
    connect(o.buttonRun, &QPushButton::clicked, this, [this] { startRun(); });
    connect(o.buttonCancelRun, &QPushButton::clicked, this, [this] {
        run->cancel();
        cancelling = true;
        optionsUi->labelStatus->setText(tr("Cancelling at the next stage..."));
    });
    connect(run, &AnalysisRun::progressed, this,
            [this](int percent, const QString& stage) { showProgress(percent, stage); });
    connect(run, &AnalysisRun::finished, this, [this] { runFinished(); });

    connect(t.buttonAccept, &QPushButton::clicked, this, [this] { acceptCandidate(); });
    connect(t.buttonLower, &QPushButton::clicked, this, [this] { stepCandidate(false); });
    connect(t.buttonHigher, &QPushButton::clicked, this, [this] { stepCandidate(true); });
    connect(t.buttonBack, &QPushButton::clicked, this, [this] { backToLines(); });
    connect(t.buttonDone, &QPushButton::clicked, this, [this] { done(); });
    connect(t.buttonFitSurfaces, &QPushButton::clicked, this, [this] { doneFitSurfaces(); });
    connect(t.buttonHelp, &QPushButton::toggled, t.labelHelp, &QLabel::setVisible);
    connect(t.buttonAddLower, &QPushButton::clicked, this, [this] { addThreshold(false); });
    connect(t.buttonAddHigher, &QPushButton::clicked, this, [this] { addThreshold(true); });
    connect(t.histogram, &HistogramWidget::valueClicked, this,
            [this](double value) { chooseValue(value); });
    connect(t.comboRegion, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
        if (i >= 0 && i < static_cast<int>(regions.size()) && i != current) {
            current = i;
            thresholdsUi->labelMessage->clear();
            refresh();
        }
    });
    connect(t.comboPreview, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this](int) { refresh(); });
}

void TaskExtraction::open()
{
    startRun();
}

// ---- The analysis ---------------------------------------------------------------------------

void TaskExtraction::startRun()
{
    FeatureLines::Extraction* e = extraction();
    if (!e || run->isRunning()) {
        return;
    }
    FeatureLines::ExtractionInput in;
    try {
        in = FeatureLines::extractionInput(*e, changedOptions());
    } catch (const std::invalid_argument& error) {
        optionsUi->labelStatus->setText(QString::fromUtf8(error.what()));
        setRunState("failed");
        return;
    }
    optionsUi->labelStatus->setText(tr("Analysing the cloud..."));
    optionsUi->progressBar->setValue(0);
    // The bar shows the share only: the stage's name goes into the status line below it, which
    // wraps in a narrow panel.
    optionsUi->progressBar->setFormat(QLatin1String("%p%"));
    runClock.start();
    cancelling = false;
    setRunning(true);
    setRunState("running");
    run->start(std::move(in));
}

void TaskExtraction::showProgress(int percent, const QString& stage)
{
    optionsUi->progressBar->setValue(percent);
    if (cancelling) {
        return; // "Cancelling..." stays until the run stops
    }
    const double left =
        featurelines::cli::secondsLeft(percent / 100.0, runClock.elapsed() / 1000.0);
    QString text = tr("Analysing: %1").arg(stage);
    if (std::isfinite(left)) {
        text += left < 60.0
                    ? tr(", about %1 s left").arg(std::max(1L, std::lround(std::ceil(left))))
                    : tr(", about %1 min left").arg(std::lround(std::ceil(left / 60.0)));
    }
    optionsUi->labelStatus->setText(text);
}

void TaskExtraction::setRunning(bool running)
{
    optionsUi->buttonRun->setEnabled(!running);
    optionsUi->buttonCancelRun->setEnabled(running);
    optionsUi->progressBar->setVisible(running);
    for (const auto& entry : optionWidgets) {
        entry.second->setEnabled(!running);
    }
    thresholdsWidget->setEnabled(!running && analysed);
}

void TaskExtraction::runFinished()
{
    const AnalysisRun::Outcome& outcome = run->outcome();
    setRunning(false);
    switch (outcome.status) {
    case AnalysisRun::Outcome::Cancelled:
        optionsUi->labelStatus->setText(
            tr("Run cancelled: the document is as it was%1.")
                .arg(analysed ? tr(", the thresholds below use the previous analysis")
                              : QString()));
        setRunState("cancelled");
        return;
    case AnalysisRun::Outcome::Failed:
        optionsUi->labelStatus->setText(tr("The analysis failed: %1").arg(outcome.message));
        setRunState("failed");
        return;
    case AnalysisRun::Outcome::Done:
        break;
    }
    FeatureLines::Extraction* e = extraction();
    if (!e) {
        return;
    }
    // The options the run used become the object's, as macro lines.
    const FeatureLines::ParameterValues changes = changedOptions();
    bool changed = false;
    for (const auto& [name, value] : changes.scalars) {
        const Parameter* p = FeatureLines::findParameter(name);
        changed = runLine(objectCommand() + "." + name + " = " + pythonValue(*p, value)) || changed;
    }
    analysis = outcome.analysis;
    input = outcome.input;
    input.options.progress = nullptr;
    adoptAnalysis();
    const size_t count = analysis.regions ? analysis.regions->geometry.size() : 0;
    QString status = tr("%1 points, %2 apart on average (spacing), %3 part(s) between sharp "
                        "edges (smooth regions).")
                         .arg(analysis.geometry->inputToPoint.size())
                         .arg(shortNumber(analysis.geometry->spacing))
                         .arg(count);
    if (analysis.regions) {
        // Regions whose noise hides their fillets at the cloud's spacing (CurvatureScale.h):
        // their histograms and lines come from a coarser scale.
        QStringList coarse;
        for (const featurelines::RegionGeometry& g : analysis.regions->geometry) {
            if (g.curvatureScale > 1.0) {
                coarse << tr("%1 at %2 \u00d7 spacing")
                              .arg(g.region)
                              .arg(shortNumber(g.curvatureScale));
            }
        }
        if (!coarse.isEmpty()) {
            status += QLatin1Char(' ') + tr("Noisy: curvature measured at a coarser scale in "
                                            "region %1.")
                                             .arg(coarse.join(QLatin1String(", ")));
        }
    }
    optionsUi->labelStatus->setText(status);
    const bool anyAccepted = std::any_of(regions.begin(), regions.end(),
                                         [](const Region& r) { return !r.accepted.empty(); });
    if (anyAccepted && (changed || needsRecompute(*e))) {
        recompute();
    }
    refresh();
    setRunState("done");
}

void TaskExtraction::setRunState(const char* state)
{
    // For scripts and tests: where the last run stands (idle, running, done, cancelled,
    // failed), once the panel shows its outcome.
    optionsWidget->setProperty("run", QString::fromLatin1(state));
}

void TaskExtraction::adoptAnalysis()
{
    analysed = true;
    thresholdsWidget->setEnabled(true);
    worldPoints.clear();
    const featurelines::PointMatrix& P = input.points;
    worldPoints.reserve(static_cast<size_t>(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const Base::Vector3d w = FeatureLines::worldPoint(input.toWorld, P, i);
        worldPoints.emplace_back(float(w.x), float(w.y), float(w.z));
    }
    const std::vector<featurelines::RegionGeometry>& geometry = analysis.regions->geometry;
    if (regionsInitialised && geometry.size() == regions.size()) {
        // Same regions (an option of the curvature changed): keep the accepted thresholds,
        // search the candidates again on the new histograms.
        for (Region& r : regions) {
            r.points = static_cast<int>(geometry[static_cast<size_t>(r.id)].members.size());
            if (r.choosing) {
                startChoosing(r, r.lower, r.upper, !std::isnan(r.upper));
            }
            r.automaticKnown = false;
        }
    } else {
        if (regionsInitialised) {
            thresholdsUi->labelMessage->setText(
                tr("The options give other smooth regions: choose their thresholds again."));
        }
        initialiseRegions();
    }
    QComboBox* combo = thresholdsUi->comboRegion;
    QSignalBlocker block(combo);
    combo->clear();
    for (const Region& r : regions) {
        combo->addItem(tr("Region %1 (%2 points)").arg(r.id).arg(r.points));
    }
    current = std::clamp(current, 0, std::max(0, static_cast<int>(regions.size()) - 1));
    combo->setCurrentIndex(current);
    const bool several = regions.size() > 1;
    thresholdsUi->labelRegion->setVisible(several);
    combo->setVisible(several);
}

void TaskExtraction::initialiseRegions()
{
    FeatureLines::Extraction* e = extraction();
    regions.clear();
    current = 0;
    const std::vector<featurelines::RegionGeometry>& geometry = analysis.regions->geometry;
    // What the object holds already: its explicit thresholds, or those a computed automatic
    // run used. A new object holds none: every region starts at stage (a).
    std::map<int, std::vector<double>> held;
    if (e->ThresholdMode.getValueAsString() == std::string("Explicit")) {
        const auto byRegion = FeatureLines::parseRegionThresholds(e->RegionThresholds.getValues());
        for (const featurelines::RegionGeometry& g : geometry) {
            auto it = byRegion.find(g.region);
            held[g.region] = it != byRegion.end() ? it->second : e->Thresholds.getValues();
        }
    } else if (!needsRecompute(*e) && e->isValid()) {
        const std::vector<double>& used = e->UsedThresholds.getValues();
        const std::vector<long>& usedRegions = e->UsedThresholdRegions.getValues();
        for (size_t i = 0; i < used.size() && i < usedRegions.size(); ++i) {
            held[int(usedRegions[i])].push_back(used[i]);
        }
    }
    for (const featurelines::RegionGeometry& g : geometry) {
        Region r;
        r.id = g.region;
        r.points = static_cast<int>(g.members.size());
        r.accepted = held[g.region];
        r.lower = r.upper = none;
        r.candidate = none;
        r.choosing = r.accepted.empty();
        if (r.choosing) {
            startChoosing(r, none, none, true);
        }
        regions.push_back(r);
    }
    regionsInitialised = true;
}

// ---- Sec. 2.3: the two stages -------------------------------------------------------------

bool TaskExtraction::search(Region& r, double lower, double upper)
{
    try {
        const featurelines::RegionGeometry& g = FeatureLines::regionGeometry(analysis, r.id);
        const featurelines::ThresholdResult t =
            FeatureLines::searchThreshold(g, input.options.smooth, lower, upper);
        r.candidate = t.threshold;
        r.note.clear();
        return true;
    } catch (const std::invalid_argument& e) {
        r.note = QString::fromUtf8(e.what());
        return false;
    }
}

void TaskExtraction::acceptCandidate()
{
    Region* r = currentRegion();
    if (!r || !r->choosing || !std::isfinite(r->candidate)) {
        return;
    }
    if (const featurelines::RegionGeometry* g = currentGeometry()) {
        const double repeated =
            FeatureLines::repeatedThreshold(*g, input.options.smooth, r->candidate, r->accepted);
        if (!std::isnan(repeated)) {
            thresholdsUi->labelMessage->setText(
                tr("\u03c4 = %1 gives the same patches as the accepted %2: its lines would repeat "
                   "those. Choose another candidate.")
                    .arg(shortNumber(r->candidate), shortNumber(repeated)));
            return;
        }
    }
    r->accepted.push_back(r->candidate);
    r->choosing = false;
    thresholdsUi->labelMessage->clear();
    writeThresholds();
    recompute();
    refresh();
}

bool TaskExtraction::startChoosing(Region& r, double lower, double upper, bool down)
{
    r.lower = lower;
    r.upper = upper;
    r.seen.clear();
    r.candidate = none;
    return findCandidate(r, lower, upper, down);
}

bool TaskExtraction::findCandidate(Region& r, double lower, double upper, bool down)
{
    const featurelines::RegionGeometry* g = nullptr;
    try {
        g = &FeatureLines::regionGeometry(analysis, r.id);
    } catch (const std::invalid_argument& e) {
        r.note = QString::fromUtf8(e.what());
        return false;
    }
    // Each pass narrows the range past the threshold it rejects; the Automatic mode's limit of
    // searches bounds them.
    QStringList repeats;
    for (int pass = 0; pass < std::max(1, input.options.smooth.automatic.maxSearches); ++pass) {
        Region trial = r;
        if (!search(trial, lower, upper)) {
            r.note = repeats.isEmpty() ? trial.note
                                       : tr("the only valleys there (%1) repeat the lines of an "
                                            "accepted threshold")
                                             .arg(repeats.join(QLatin1String(", ")));
            return false;
        }
        const double t = trial.candidate;
        if (std::isnan(FeatureLines::repeatedThreshold(*g, input.options.smooth, t, r.accepted))) {
            r.candidate = t;
            r.note.clear();
            r.seen.insert(std::upper_bound(r.seen.begin(), r.seen.end(), t), t);
            return true;
        }
        repeats << shortNumber(t);
        // Beyond the repeated one, the way the search goes; no progress: nothing beyond.
        if (down ? !(t < upper || std::isnan(upper)) : !(t > lower || std::isnan(lower))) {
            break;
        }
        (down ? upper : lower) = t;
    }
    r.note = tr("the only valleys there (%1) repeat the lines of an accepted threshold")
                 .arg(repeats.join(QLatin1String(", ")));
    return false;
}

void TaskExtraction::stepCandidate(bool higher)
{
    Region* r = currentRegion();
    if (!r || !r->choosing || !std::isfinite(r->candidate)) {
        return;
    }
    // The history first: the nearest candidate of this stage that way.
    const auto next = higher ? std::upper_bound(r->seen.begin(), r->seen.end(), r->candidate)
                             : std::lower_bound(r->seen.begin(), r->seen.end(), r->candidate);
    if (higher && next != r->seen.end()) {
        r->candidate = *next;
    } else if (!higher && next != r->seen.begin()) {
        r->candidate = *std::prev(next);
    } else {
        // Sec. 2.3: a new search in the values below (above) the candidate, between the
        // accepted thresholds around it.
        Region trial = *r;
        const bool found = higher ? findCandidate(trial, r->candidate, r->upper, false)
                                  : findCandidate(trial, r->lower, r->candidate, true);
        if (!found) {
            thresholdsUi->labelMessage->setText(
                (higher ? tr("No higher level found (no valley above): %1. The proposal stays.")
                        : tr("No lower level found (no valley below): %1. The proposal stays."))
                    .arg(trial.note));
            refresh();
            return;
        }
        *r = trial;
    }
    thresholdsUi->labelMessage->clear();
    refresh();
}

const std::vector<double>& TaskExtraction::thresholdsInUse(Region& r)
{
    if (!r.accepted.empty()) {
        return r.accepted;
    }
    if (!r.automaticKnown) {
        r.automatic.clear();
        try {
            r.automatic = FeatureLines::automaticRegionThresholds(
                FeatureLines::regionGeometry(analysis, r.id), input.options.smooth);
        } catch (const std::invalid_argument&) {
            // No valley, no region: no automatic threshold either.
        }
        r.automaticKnown = true;
    }
    return r.automatic;
}

QString TaskExtraction::untouchedRegionsNote()
{
    if (regions.size() < 2) {
        return {};
    }
    QStringList kept;
    QStringList without;
    for (Region& r : regions) {
        if (!r.accepted.empty()) {
            continue;
        }
        QStringList values;
        for (double t : thresholdsInUse(r)) {
            values << shortNumber(t);
        }
        if (values.isEmpty()) {
            without << QString::number(r.id);
        } else {
            kept << tr("%1 (%2)").arg(r.id).arg(values.join(QLatin1String(", ")));
        }
    }
    QString note;
    if (!kept.isEmpty()) {
        note += tr("Regions without a threshold of yours keep the automatic ones: %1.")
                    .arg(kept.join(QLatin1String("; ")));
    }
    if (!without.isEmpty()) {
        note += (note.isEmpty() ? QString() : QStringLiteral(" ")) +
                tr("<b>No smooth lines</b> in region(s) %1: no threshold of yours and no automatic "
                   "one.")
                    .arg(without.join(QLatin1String(", ")));
    }
    return note;
}

void TaskExtraction::backToLines()
{
    Region* r = currentRegion();
    if (r && !r->accepted.empty()) {
        r->choosing = false;
        thresholdsUi->labelMessage->clear();
        refresh();
    }
}

void TaskExtraction::addThreshold(bool higher)
{
    Region* r = currentRegion();
    if (!r || r->accepted.empty()) {
        return;
    }
    // Sec. 2.3: the histogram of the values below the lowest accepted threshold (Fig. 5), or
    // above the highest.
    const auto [lo, hi] = std::minmax_element(r->accepted.begin(), r->accepted.end());
    Region trial = *r;
    trial.choosing = true;
    // Going away from the accepted threshold it starts at, past any that would repeat it.
    if (startChoosing(trial, higher ? *hi : none, higher ? none : *lo, !higher)) {
        *r = trial;
        thresholdsUi->labelMessage->clear();
    } else {
        thresholdsUi->labelMessage->setText((higher
                                                 ? tr("No higher level found (no valley above): %1")
                                                 : tr("No lower level found (no valley below): %1"))
                                                .arg(trial.note));
    }
    refresh();
}

void TaskExtraction::chooseValue(double value)
{
    Region* r = currentRegion();
    if (!r || !std::isfinite(value) ||
        std::find(r->accepted.begin(), r->accepted.end(), value) != r->accepted.end()) {
        return;
    }
    // The user's own threshold: bounded by the accepted ones around it, as a searched one is.
    r->lower = none;
    r->upper = none;
    for (double a : r->accepted) {
        if (a < value && !(a <= r->lower)) {
            r->lower = a;
        }
        if (a > value && !(a >= r->upper)) {
            r->upper = a;
        }
    }
    r->candidate = value;
    r->choosing = true;
    r->note.clear();
    r->seen.assign(1, value);
    thresholdsUi->labelMessage->setText(tr("Level chosen in the histogram."));
    refresh();
}

void TaskExtraction::done()
{
    // Closing deletes this dialog and its buttons: not from inside the button's own signal.
    QTimer::singleShot(0, &Gui::Control(), [] { Gui::Control().accept(); });
}

void TaskExtraction::doneFitSurfaces()
{
    // As done(), then the command Fit surfaces on this object once the panel is closed.
    const std::string doc = documentName;
    const std::string name = object.getObjectName();
    QTimer::singleShot(0, &Gui::Control(), [doc, name] {
        Gui::Control().accept();
        App::Document* d = App::GetApplication().getDocument(doc.c_str());
        if (!d || !d->getObject(name.c_str()) || Gui::Control().activeDialog()) {
            return;
        }
        Gui::Selection().clearSelection();
        Gui::Selection().addSelection(doc.c_str(), name.c_str());
        Gui::Application::Instance->commandManager().runCommandByName("FeatureLines_FitSurfaces");
    });
}

// ---- The document ---------------------------------------------------------------------------

std::string TaskExtraction::objectCommand() const
{
    return "App.getDocument('" + documentName + "').getObject('" + object.getObjectName() + "')";
}

bool TaskExtraction::runLine(const std::string& command, bool gui)
{
    try {
        Gui::Command::doCommand(gui ? Gui::Command::Gui : Gui::Command::Doc, "%s", command.c_str());
        return true;
    } catch (const Base::Exception& e) {
        thresholdsUi->labelMessage->setText(QString::fromUtf8(e.what()));
        Base::Console().Error("FeatureLines: %s\n", e.what());
        return false;
    }
}

void TaskExtraction::writeThresholds()
{
    auto list = [](std::vector<double> values) {
        std::sort(values.begin(), values.end(), std::greater<double>());
        return values;
    };
    const std::string obj = objectCommand();
    runLine(obj + ".ThresholdMode = 'Explicit'");
    if (regions.size() == 1) {
        std::string text;
        for (double t : list(regions.front().accepted)) {
            text += (text.empty() ? "" : ", ") + pythonNumber(t);
        }
        runLine(obj + ".Thresholds = [" + text + "]");
        runLine(obj + ".RegionThresholds = {}");
        return;
    }
    // Several regions: each its own list. A region without an accepted threshold keeps the
    // thresholds the Automatic mode gives it (its lines do not vanish because another region
    // went Explicit); one without those either gets none (Thresholds empty).
    std::string map;
    for (Region& r : regions) {
        const std::vector<double>& thresholds = thresholdsInUse(r);
        if (thresholds.empty()) {
            continue;
        }
        std::string text;
        for (double t : list(thresholds)) {
            text += (text.empty() ? "" : " ") + pythonNumber(t);
        }
        map += (map.empty() ? "'" : ", '") + std::to_string(r.id) + "': '" + text + "'";
    }
    runLine(obj + ".Thresholds = []");
    runLine(obj + ".RegionThresholds = {" + map + "}");
}

bool TaskExtraction::recompute()
{
    if (!runLine("App.getDocument('" + documentName + "').recompute()")) {
        return false;
    }
    FeatureLines::Extraction* e = extraction();
    if (e && !e->isValid()) {
        // The object keeps its last good lines; the message says why this recompute failed.
        thresholdsUi->labelMessage->setText(
            tr("Recompute failed: %1").arg(QString::fromUtf8(e->getStatusString())));
        return false;
    }
    return true;
}

bool TaskExtraction::accept()
{
    closing = true;
    run->cancelAndWait();
    closePreview();
    FeatureLines::Extraction* e = extraction();
    if (e && needsRecompute(*e)) {
        // OK before any threshold was accepted keeps the object in its mode (Automatic for a
        // new one): it is computed as it stands.
        runLine("App.getDocument('" + documentName + "').recompute()");
    }
    Gui::Command::commitCommand();
    runLine("Gui.getDocument('" + documentName + "').resetEdit()", true);
    return true;
}

bool TaskExtraction::reject()
{
    closing = true;
    run->cancelAndWait();
    closePreview();
    // Back to the document as it was before the panel opened: a new object goes again. Before
    // resetEdit, which commits the transaction still open (Gui::Document::resetEdit).
    Gui::Command::abortCommand();
    runLine("Gui.getDocument('" + documentName + "').resetEdit()", true);
    return true;
}

// ---- What the panel shows -------------------------------------------------------------------

TaskExtraction::Region* TaskExtraction::currentRegion()
{
    if (current < 0 || current >= static_cast<int>(regions.size())) {
        return nullptr;
    }
    return &regions[static_cast<size_t>(current)];
}

const featurelines::RegionGeometry* TaskExtraction::currentGeometry() const
{
    if (!analysed || current < 0 || current >= static_cast<int>(regions.size())) {
        return nullptr;
    }
    try {
        return &FeatureLines::regionGeometry(analysis, regions[static_cast<size_t>(current)].id);
    } catch (const std::invalid_argument&) {
        return nullptr;
    }
}

double TaskExtraction::focusThreshold(const Region& r) const
{
    if (r.choosing) {
        return r.candidate;
    }
    return r.accepted.empty() ? none : r.accepted.back();
}

void TaskExtraction::refresh()
{
    if (closing) {
        return;
    }
    refreshHistogram();
    refreshPreview();
    refreshStage();
}

void TaskExtraction::refreshHistogram()
{
    HistogramWidget* h = thresholdsUi->histogram;
    const featurelines::RegionGeometry* g = currentGeometry();
    const Region* r = currentRegion();
    if (!g || !r) {
        h->clear();
        if (analysed) {
            h->setMessage(tr("No smooth region: the cloud has no curvature histogram."));
        }
        return;
    }
    const FeatureLines::RegionHistogram rh =
        FeatureLines::regionHistogram(*g, input.options.smooth);
    h->setHistogram(std::vector<double>(rh.counts.begin(), rh.counts.end()), rh.minimum,
                    rh.binWidth);
    h->setOutlierCut(rh.outlierCut);
    h->setThresholds(r->choosing ? r->candidate : none, r->accepted);
}

void TaskExtraction::refreshStage()
{
    Ui_TaskExtractionThresholds& t = *thresholdsUi;
    const Region* r = currentRegion();
    // For scripts and tests: the state the texts describe, as numbers.
    thresholdsWidget->setProperty("stage", QString::fromLatin1(r ? (r->choosing ? "a" : "b") : ""));
    thresholdsWidget->setProperty("candidate", r && r->choosing ? r->candidate : none);
    thresholdsWidget->setProperty("region", r ? r->id : -1);
    if (!analysed || !r) {
        t.labelStage->setText(analysed ? tr("The cloud has no part between sharp edges (smooth "
                                            "region) to look for fillet borders in.")
                                       : tr("The curvature levels follow the analysis above."));
        t.stageStack->setEnabled(false);
        t.buttonBack->setVisible(false);
        return;
    }
    t.stageStack->setEnabled(true);
    QStringList accepted;
    for (double a : r->accepted) {
        accepted << shortNumber(a);
    }
    if (r->choosing) {
        t.stageStack->setCurrentWidget(t.pageCandidate);
        const bool has = std::isfinite(r->candidate);
        t.buttonAccept->setEnabled(has);
        t.buttonLower->setEnabled(has);
        t.buttonHigher->setEnabled(has);
        t.buttonBack->setVisible(!r->accepted.empty());
        if (!has) {
            t.labelStage->setText(tr("<b>No candidate threshold</b> (no curvature level to "
                                     "propose): %1. Click in the histogram "
                                     "to choose one.")
                                      .arg(r->note.toHtmlEscaped()));
            return;
        }
        QString counts;
        if (labelCounts.size() == 4) {
            counts = tr("<br>Points: %1 flatter (low), %2 more curved (inner), %3 at the change "
                        "(border), %4 isolated (noisy).")
                         .arg(labelCounts[0])
                         .arg(labelCounts[1])
                         .arg(labelCounts[2])
                         .arg(labelCounts[3]);
        }
        t.labelStage->setText(
            tr("<b>Proposed curvature level %1</b> (threshold \u03c4)%2. Do the green areas "
               "ringed in black show the fillets or corners you want lines around? Accept, or "
               "try a lower or higher level.%3")
                .arg(shortNumber(r->candidate))
                .arg(accepted.isEmpty()
                         ? QString()
                         : tr("; accepted: %1").arg(accepted.join(QLatin1String(", "))))
                .arg(counts));
        return;
    }
    t.stageStack->setCurrentWidget(t.pageLines);
    int lines = 0;
    int closed = 0;
    if (const FeatureLines::Extraction* e = extraction()) {
        std::tie(lines, closed) = regionLines(*e, r->id);
    }
    const QString others = untouchedRegionsNote();
    t.labelStage->setText(tr("<b>%1 smooth line(s), %2 closed</b> (fillet borders) at curvature "
                             "level \u03c4 = %3. Are all the lines there? Done, or add a level "
                             "for lines between flatter or more curved surfaces.")
                              .arg(lines)
                              .arg(closed)
                              .arg(accepted.join(QLatin1String(", "))) +
                          (others.isEmpty() ? QString() : QStringLiteral("<br>") + others));
}

std::vector<int> TaskExtraction::labelsPerInputPoint(const Region* r,
                                                     const featurelines::RegionGeometry* g)
{
    labelCounts.clear();
    std::vector<int> perInput(worldPoints.size(), -1);
    if (r && g && std::isfinite(focusThreshold(*r))) {
        const std::vector<int> values = FeatureLines::labelValues<int>(
            FeatureLines::regionLabels(*g, focusThreshold(*r), input.options.smooth));
        labelCounts.assign(4, 0);
        for (int value : values) {
            if (value >= 0 && value < 4) {
                ++labelCounts[static_cast<size_t>(value)];
            }
        }
        if (perInput.size() == analysis.geometry->inputToPoint.size()) {
            FeatureLines::scatterToInputPoints(*analysis.geometry, *g, values, perInput);
        }
    } else if (g && perInput.size() == analysis.geometry->inputToPoint.size()) {
        // No threshold yet: every point of the region is low, which shows where it lies.
        FeatureLines::scatterToInputPoints(*analysis.geometry, *g,
                                           std::vector<int>(g->members.size(), 0), perInput);
    }
    return perInput;
}

void TaskExtraction::refreshPreview()
{
    Ui_TaskExtractionThresholds& t = *thresholdsUi;
    const auto mode = static_cast<PreviewMode>(t.comboPreview->currentIndex());
    const Region* r = currentRegion();
    const featurelines::RegionGeometry* g = currentGeometry();
    // The label counts are shown with the candidate whatever the preview shows.
    const std::vector<int> perInput = labelsPerInputPoint(r, g);
    if (mode == PreviewMode::Off || !analysed || worldPoints.empty()) {
        t.labelLegend->clear();
        if (preview) {
            preview->remove();
        }
        return;
    }
    std::vector<Base::Vector3f> colours(worldPoints.size());
    if (mode == PreviewMode::Labels) {
        for (size_t i = 0; i < colours.size(); ++i) {
            colours[i] = PointPreview::labelColour(perInput[i]);
        }
        QString legend;
        const char* names[] = {QT_TR_NOOP("flatter (low)"), QT_TR_NOOP("curved (inner)"),
                               QT_TR_NOOP("change (border)"), QT_TR_NOOP("isolated (noisy)")};
        for (int l = 0; l < 4; ++l) {
            legend += QString::fromUtf8("<span style=\"color:%1\">\u25a0</span> %2&nbsp;&nbsp; ")
                          .arg(colourName(PointPreview::labelColour(l)), tr(names[l]));
        }
        if (regions.size() > 1) {
            legend += QString::fromUtf8("<span style=\"color:%1\">\u25a0</span> %2")
                          .arg(colourName(PointPreview::labelColour(-1)), tr("other regions"));
        }
        t.labelLegend->setText(legend);
    } else {
        // Every region's patches at its accepted thresholds (and the candidate).
        std::vector<int> patch(worldPoints.size(), -1);
        int next = 0;
        for (const Region& region : regions) {
            std::vector<double> levels = region.accepted;
            if (region.choosing && std::isfinite(region.candidate)) {
                levels.push_back(region.candidate);
            }
            const featurelines::RegionGeometry& rg =
                FeatureLines::regionGeometry(analysis, region.id);
            std::vector<int> patchOf;
            next = featurelines::labelPatches(rg, levels, next, patchOf);
            FeatureLines::scatterToInputPoints(*analysis.geometry, rg, patchOf, patch);
        }
        for (size_t i = 0; i < colours.size(); ++i) {
            colours[i] = PointPreview::patchColour(patch[i]);
        }
        t.labelLegend->setText(tr("%1 surface patch(es): connected points between the same two "
                                  "curvature levels.")
                                   .arg(next));
    }
    if (preview) {
        try {
            preview->show(worldPoints, colours);
        } catch (const std::exception& e) {
            Base::Console().Error("FeatureLines preview: %s\n", e.what());
        }
    }
}

void TaskExtraction::closePreview()
{
    if (preview) {
        preview->remove();
        preview.reset();
    }
}
