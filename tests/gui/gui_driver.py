# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the Gui tests share: steps run one after another from Qt's event loop, widgets of the
task panel found by object name and clicked as a user clicks them, screenshots, and a real exit
code.

FreeCAD runs a script given on its command line inside the GUI (it imports it, and runs it once
more when the import raises): a test script only schedules its steps and returns; the steps run
while FreeCAD's event loop turns, so the interface stays live between them (a worker thread's
signals arrive, the 3D view redraws). Every outcome ends the process with os._exit: 0 when all
steps passed, 1 on a failed check (after a screenshot of the failure), 2 when a step waited in
vain, 3 when the whole test ran over its time limit.
"""

import os
import re
import subprocess
import sys
import tempfile
import time
import traceback

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

SCREENSHOTS = os.environ.get("FEATURELINES_SCREENSHOTS") or tempfile.gettempdir()
APP_TESTS = os.environ.get("FEATURELINES_APP_TEST_DIR")
if APP_TESTS and APP_TESTS not in sys.path:
    sys.path.insert(0, APP_TESTS)

NaN = float("nan")


def log(text):
    """To the terminal (FreeCAD sends sys.stdout to its report view)."""
    sys.__stdout__.write(text + "\n")
    sys.__stdout__.flush()


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


# ---- Widgets ------------------------------------------------------------------------------

def main_window():
    return FreeCADGui.getMainWindow()


def find(cls, name):
    widget = main_window().findChild(cls, name)
    check(widget is not None, "no %s named %s" % (cls.__name__, name))
    return widget


def button(name):
    return find(QtWidgets.QPushButton, name)


def click(name):
    """Clicks a push button of the panel as a user does: it must be visible and enabled."""
    b = button(name)
    check(b.isVisible(), "button %s is not visible" % name)
    check(b.isEnabled(), "button %s is not enabled" % name)
    log("click %s" % name)
    b.click()


def label(name):
    return find(QtWidgets.QLabel, name).text()


def thresholds_panel():
    return find(QtWidgets.QWidget, "TaskExtractionThresholds")


def stage():
    """'a' (a candidate to accept) or 'b' (the lines of the accepted thresholds)."""
    return thresholds_panel().property("stage")


def candidate():
    value = thresholds_panel().property("candidate")
    return NaN if value is None else float(value)


def panel_is_open():
    return bool(FreeCADGui.Control.activeDialog())


def run_state():
    """Where the panel's last analysis stands: idle, running, done, cancelled or failed."""
    if not panel_is_open():
        return None
    options = main_window().findChild(QtWidgets.QWidget, "TaskExtractionOptions")
    return None if options is None else options.property("run")


def analysis_finished():
    """The panel's run is over and its outcome shown."""
    return run_state() in ("done", "cancelled", "failed")


def analysis_running():
    return run_state() == "running"


def choose_in_histogram(value):
    """What a click in the histogram at curvature `value` does: the widget's valueClicked
    signal, emitted as the click emits it."""
    histogram = find(QtWidgets.QWidget, "histogram")
    log("choose %r in the histogram" % value)
    check(QtCore.QObject.emit(histogram, QtCore.SIGNAL("valueClicked(double)"), value),
          "the histogram has no signal valueClicked(double)")


def press_dialog_button(which):
    """Presses OK or Cancel of the open task dialog ('ok' or 'cancel'), as a user does."""
    role = {"ok": QtWidgets.QDialogButtonBox.Ok, "cancel": QtWidgets.QDialogButtonBox.Cancel}
    for box in main_window().findChildren(QtWidgets.QDialogButtonBox):
        b = box.button(role[which])
        if b is not None and b.isVisible():
            log("press %s of the task dialog" % which)
            b.click()
            return
    raise Failure("no visible %s button of a task dialog" % which)


def select_option(name, index):
    """Chooses entry `index` of the panel's combo box `name`."""
    find(QtWidgets.QComboBox, name).setCurrentIndex(index)


def fold_task_box(content_name):
    """Folds the task box holding the widget `content_name`, as a click on its header does."""
    widget = find(QtWidgets.QWidget, content_name)
    while widget is not None and widget.metaObject().className() != "Gui::TaskView::TaskBox":
        widget = widget.parentWidget()
    check(widget is not None, "%s is in no task box" % content_name)
    QtCore.QMetaObject.invokeMethod(widget, "showHide")


def capture_message_box(action, screenshot_name=None):
    """Runs `action`, which opens a modal message box: returns its title and text after
    pressing its default button (from a timer, since the box runs its own event loop)."""
    seen = {}

    def grab():
        box = QtWidgets.QApplication.activeModalWidget()
        if isinstance(box, QtWidgets.QMessageBox):
            seen["title"] = box.windowTitle()
            seen["text"] = box.text()
            if screenshot_name:
                screenshot(screenshot_name)
            box.accept()
        elif not seen.get("returned"):
            QtCore.QTimer.singleShot(50, grab)

    QtCore.QTimer.singleShot(50, grab)
    action()
    seen["returned"] = True
    return seen


