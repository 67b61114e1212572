// SPDX-License-Identifier: LGPL-2.1-or-later
// The task panel of a FeatureLines::Extraction: the user-guided thresholding of Sec. 2.3 of
// Demarsin et al. (2008).
//
// "Analysis" box: the main options (tool tips: the parameters' documentation), Run, progress and
// Cancel. The analysis (neighbours, normals, sharp edges, smooth regions and their curvature) runs
// in a worker thread (AnalysisRun) and lands in the App module's cache; option changes reach the
// document only when a run succeeds.
//
// "Curvature thresholds" box, per smooth region (a selector when the sharp edges divide the
// cloud into several): the region's histogram with the candidate and the accepted thresholds and
// the outlier cut, and the two stages of Sec. 2.3:
//  (a) a candidate threshold, the points coloured by their Sec. 3 labels at it (Fig. 7 a) or by
//      patch: Accept, or Lower / Higher (the next valley below / above it, between the accepted
//      thresholds around it);
//  (b) the closed lines of the accepted thresholds: Done, or Add lower / higher threshold (the
//      next valley below the lowest / above the highest accepted one), which goes back to (a).
// Every accepted threshold is written to the object (ThresholdMode "Explicit" with Thresholds,
// or RegionThresholds when there are several regions) and the document recomputed, through
// doCommand: macro lines, inside the one transaction of the panel. OK commits it, Cancel aborts
// it (a new object goes, an edited one is as before). The preview is removed either way.
#pragma once

#include <App/DocumentObserver.h>
#include <Base/Vector3D.h>
#include <Gui/TaskView/TaskDialog.h>

#include <QElapsedTimer>
#include <QString>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "InteractiveThresholds.h"

class QWidget;
class Ui_TaskExtractionOptions;
class Ui_TaskExtractionThresholds;

namespace App {
class DocumentObject;
}
namespace FeatureLines {
class Extraction;
}

namespace FeatureLinesGui {

class AnalysisRun;
class PointPreview;
class ViewProviderExtraction;

class TaskExtraction : public Gui::TaskView::TaskDialog
{
    Q_OBJECT

public:
    explicit TaskExtraction(ViewProviderExtraction* view);
    ~TaskExtraction() override;

    /// The edited object; nullptr once it is deleted.
    App::DocumentObject* getObject() const;

    void open() override;
    bool accept() override;
    bool reject() override;
    bool isAllowedAlterDocument() const override { return false; }
    QDialogButtonBox::StandardButtons getStandardButtons() const override
    {
        return QDialogButtonBox::Ok | QDialogButtonBox::Cancel;
    }

private:
    /// The thresholding state of one smooth region.
    struct Region
    {
        int id = 0;
        int points = 0;
        /// Accepted thresholds, in the order accepted.
        std::vector<double> accepted;
        /// Stage (a) (a candidate to accept) or (b) (the lines of the accepted ones).
        bool choosing = true;
        double candidate = 0.0;
        /// The candidate is searched among the values in (lower, upper]: the accepted
        /// thresholds around it (NaN: none).
        double lower = 0.0;
        double upper = 0.0;
        /// Why there is no candidate, or why the last search found none.
        QString note;
        /// The candidates of this stage (a), low to high: Lower and Higher step through them
        /// before they search further, so Lower then Higher comes back where it started.
        std::vector<double> seen;
        /// The thresholds of the Automatic mode, which a region without an accepted threshold
        /// keeps (computed when first needed).
        std::vector<double> automatic;
        bool automaticKnown = false;
    };

    enum class PreviewMode
    {
        Labels = 0,
        Patches = 1,
        Off = 2,
    };

    FeatureLines::Extraction* extraction() const;
    void buildOptions();
    void connectWidgets();
    FeatureLines::ParameterValues changedOptions() const;

    void startRun();
    void runFinished();
    void setRunning(bool running);
    /// The bar at `percent`, the stage and the time left (secondsLeft) in the status line.
    void showProgress(int percent, const QString& stage);
    void setRunState(const char* state);
    void adoptAnalysis();
    void initialiseRegions();

    /// Sec. 2.3: the candidate of `r` among the values in (lower, upper]; false (and the note
    /// set) when those values have no valley.
    bool search(Region& r, double lower, double upper);
    /// Stage (a) of `r` between `lower` and `upper` (NaN: open): a new history, and its first
    /// candidate (findCandidate, going `down` from upper or up from lower).
    bool startChoosing(Region& r, double lower, double upper, bool down);
    /// The valley search in (lower, upper], passing over every threshold that repeats an
    /// accepted one (repeatedThreshold: the same patches) towards lower (`down`) or upper;
    /// the candidate found joins the history. False (and the note set) when none is left.
    bool findCandidate(Region& r, double lower, double upper, bool down);
    /// Lower (`higher` false) or Higher: the next candidate of the history that way, or a new
    /// search beyond the last.
    void stepCandidate(bool higher);
    /// The thresholds the lines of region `r` use: its accepted ones, or the Automatic mode's.
    const std::vector<double>& thresholdsInUse(Region& r);
    /// "Regions 1, 3 keep the automatic thresholds..." for the regions without an accepted
    /// threshold; empty with one region.
    QString untouchedRegionsNote();
    void acceptCandidate();
    void backToLines();
    void addThreshold(bool higher);
    void chooseValue(double value);
    void done();
    /// Done, then the surfaces of the lines' patches (the command Fit surfaces) and their panel.
    void doneFitSurfaces();

    /// ThresholdMode = Explicit and the accepted thresholds, then a recompute: macro lines.
    void writeThresholds();
    bool recompute();
    bool runLine(const std::string& command, bool gui = false);
    std::string objectCommand() const;

    void refresh();
    void refreshHistogram();
    void refreshStage();
    void refreshPreview();
    /// The Sec. 3 labels of the current region at its focus threshold per input point (-1
    /// outside it; all low without a threshold); sets labelCounts.
    std::vector<int> labelsPerInputPoint(const Region* r, const featurelines::RegionGeometry* g);
    void closePreview();

    Region* currentRegion();
    const featurelines::RegionGeometry* currentGeometry() const;
    double focusThreshold(const Region& r) const;

    App::DocumentObjectT object;
    std::string documentName;

    QWidget* optionsWidget = nullptr;
    QWidget* thresholdsWidget = nullptr;
    std::unique_ptr<Ui_TaskExtractionOptions> optionsUi;
    std::unique_ptr<Ui_TaskExtractionThresholds> thresholdsUi;
    /// The option widgets by parameter name (QSpinBox, QDoubleSpinBox, QCheckBox, QComboBox).
    std::map<std::string, QWidget*> optionWidgets;

    AnalysisRun* run = nullptr;
    /// Time since the run started, for the time left; whether Cancel run was pressed.
    QElapsedTimer runClock;
    bool cancelling = false;
    bool analysed = false;
    bool regionsInitialised = false;
    FeatureLines::CloudAnalysis analysis;
    FeatureLines::ExtractionInput input;
    std::vector<Base::Vector3f> worldPoints;

    std::vector<Region> regions;
    int current = 0;
    /// Points of the current region per label (low, inner, border, noisy) at its focus threshold.
    std::vector<int> labelCounts;
    std::unique_ptr<PointPreview> preview;
    bool closing = false;
};

} // namespace FeatureLinesGui
