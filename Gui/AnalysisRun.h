// SPDX-License-Identifier: LGPL-2.1-or-later
// The expensive part of an extraction (neighbours, normals, sharp edges, smooth regions and their
// curvature: the two cached steps of App/ExtractionCache.h) run in a worker thread, so the task
// panel stays responsive, shows progress and can cancel through the core's progress callback.
// The document object recomputes afterwards in the GUI thread and finds the analysis cached.
#pragma once

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

#include "InteractiveThresholds.h"

class QThread;

namespace FeatureLinesGui {

class AnalysisRun : public QObject
{
    Q_OBJECT

public:
    explicit AnalysisRun(QObject* parent = nullptr);
    /// Cancels a run still going and waits for its thread (the core sees the request at its
    /// next stage).
    ~AnalysisRun() override;

    /// Starts analysing `input` (which the run keeps). Only one run at a time: a second start
    /// while one is going is ignored and returns false.
    bool start(FeatureLines::ExtractionInput input);
    /// Asks the running analysis to stop at its next stage; finished() follows.
    void cancel();
    /// Cancels and blocks until the thread has ended (for a dialog that closes).
    void cancelAndWait();
    bool isRunning() const;

    struct Outcome
    {
        enum Status
        {
            Done,
            Cancelled,
            Failed,
        } status = Failed;
        /// Failed: the core's message (bad cloud or option).
        QString message;
        FeatureLines::CloudAnalysis analysis;
        FeatureLines::ExtractionInput input;
    };
    /// The last run's outcome, valid after finished().
    const Outcome& outcome() const { return last; }

Q_SIGNALS:
    /// Share done in percent and the stage's name, from the core's progress callback.
    void progressed(int percent, const QString& stage);
    void finished();

private:
    void onThreadFinished();

    QThread* thread = nullptr;
    std::atomic<bool> cancelRequested{false};
    Outcome last;
};

} // namespace FeatureLinesGui