def start_macro_recording(name):
    """Macro > Macro recording... as a user starts it: the recorder's dialog gets `name` and
    Start. Returns the path of the macro file Std_MacroStopRecord writes."""
    folder = os.path.join(os.path.dirname(SCREENSHOTS), "macros")
    os.makedirs(folder, exist_ok=True)
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Macro").SetString("MacroPath", folder)
    path = os.path.join(folder, name + ".FCMacro")
    if os.path.exists(path):
        os.remove(path)

    def fill():
        dialog = QtWidgets.QApplication.activeModalWidget()
        entry = dialog.findChild(QtWidgets.QLineEdit, "lineEditPath") if dialog else None
        if entry is None:
            QtCore.QTimer.singleShot(50, fill)
            return
        entry.setText(name)
        dialog.findChild(QtWidgets.QPushButton, "buttonStart").click()

    QtCore.QTimer.singleShot(50, fill)
    FreeCADGui.runCommand("Std_DlgMacroRecord")
    return path


def stop_macro_recording(path):
    # Macro > Stop macro recording: its own command in FreeCAD 0.20; from 1.0 on the recording
    # command itself stops a running recording.
    stop = "Std_MacroStopRecord"
    if stop not in FreeCADGui.listCommands():
        stop = "Std_DlgMacroRecord"
    FreeCADGui.runCommand(stop)
    check(os.path.isfile(path), "the recorder wrote " + path)
    with open(path) as f:
        return f.read()


# ---- Screenshots --------------------------------------------------------------------------

