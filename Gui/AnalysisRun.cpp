// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "AnalysisRun.h"
#include "ExtractionProgress.h"

#include <QThread>

#include <cmath>
#include <exception>
#include <stdexcept>

using namespace FeatureLinesGui;

AnalysisRun::AnalysisRun(QObject* parent) : QObject(parent) {}

AnalysisRun::~AnalysisRun()
{
    cancelAndWait();
}

bool AnalysisRun::start(FeatureLines::ExtractionInput input)
{
    if (isRunning()) {
        return false;
    }
    if (thread) {
        thread->deleteLater();
        thread = nullptr;
    }
    cancelRequested = false;
    last = Outcome{};
    last.input = std::move(input);
    // The worker writes `last` only; the GUI thread reads it after QThread::finished, which
    // is delivered once the worker has returned.
    thread = QThread::create([this] {
        FeatureLines::ExtractionInput& in = last.input;
        in.options.progress = [this](double done, const std::string& stage) {
            // A script's observer (FeatureLines.setProgressObserver) sees and may cancel the
            // panel's runs as it does a recompute's.
            if (cancelRequested || !FeatureLines::notifyProgressObserver(done, stage)) {
                return false;
            }
            Q_EMIT progressed(static_cast<int>(std::lround(100.0 * done)),
                              QString::fromStdString(stage));
            return true;
        };
        try {
            last.analysis = FeatureLines::analyseCached(in.points, in.cloudHash, in.options);
            // A cancel after the core's last stage report: the user asked to stop, so the
            // result is not used (it stays in the cache for the next run).
            last.status = cancelRequested ? Outcome::Cancelled : Outcome::Done;
        } catch (const featurelines::ExtractionCancelled&) {
            last.status = Outcome::Cancelled;
        } catch (const std::exception& e) {
            last.status = Outcome::Failed;
            last.message = QString::fromUtf8(e.what());
        }
        in.options.progress = nullptr;
    });
    connect(thread, &QThread::finished, this, &AnalysisRun::onThreadFinished);
    thread->start();
    return true;
}

void AnalysisRun::cancel()
{
    cancelRequested = true;
}

void AnalysisRun::cancelAndWait()
{
    if (!thread) {
        return;
    }
    cancel();
    thread->wait();
    // finished() is not emitted to a dialog that is closing: the thread is simply gone.
    disconnect(thread, nullptr, this, nullptr);
    delete thread;
    thread = nullptr;
}

bool AnalysisRun::isRunning() const
{
    return thread && thread->isRunning();
}

void AnalysisRun::onThreadFinished()
{
    Q_EMIT finished();
}
