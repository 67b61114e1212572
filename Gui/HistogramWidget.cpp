// SPDX-License-Identifier: LGPL-2.1-or-later
#include "HistogramWidget.h"

#include <QEvent>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <limits>

namespace FeatureLinesGui {

namespace {

const double noValue = std::numeric_limits<double>::quiet_NaN();

/// The candidate threshold: red on light and dark themes alike (the paper's figures mark
/// thresholds the same way); earlier ones a mid grey readable on both.
const QColor candidateColour(215, 25, 25);
const QColor earlierColour(140, 140, 140);

/// Nice tick step (1, 2 or 5 times a power of ten) for about `count` ticks over `range`.
double niceStep(double range, int count)
{
    const double raw = range / std::max(count, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double fraction = raw / magnitude;
    const double nice = fraction <= 1.0   ? 1.0
                        : fraction <= 2.0 ? 2.0
                        : fraction <= 5.0 ? 5.0
                                          : 10.0;
    return nice * magnitude;
}

/// Multiples of `step` in [lo, hi], snapped so that 0.1 * 3 prints as 0.3 and not -0.
std::vector<double> ticksIn(double lo, double hi, double step)
{
    std::vector<double> ticks;
    if (!(step > 0.0) || !std::isfinite(lo) || !std::isfinite(hi))
        return ticks;
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) {
        double v = k * step;
        if (std::abs(v) < step * 1e-9)
            v = 0.0;
        ticks.push_back(v);
        if (ticks.size() > 64)
            break;
    }
    return ticks;
}

/// Counts the way a plot axis shows them: 950, 1.2k, 30k, 1.5M.
QString compactCount(double count)
{
    if (count < 1000.0)
        return QString::number(count, 'g', 3);
    if (count < 1e6)
        return QString::number(count / 1e3, 'g', 3) + QLatin1Char('k');
    return QString::number(count / 1e6, 'g', 3) + QLatin1Char('M');
}

} // namespace

HistogramWidget::HistogramWidget(QWidget* parent)
    : QWidget(parent), outlierCut_(noValue), current_(noValue)
{
    setMouseTracking(true); // hover highlight and tooltips follow the cursor
    setCursor(Qt::CrossCursor);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void HistogramWidget::setHistogram(const std::vector<double>& counts, double minimum,
                                   double binWidth)
{
    counts_.clear();
    maxCount_ = 0.0;
    hoveredBin_ = -1;
    message_.clear();
    const double end = minimum + binWidth * static_cast<double>(counts.size());
    if (std::isfinite(minimum) && std::isfinite(binWidth) && binWidth > 0.0 && std::isfinite(end) &&
        !counts.empty()) {
        counts_.reserve(counts.size());
        for (double c : counts) {
            // A count is a number of points: NaN, infinite or negative ones count nothing.
            const double count = std::isfinite(c) && c > 0.0 ? c : 0.0;
            counts_.push_back(count);
            maxCount_ = std::max(maxCount_, count);
        }
        minimum_ = minimum;
        binWidth_ = binWidth;
    }
    update();
}

void HistogramWidget::setOutlierCut(double cut)
{
    outlierCut_ = std::isfinite(cut) ? cut : noValue;
    update();
}

void HistogramWidget::setThresholds(double current, const std::vector<double>& earlier)
{
    current_ = std::isfinite(current) ? current : noValue;
    earlier_ = earlier;
    update();
}

void HistogramWidget::clear()
{
    counts_.clear();
    maxCount_ = 0.0;
    hoveredBin_ = -1;
    outlierCut_ = noValue;
    current_ = noValue;
    earlier_.clear();
    message_.clear();
    update();
}

void HistogramWidget::setMessage(const QString& text)
{
    message_ = text;
    hoveredBin_ = -1;
    update();
}

void HistogramWidget::setScale(Scale scale)
{
    scale_ = scale;
    update();
}

QSize HistogramWidget::sizeHint() const
{
    return {320, 180};
}

QSize HistogramWidget::minimumSizeHint() const
{
    return {150, 120};
}

bool HistogramWidget::hasBars() const
{
    return !counts_.empty();
}

double HistogramWidget::histogramEnd() const
{
    return minimum_ + binWidth_ * static_cast<double>(counts_.size());
}

QFont HistogramWidget::tickFont() const
{
    // Axis labels a little smaller than the panel's text, relative to the user's font.
    QFont f = font();
    if (f.pointSizeF() > 0)
        f.setPointSizeF(f.pointSizeF() * 0.9);
    else if (f.pixelSize() > 0)
        f.setPixelSize(std::max(1, static_cast<int>(std::lround(f.pixelSize() * 0.9))));
    return f;
}

double HistogramWidget::Layout::xOf(double value) const
{
    return plot.left() + (value - xMin) / (xMax - xMin) * plot.width();
}

double HistogramWidget::Layout::valueAt(double x) const
{
    return xMin + (x - plot.left()) / plot.width() * (xMax - xMin);
}

HistogramWidget::Layout HistogramWidget::layout() const
{
    Layout l;
    const QFontMetricsF fm(tickFont());
    const double line = fm.height();
    const double tick = std::round(line * 0.35);

    // Left: rotated axis title, widest count label, tick. Bottom: tick, labels, axis title.
    // Top: the threshold labels. Right: half a tick label that may stick out.
    const double countWidth = fm.horizontalAdvance(compactCount(std::max(maxCount_, 1.0)));
    const double left = std::ceil(line * 1.2 + std::max(countWidth, fm.horizontalAdvance("00")) +
                                  tick + line * 0.3);
    const double top = std::ceil(line * 1.3);
    const double bottom = std::ceil(tick + line * 2.2);
    const double right = std::ceil(line * 0.9);
    l.plot =
        QRectF(left, top, std::floor(width() - left - right), std::floor(height() - top - bottom));
    if (!hasBars() || l.plot.width() < 20 || l.plot.height() < 20)
        return l;

    // The curvature range: the histogram and every marker the caller set.
    double lo = minimum_;
    double hi = histogramEnd();
    auto include = [&](double v) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    };
    include(current_);
    for (double v : earlier_)
        include(v);
    include(outlierCut_);
    if (!(hi > lo))
        hi = lo + 1.0;
    if (std::isfinite(outlierCut_) && outlierCut_ >= histogramEnd() - 1e-12 * (hi - lo)) {
        // The dropped values are not in the histogram: widen the range so their band is wide
        // enough for its caption.
        const double band = std::min(line * 1.8, l.plot.width() * 0.3);
        hi += band * (hi - lo) / (l.plot.width() - band);
    } else {
        // A threshold at the histogram's end (Sec. 2.3 searches below it) stays off the frame.
        hi += 0.02 * (hi - lo);
    }
    l.xMin = lo;
    l.xMax = hi;
    l.valid = true;
    return l;
}

double HistogramWidget::heightFraction(double count) const
{
    if (maxCount_ <= 0.0 || count <= 0.0)
        return 0.0;
    switch (scale_) {
    case Scale::Linear:
        return count / maxCount_;
    case Scale::SquareRoot:
        return std::sqrt(count / maxCount_);
    case Scale::Log:
        break;
    }
    return std::log1p(count) / std::log1p(maxCount_);
}

double HistogramWidget::yOf(const Layout& l, double count) const
{
    // The tallest bar stops short of the top so that it does not merge with the labels.
    return l.plot.bottom() - heightFraction(count) * l.plot.height() * 0.95;
}

int HistogramWidget::binAt(const Layout& l, const QPointF& pos) const
{
    if (!l.valid || !l.plot.adjusted(0, -1, 0, 1).contains(pos))
        return -1;
    const double bin = std::floor((l.valueAt(pos.x()) - minimum_) / binWidth_);
    if (bin < 0 || bin >= static_cast<double>(counts_.size()))
        return -1;
    return static_cast<int>(bin);
}

void HistogramWidget::paintEvent(QPaintEvent* /*event*/)
{
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Window));
    p.setFont(tickFont());
    const Layout l = layout();
    if (!message_.isEmpty() || !l.valid) {
        QString text = message_;
        if (text.isEmpty())
            text = hasBars() ? QString() : tr("no histogram");
        drawMessage(p, text);
        return;
    }
    p.fillRect(l.plot, palette().color(QPalette::Base));
    drawAxes(p, l);
    drawBars(p, l);
    drawOutlierBand(p, l);
    drawThresholds(p, l);
}