def settle(seconds=0.3):
    """Lets the event loop turn a while: the 3D views redraw from timers of their own."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        QtWidgets.QApplication.processEvents()
        time.sleep(0.02)


def screenshot(name):
    """The whole screen (the 3D view included, which QWidget.grab leaves blank)."""
    settle()
    path = os.path.join(SCREENSHOTS, name + ".png")
    subprocess.run(["import", "-window", "root", path], check=True)
    log("screenshot %s" % path)
    return path


def grab_widget(widget, name):
    """One widget as Qt draws it, once its layout has settled (a 3D view inside it would stay
    blank)."""
    settle()
    path = os.path.join(SCREENSHOTS, name + ".png")
    check(widget.grab().save(path), "cannot save " + path)
    log("screenshot %s" % path)
    return path


def view_image(name, width=1000, height=750):
    """The active 3D view alone, on white."""
    path = os.path.join(SCREENSHOTS, name + ".png")
    settle()
    FreeCADGui.activeDocument().activeView().saveImage(path, width, height, "White")
    log("screenshot %s" % path)
    return path


# ---- Set-up -------------------------------------------------------------------------------

def prepare_window():
    """The Feature Lines workbench and no start page, in FreeCAD's default layout on a laptop
    screen: the main window maximized on the 1366 x 768 screen, the combo view (and the task
    panel in it) at the width FreeCAD gives it by itself."""
    FreeCADGui.activateWorkbench("FeatureLinesWorkbench")
    mw = main_window()
    # The start page (a web view still loading) is no part of the test.
    area = mw.findChild(QtWidgets.QMdiArea)
    if area is not None:
        area.closeAllSubWindows()
    # The tests' screen is 1366 x 768 (tests/gui/CMakeLists.txt): maximized, the window fills it.
    mw.showMaximized()
    settle(0.2)
    dock = task_dock()
    log("main window %d x %d, %s %d px wide" % (mw.width(), mw.height(),
                                               dock.objectName() if dock else "task dock",
                                               dock.width() if dock else -1))


def task_dock():
    """The dock that holds FreeCAD's task view. Release difference: FreeCAD 0.20 shows the
    task view as a tab of the "Combo View" dock, FreeCAD 1.0 in a dock of its own ("Tasks")."""
    for dock in main_window().findChildren(QtWidgets.QDockWidget):
        for child in dock.findChildren(QtWidgets.QWidget):
            if child.metaObject().className() == "Gui::TaskView::TaskView":
                return dock
    return None


def narrow_combo_view(width=230):
    """The dock of the task panel (the combo view on 0.20) `width` pixels wide, as a user
    drags it."""
    mw = main_window()
    dock = task_dock()
    check(dock is not None, "no dock holds the task view")
    mw.resizeDocks([dock], [width], QtCore.Qt.Horizontal)
    settle(0.5)
    log("%s %d px wide" % (dock.objectName(), dock.width()))


# What a user reads or clicks in the panel: none may stick out of the panel's visible width.
_PANEL_WIDGETS = (QtWidgets.QAbstractButton, QtWidgets.QComboBox, QtWidgets.QAbstractSpinBox,
                  QtWidgets.QProgressBar, QtWidgets.QLabel)


def check_panel_fits(what):
    """Every visible button, box, label, progress bar and the histogram of the open task panel
    lies whole within the task view's visible width, a button or box at least as wide as its
    text needs, and the histogram at least 150 pixels wide (its ticks and labels readable).
    `what` names the moment in the messages."""
    check_panel_fits_widget(thresholds_panel(), what)


def check_panel_fits_widget(anchor, what):
    """check_panel_fits for the task panel that holds the widget `anchor`; a table in it must
    fit too, at least 150 pixels wide."""
    viewport = anchor
    while viewport is not None and viewport.objectName() != "qt_scrollarea_viewport":
        viewport = viewport.parentWidget()
    check(viewport is not None, "the task panel is in no scroll area")
    content = viewport.findChildren(QtWidgets.QWidget)
    width = viewport.width()
    checked = 0
    for w in content:
        histogram = w.objectName() == "histogram" or isinstance(w, QtWidgets.QTableView)
        if not (histogram or isinstance(w, _PANEL_WIDGETS)) or not w.isVisible():
            continue
        if isinstance(w, QtWidgets.QLabel) and not w.text():
            continue
        if w.objectName().startswith("qt_"):
            continue  # the parts of a spin box or scroll bar
        left = w.mapTo(viewport, QtCore.QPoint(0, 0)).x()
        name = w.objectName() or type(w).__name__
        check(left >= 0 and left + w.width() <= width,
              "%s: %s spans x %d..%d of a %d px wide panel" % (what, name, left,
                                                               left + w.width(), width))
        if isinstance(w, (QtWidgets.QAbstractButton, QtWidgets.QComboBox)):
            check(w.width() >= w.minimumSizeHint().width(),
                  "%s: %s is %d px wide, its text needs %d" % (what, name, w.width(),
                                                               w.minimumSizeHint().width()))
        if histogram:
            check(w.width() >= 150, "%s: %s is only %d px wide" % (what, name, w.width()))
        checked += 1
    check(checked >= 5, "%s: only %d widgets of the panel are visible" % (what, checked))
    log("%s: %d widgets within the %d px panel" % (what, checked, width))


def add_cloud(doc, points, name="Cloud"):
    """A Points feature of (x, y, z) tuples, shown from the isometric direction."""
    import Points

    cloud = doc.addObject("Points::Feature", name)
    cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in points])
    doc.recompute()
    view = FreeCADGui.getDocument(doc.Name).activeView()
    view.viewIsometric()
    view.fitAll()
    return cloud


def wire_centre(wire):
    """The centre of a wire's length (a fitted loop may have a single vertex, so the mean of
    its vertices would lie on it, not inside it)."""
    return wire.CenterOfMass


# ---- Steps --------------------------------------------------------------------------------

class Steps:
    """Steps run in order from the event loop. A step waits (polling every 50 ms) until its
    `wait_for` holds, up to `within` seconds, then runs its action."""

    def __init__(self, name, limit=240):
        self.name = name
        self.limit = limit
        self.steps = []
        self.index = 0
        self.waiting_since = None

    def then(self, description, action=None, wait_for=None, within=60):
        self.steps.append((description, action, wait_for, within))
        return self

    def run(self):
        log("== %s" % self.name)
        stale = os.path.join(SCREENSHOTS, self._slug() + "-failure.png")
        if os.path.exists(stale):
            os.remove(stale)
        QtCore.QTimer.singleShot(0, self._next)
        QtCore.QTimer.singleShot(int(self.limit * 1000), self._over_time)

    def _over_time(self):
        log("FAILED %s: the test ran over %d s" % (self.name, self.limit))
        self._finish(3)

    def _next(self):
        if self.index >= len(self.steps):
            log("PASSED %s (%d steps)" % (self.name, len(self.steps)))
            self._finish(0)
            return
        description, action, wait_for, within = self.steps[self.index]
        try:
            if wait_for is not None and not wait_for():
                if self.waiting_since is None:
                    self.waiting_since = time.monotonic()
                if time.monotonic() - self.waiting_since > within:
                    log("FAILED %s: step '%s' waited %d s in vain" % (self.name, description, within))
                    self._failure_screenshot()
                    self._finish(2)
                    return
                QtCore.QTimer.singleShot(50, self._next)
                return
            self.waiting_since = None
            log("-- %s" % description)
            if action is not None:
                action()
        except BaseException:
            log("FAILED %s: step '%s'\n%s" % (self.name, description, traceback.format_exc()))
            self._failure_screenshot()
            self._finish(1)
            return
        self.index += 1
        QtCore.QTimer.singleShot(20, self._next)

    def _slug(self):
        return re.sub(r"\W+", "_", self.name).strip("_")

    def _failure_screenshot(self):
        try:
            screenshot(self._slug() + "-failure")
        except BaseException:
            pass

    @staticmethod
    def _finish(code):
        sys.__stdout__.flush()
        sys.__stderr__.flush()
        os._exit(code)


# The running steps: Qt's timers hold their callbacks weakly.
_running = []


def start(name, build, limit=240):
    """Builds the steps with build(steps) and runs them; a failure while building ends the
    process too (FreeCAD would otherwise run the script a second time)."""
    try:
        steps = Steps(name, limit)
        _running.append(steps)
        build(steps)
        steps.run()
    except BaseException:
        log("FAILED %s while setting up\n%s" % (name, traceback.format_exc()))
        sys.__stdout__.flush()
        os._exit(1)
