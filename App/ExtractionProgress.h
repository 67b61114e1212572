// SPDX-License-Identifier: LGPL-2.1-or-later
// Progress of an extraction shown through FreeCAD's sequencer (the progress bar of the GUI, the
// console in freecadcmd) and handed to an optional Python observer. Either can cancel: the
// user through the progress bar, a script by returning False from its observer.
#pragma once

#include <Base/Sequencer.h>

#include <functional>
#include <memory>
#include <string>

namespace FeatureLines {

class ExtractionProgress
{
public:
    explicit ExtractionProgress(const std::string& title);
    /// The core's progress callback (ExtractionOptions::progress): false cancels.
    std::function<bool(double, const std::string&)> callback();

private:
    bool report(double done, const std::string& stage);

    std::string title;
    /// Inside a document recompute FreeCAD's own "Recompute..." launcher is the outermost one
    /// and this one's steps are ignored (Base/Sequencer.cpp).
    bool nested = false;
    std::unique_ptr<Base::SequencerLauncher> launcher;
    size_t steps = 0;
};

/// Sets the callable called as observer(fraction_done, stage_name) at every stage of every
/// extraction (document recomputes, FeatureLines.extract() and the task panel's analyses);
/// returning False cancels the run, raising an exception cancels it too. nullptr or None
/// removes it.
void setProgressObserver(PyObject* callable);

/// Calls the observer, if one is set, from any thread (it takes the interpreter lock): false
/// when it cancels the run.
bool notifyProgressObserver(double done, const std::string& stage);

} // namespace FeatureLines