void HistogramWidget::drawMessage(QPainter& p, const QString& text) const
{
    const QRectF area = rect().adjusted(4, 4, -4, -4);
    p.fillRect(area, palette().color(QPalette::Base));
    QColor frame = palette().color(QPalette::WindowText);
    frame.setAlphaF(0.3);
    p.setPen(frame);
    p.drawRect(area.adjusted(0, 0, -1, -1));
    p.setFont(font());
    p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
    p.drawText(area.adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, text);
}

void HistogramWidget::drawAxes(QPainter& p, const Layout& l) const
{
    const QFontMetricsF fm(p.font());
    const double line = fm.height();
    const double tick = std::round(line * 0.35);
    const QColor text = palette().color(QPalette::WindowText);
    QColor grid = text;
    grid.setAlphaF(0.12);
    QColor axis = text;
    axis.setAlphaF(0.7);

    // y: grid lines at powers of ten (log) or nice steps; labels where they have room,
    // placed from the top down (log1p puts 0 and 1 close together: "1" gives way to "0").
    std::vector<double> yTicks;
    if (scale_ == Scale::Log) {
        for (double v = 1.0; v <= maxCount_; v *= 10.0)
            yTicks.push_back(v);
    } else if (maxCount_ > 0.0) {
        const int room = std::max(2, static_cast<int>(l.plot.height() / (line * 1.5)));
        yTicks = ticksIn(0.0, maxCount_, niceStep(maxCount_, std::min(room, 4)));
    }
    std::reverse(yTicks.begin(), yTicks.end());
    std::vector<double> labelled{l.plot.bottom()};
    p.setRenderHint(QPainter::Antialiasing, false);
    auto yLabel = [&](double y, double v) {
        p.setPen(axis);
        p.drawLine(QPointF(l.plot.left() - tick, y), QPointF(l.plot.left(), y));
        p.setPen(text);
        p.drawText(QRectF(0, y - line / 2, l.plot.left() - tick - line * 0.2, line),
                   Qt::AlignRight | Qt::AlignVCenter, compactCount(v));
    };
    yLabel(l.plot.bottom(), 0.0);
    for (double v : yTicks) {
        if (v <= 0.0)
            continue;
        const double y = std::round(yOf(l, v));
        p.setPen(grid);
        p.drawLine(QPointF(l.plot.left(), y), QPointF(l.plot.right(), y));
        const bool room = std::all_of(labelled.begin(), labelled.end(), [&](double other) {
            return std::abs(other - y) >= line * 1.1;
        });
        if (room) {
            labelled.push_back(y);
            yLabel(y, v);
        }
    }

    // x: curvature ticks at nice steps, as many as their labels leave room for.
    std::vector<double> xTicks;
    for (int wanted = 8; wanted >= 2; --wanted) {
        xTicks = ticksIn(l.xMin, l.xMax, niceStep(l.xMax - l.xMin, wanted));
        double widest = 0.0;
        for (double v : xTicks)
            widest = std::max(widest, fm.horizontalAdvance(locale().toString(v, 'g', 4)));
        if ((widest + line) * static_cast<double>(xTicks.size()) <= l.plot.width())
            break;
    }
    for (double v : xTicks) {
        const double x = std::round(l.xOf(v));
        p.setPen(axis);
        p.drawLine(QPointF(x, l.plot.bottom()), QPointF(x, l.plot.bottom() + tick));
        p.setPen(text);
        p.drawText(QRectF(x - 40 * line, l.plot.bottom() + tick, 80 * line, line),
                   Qt::AlignHCenter | Qt::AlignTop, locale().toString(v, 'g', 4));
    }

    p.setPen(axis);
    p.drawLine(l.plot.bottomLeft(), l.plot.bottomRight());
    p.drawLine(l.plot.bottomLeft(), l.plot.topLeft());

    p.setPen(text);
    // The x title under the plot; in a narrow panel it may use the whole width, and a shorter
    // wording when even that is too little (never cut off).
    QString xTitle = tr("mean curvature (1/length)");
    QRectF titleBox(l.plot.left(), l.plot.bottom() + tick + line, l.plot.width(), line * 1.2);
    if (fm.horizontalAdvance(xTitle) > titleBox.width()) {
        titleBox.setLeft(0.0);
        titleBox.setRight(width());
    }
    if (fm.horizontalAdvance(xTitle) > titleBox.width()) {
        xTitle = tr("curvature (1/length)");
    }
    p.drawText(titleBox, Qt::AlignHCenter | Qt::AlignVCenter,
               fm.elidedText(xTitle, Qt::ElideRight, titleBox.width()));
    const QString yTitle = scale_ == Scale::Log          ? tr("points (log)")
                           : scale_ == Scale::SquareRoot ? tr("points (sqrt)")
                                                         : tr("points");
    p.save();
    p.translate(0, l.plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-l.plot.height() / 2, 0, l.plot.height(), line * 1.1),
               Qt::AlignHCenter | Qt::AlignTop, yTitle);
    p.restore();
}

