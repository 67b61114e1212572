// SPDX-License-Identifier: LGPL-2.1-or-later
// The curvature histogram of a smooth region with its thresholds (Sec. 2.2-2.4), drawn with
// QPainter for the task panel. Qt5 Widgets only: no FreeCAD types, no QtCharts.
#pragma once

#include <QString>
#include <QWidget>
#include <vector>

namespace FeatureLinesGui {

/// Bars of a curvature histogram, a curvature axis (1/length), the candidate threshold as a
/// red line with its value, thresholds accepted earlier as grey dashed lines numbered 1, 2 ...
/// (Sec. 2.3 finds them one after the other), and the outlier cut of Sec. 2.4 as a shaded band
/// to the right. Hovering shows a bin's range and count; a click reports the value under the
/// cursor. Colours come from the widget's palette (bars: Highlight, plot: Base, text:
/// WindowText), so a dark theme works; fonts are the widget's own, scaled, never pixel sizes.
///
/// Invalid input never throws from this widget (it is fed from slots): a histogram with a
/// non-finite minimum or a bin width that is not positive shows "no histogram", NaN or
/// negative counts count as 0, non-finite thresholds and cuts are not drawn.
class HistogramWidget : public QWidget
{
    Q_OBJECT
public:
    /// How bar heights grow with the count.
    enum class Scale
    {
        Linear,
        /// sqrt(count): halfway between linear and logarithmic.
        SquareRoot,
        /// log(1 + count), the default. The planes' peak at zero holds most of the points
        /// (Fig. 2, 5): on a linear axis a fillet peak of 1 % of them is 1 % of the height and
        /// the valley before it, where the threshold goes, is invisible. log(1 + count) keeps
        /// every bin holding points visible and a valley between two peaks a visible dip, and
        /// an empty bin at zero height (hence the 1 +). Square root still leaves a fillet peak
        /// 100 times smaller than the planes' at a tenth of the height, its valley a few pixels.
        Log,
    };

    explicit HistogramWidget(QWidget* parent = nullptr);

    /// Bin i counts the values in [minimum + i*binWidth, minimum + (i+1)*binWidth).
    void setHistogram(const std::vector<double>& counts, double minimum, double binWidth);
    /// Values above `cut` were dropped as outliers (Sec. 2.4 of the paper); NaN: none. Drawn as
    /// a shaded band / dashed line with a caption.
    void setOutlierCut(double cut);
    /// The candidate threshold (drawn strong, red) and thresholds accepted earlier (drawn
    /// grey with their order number); NaN current: none.
    void setThresholds(double current, const std::vector<double>& earlier);
    /// Forget the histogram and thresholds: "no histogram" text.
    void clear();
    /// Shown instead of the bars (e.g. "no valley"); an empty text shows the bars again, and
    /// so does the next setHistogram.
    void setMessage(const QString& text);
    /// The y axis scale; Scale::Log by default (see Scale::Log for why).
    void setScale(Scale scale);
    Scale scale() const { return scale_; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

Q_SIGNALS:
    /// The user clicked in the plot: the curvature value under the cursor.
    void valueClicked(double value);

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    /// Where things go at the current size and font: the plot rectangle and the curvature
    /// range it shows.
    struct Layout
    {
        QRectF plot;
        double xMin = 0.0;
        double xMax = 1.0;
        bool valid = false;

        double xOf(double value) const;
        double valueAt(double x) const;
    };

    bool hasBars() const;
    double histogramEnd() const;
    Layout layout() const;
    /// Bar height in 0..1 of the plot height for `count` on the current scale.
    double heightFraction(double count) const;
    /// Widget y of the top of a bar holding `count` values.
    double yOf(const Layout& l, double count) const;
    int binAt(const Layout& l, const QPointF& pos) const;
    QFont tickFont() const;

    void drawAxes(QPainter& p, const Layout& l) const;
    void drawBars(QPainter& p, const Layout& l) const;
    void drawOutlierBand(QPainter& p, const Layout& l) const;
    void drawThresholds(QPainter& p, const Layout& l) const;
    void drawMessage(QPainter& p, const QString& text) const;

    std::vector<double> counts_;
    double minimum_ = 0.0;
    double binWidth_ = 0.0;
    double maxCount_ = 0.0;
    double outlierCut_;
    double current_;
    std::vector<double> earlier_;
    QString message_;
    Scale scale_ = Scale::Log;
    int hoveredBin_ = -1;
};

} // namespace FeatureLinesGui
