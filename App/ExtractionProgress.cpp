// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "ExtractionProgress.h"

#include <Base/Console.h>
#include <Base/Exception.h>
#include <Base/Interpreter.h>
#include <CXX/Objects.hxx>

#include <algorithm>
#include <atomic>

namespace FeatureLines {

namespace {

constexpr size_t totalSteps = 100;

/// The observer, with a reference held (never released at exit: the interpreter may be gone);
/// nullptr when none is set.
std::atomic<PyObject*> observer{nullptr};

} // namespace

void setProgressObserver(PyObject* callable)
{
    Base::PyGILStateLocker lock;
    Py_XDECREF(observer.exchange(nullptr));
    if (callable && callable != Py_None) {
        Py_INCREF(callable);
        observer = callable;
    }
}

bool notifyProgressObserver(double done, const std::string& stage)
{
    // Without an observer no lock is taken: a worker thread then never waits for the
    // interpreter.
    if (!observer.load()) {
        return true;
    }
    Base::PyGILStateLocker lock;
    PyObject* callable = observer.load();
    if (!callable) {
        return true;
    }
    try {
        Py::Callable call(callable);
        Py::Tuple args(2);
        args.setItem(0, Py::Float(done));
        args.setItem(1, Py::String(stage));
        const Py::Object answer = call.apply(args);
        // Only an explicit False cancels: an observer that prints and returns None goes on.
        return !(answer.ptr() == Py_False);
    } catch (Py::Exception&) {
        Base::PyException e; // fetches and clears the Python error
        Base::Console().Error("FeatureLines progress observer failed, cancelling: %s\n", e.what());
        return false;
    }
}

ExtractionProgress::ExtractionProgress(const std::string& title)
    : title(title)
      // Inside a document recompute FreeCAD's own "Recompute..." launcher is the outermost one:
      // this one's steps are then ignored by the sequencer, but a cancel is still seen below.
      ,
      launcher(std::make_unique<Base::SequencerLauncher>(title.c_str(), totalSteps))
{
}

std::function<bool(double, const std::string&)> ExtractionProgress::callback()
{
    return [this](double done, const std::string& stage) { return report(done, stage); };
}

bool ExtractionProgress::report(double done, const std::string& stage)
{
    try {
        launcher->setText((title + ": " + stage).c_str());
        if (nested) {
            // The recompute's bar shows this extraction's share while it runs (the next object
            // puts it back), and setProgress, unlike next, reaches the sequencer from a nested
            // launcher: the GUI then handles its events and Esc is seen by wasCanceled() below.
            launcher->setProgress(static_cast<size_t>(done * launcher->numberOfSteps()));
        }
        const size_t target = std::min(totalSteps, static_cast<size_t>(done * totalSteps));
        while (steps < target) {
            launcher->next(true); // throws Base::AbortException when the user cancels
            ++steps;
        }
    } catch (const Base::AbortException&) {
        return false;
    }
    if (launcher->wasCanceled()) {
        return false;
    }
    return notifyProgressObserver(done, stage);
}

} // namespace FeatureLines