void HistogramWidget::drawBars(QPainter& p, const Layout& l) const
{
    // Pixel-aligned bars without antialiasing: crisp edges, one pixel apart when wide enough.
    p.setRenderHint(QPainter::Antialiasing, false);
    const QColor fill = palette().color(QPalette::Highlight);
    const QColor hover = fill.lightness() > 128 ? fill.darker(125) : fill.lighter(135);
    const int bottom = static_cast<int>(std::round(l.plot.bottom()));
    for (std::size_t i = 0; i < counts_.size(); ++i) {
        const int x0 = static_cast<int>(std::round(l.xOf(minimum_ + binWidth_ * i)));
        const int x1 = static_cast<int>(std::round(l.xOf(minimum_ + binWidth_ * (i + 1))));
        const int gap = x1 - x0 >= 4 ? 1 : 0;
        int h = static_cast<int>(std::round(l.plot.bottom() - yOf(l, counts_[i])));
        if (counts_[i] > 0.0)
            h = std::max(h, 1); // a bin holding points is never invisible
        if (h <= 0 || x1 - x0 - gap <= 0)
            continue;
        p.fillRect(QRect(x0, bottom - h, x1 - x0 - gap, h),
                   static_cast<int>(i) == hoveredBin_ ? hover : fill);
    }
}

void HistogramWidget::drawOutlierBand(QPainter& p, const Layout& l) const
{
    if (!std::isfinite(outlierCut_))
        return;
    const double x = std::round(l.xOf(outlierCut_));
    if (x >= l.plot.right())
        return;
    const QColor text = palette().color(QPalette::WindowText);
    const QRectF band(QPointF(std::max(x, l.plot.left()), l.plot.top()), l.plot.bottomRight());
    QColor shade = text;
    shade.setAlphaF(0.08);
    p.fillRect(band, shade);
    QColor hatch = text;
    hatch.setAlphaF(0.22);
    p.fillRect(band, QBrush(hatch, Qt::BDiagPattern));

    QColor edge = text;
    edge.setAlphaF(0.6);
    QPen pen(edge, 1, Qt::DashLine);
    p.setPen(pen);
    p.setRenderHint(QPainter::Antialiasing, false);
    p.drawLine(QPointF(x, l.plot.top()), QPointF(x, l.plot.bottom()));

    // Caption along the band when it is at least a line wide, else left of the cut line.
    const QFontMetricsF fm(p.font());
    const QString caption = tr("outliers > %1").arg(locale().toString(outlierCut_, 'g', 3));
    p.setPen(text);
    p.setRenderHint(QPainter::Antialiasing, true);
    if (band.width() >= fm.height()) {
        p.save();
        p.translate(band.center());
        p.rotate(-90);
        const QRectF r(-band.height() / 2, -fm.height() / 2, band.height() - fm.height() * 0.3,
                       fm.height());
        QColor back = palette().color(QPalette::Base);
        back.setAlphaF(0.75);
        const double w = std::min(fm.horizontalAdvance(caption) + 4, r.width());
        p.fillRect(QRectF(r.right() - w, r.top(), w, r.height()), back);
        p.drawText(r, Qt::AlignRight | Qt::AlignVCenter, caption);
        p.restore();
    } else {
        const double w = fm.horizontalAdvance(caption);
        p.drawText(QRectF(x - w - 4, l.plot.top() + 2, w, fm.height()), Qt::AlignRight, caption);
    }
}

void HistogramWidget::drawThresholds(QPainter& p, const Layout& l) const
{
    const QFontMetricsF fm(p.font());
    const double labelY = l.plot.top() - fm.height() * 1.15;
    const QColor base = palette().color(QPalette::Window);
    auto inside = [&](double x) { return x >= l.plot.left() && x <= l.plot.right(); };
    // A label centred over its line, kept within the widget, on the window colour so that a
    // later label drawn over an earlier one stays legible.
    auto label = [&](double x, const QString& text, const QColor& colour) {
        const double w = fm.horizontalAdvance(text) + 4;
        const double left = std::clamp(x - w / 2, 0.0, std::max(0.0, width() - w));
        const QRectF r(left, labelY, w, fm.height());
        p.fillRect(r, base);
        p.setPen(colour);
        p.drawText(r, Qt::AlignCenter, text);
    };

    p.setRenderHint(QPainter::Antialiasing, false);
    for (std::size_t i = 0; i < earlier_.size(); ++i) {
        const double v = earlier_[i];
        if (!std::isfinite(v))
            continue;
        // One pixel column: the one the value falls in.
        const double x = std::floor(l.xOf(v));
        if (!inside(x))
            continue;
        QPen pen(earlierColour, 1, Qt::CustomDashLine);
        pen.setDashPattern({4, 3});
        p.setPen(pen);
        p.drawLine(QPointF(x, l.plot.top()), QPointF(x, l.plot.bottom()));
        label(x, QString::number(i + 1), earlierColour);
    }
    if (std::isfinite(current_)) {
        const double x = std::round(l.xOf(current_));
        if (inside(x)) {
            // Two pixel columns either side of the pixel boundary nearest to the value.
            p.fillRect(QRectF(x - 1, l.plot.top(), 2, l.plot.height()), candidateColour);
            QFont bold = p.font();
            bold.setBold(true);
            p.save();
            p.setFont(bold);
            const QFontMetricsF bfm(bold);
            const QString text = locale().toString(current_, 'g', 3);
            const double w = bfm.horizontalAdvance(text) + 4;
            const double left = std::clamp(x - w / 2, 0.0, std::max(0.0, width() - w));
            const QRectF r(left, labelY, w, bfm.height());
            p.fillRect(r, base);
            p.setPen(candidateColour);
            p.drawText(r, Qt::AlignCenter, text);
            p.restore();
        }
    }
}

bool HistogramWidget::event(QEvent* e)
{
    if (e->type() != QEvent::ToolTip)
        return QWidget::event(e);
    auto* help = static_cast<QHelpEvent*>(e);
    const Layout l = layout();
    QString tip;
    if (message_.isEmpty() && l.valid && l.plot.contains(help->pos())) {
        const double x = help->pos().x();
        auto near = [&](double v) { return std::isfinite(v) && std::abs(l.xOf(v) - x) <= 3.0; };
        if (near(current_)) {
            tip = tr("candidate threshold %1").arg(locale().toString(current_, 'g', 4));
        } else {
            for (std::size_t i = 0; i < earlier_.size() && tip.isEmpty(); ++i) {
                if (near(earlier_[i]))
                    tip = tr("threshold %1: %2")
                              .arg(i + 1)
                              .arg(locale().toString(earlier_[i], 'g', 4));
            }
        }
        const int bin = binAt(l, help->pos());
        if (tip.isEmpty() && bin >= 0) {
            const double from = minimum_ + binWidth_ * bin;
            tip = tr("%1 to %2 (1/length)\n%3 points")
                      .arg(locale().toString(from, 'g', 4))
                      .arg(locale().toString(from + binWidth_, 'g', 4))
                      .arg(locale().toString(static_cast<qlonglong>(std::llround(counts_[bin]))));
        }
        if (tip.isEmpty() && std::isfinite(outlierCut_) && x >= l.xOf(outlierCut_))
            tip = tr("values above %1 were dropped as outliers")
                      .arg(locale().toString(outlierCut_, 'g', 4));
    }
    if (tip.isEmpty()) {
        QToolTip::hideText();
        e->ignore();
    } else {
        QToolTip::showText(help->globalPos(), tip, this);
    }
    return true;
}

void HistogramWidget::mousePressEvent(QMouseEvent* event)
{
    const Layout l = layout();
    if (event->button() == Qt::LeftButton && message_.isEmpty() && l.valid &&
        l.plot.adjusted(-2, -2, 2, 2).contains(event->localPos())) {
        const double x = std::clamp(event->localPos().x(), l.plot.left(), l.plot.right());
        emit valueClicked(l.valueAt(x));
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void HistogramWidget::mouseMoveEvent(QMouseEvent* event)
{
    const int bin = message_.isEmpty() ? binAt(layout(), event->localPos()) : -1;
    if (bin != hoveredBin_) {
        hoveredBin_ = bin;
        update();
    }
    QWidget::mouseMoveEvent(event);
}

void HistogramWidget::leaveEvent(QEvent* event)
{
    if (hoveredBin_ >= 0) {
        hoveredBin_ = -1;
        update();
    }
    QWidget::leaveEvent(event);
}

void HistogramWidget::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange ||
        event->type() == QEvent::LocaleChange)
        update();
    QWidget::changeEvent(event);
}

} // namespace FeatureLinesGui
