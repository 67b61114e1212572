// SPDX-License-Identifier: LGPL-2.1-or-later
// HistogramWidget rendered off screen (QT_QPA_PLATFORM=offscreen) and read back pixel by
// pixel: the bars' geometry is found in the image, and every marker is checked against it.
// The histogram is the mean curvature of a rounded cube (Sec. 2.2, Fig. 2 b): planes at 0,
// fillets of radius r at 1 / (2 r), corners at 1 / r, plus a floor of scattered noise values.
// The rendered images are written as histogram_widget_*.png to the working directory (or to
// FEATURELINES_TEST_OUTPUT) for a person to look at.

#include "HistogramWidget.h"

#include <QApplication>
#include <QDir>
#include <QHelpEvent>
#include <QImage>
#include <QPalette>
#include <QTest>
#include <QToolTip>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

using FeatureLinesGui::HistogramWidget;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

// The bar colour the tests give the palette, so bars can be told from everything else.
const QColor barColour(40, 110, 200);

/// Rounded cube of edge 2 with fillets of radius 0.2 (mean curvature 2.5) and corners of
/// radius 0.2 (mean curvature 5): 30000 plane, 3000 fillet and 500 corner points with normal
/// spread, binned into 40 bins on [-0.5, 6); every bin also holds 2 noise values.
struct RoundedCubeHistogram
{
    double minimum = -0.5;
    double binWidth = 6.5 / 40;
    std::vector<double> counts;

    RoundedCubeHistogram()
    {
        auto mass = [](double n, double mean, double sigma, double a, double b) {
            auto phi = [&](double x) {
                return 0.5 * std::erfc(-(x - mean) / (sigma * std::sqrt(2.0)));
            };
            return n * (phi(b) - phi(a));
        };
        for (int i = 0; i < 40; ++i) {
            const double a = minimum + i * binWidth;
            const double b = a + binWidth;
            counts.push_back(std::round(mass(30000, 0.0, 0.15, a, b) + mass(3000, 2.5, 0.25, a, b) +
                                        mass(500, 5.0, 0.3, a, b)) +
                             2.0);
        }
    }
    int binOf(double value) const
    {
        return static_cast<int>(std::floor((value - minimum) / binWidth));
    }
};

QString outputPath(const QString& name)
{
    const QByteArray dir = qgetenv("FEATURELINES_TEST_OUTPUT");
    return QDir(dir.isEmpty() ? QDir::currentPath() : QString::fromLocal8Bit(dir)).filePath(name);
}

QPalette lightPalette()
{
    QPalette pal = QApplication::palette();
    pal.setColor(QPalette::Window, QColor(239, 239, 239));
    pal.setColor(QPalette::WindowText, Qt::black);
    pal.setColor(QPalette::Base, Qt::white);
    pal.setColor(QPalette::Text, Qt::black);
    pal.setColor(QPalette::Highlight, barColour);
    return pal;
}

QPalette darkPalette()
{
    QPalette pal = QApplication::palette();
    pal.setColor(QPalette::Window, QColor(53, 53, 53));
    pal.setColor(QPalette::WindowText, QColor(230, 230, 230));
    pal.setColor(QPalette::Base, QColor(35, 35, 35));
    pal.setColor(QPalette::Text, QColor(230, 230, 230));
    pal.setColor(QPalette::Disabled, QPalette::Text, QColor(150, 150, 150));
    pal.setColor(QPalette::Highlight, QColor(42, 130, 218));
    return pal;
}

bool isBar(QRgb p, const QColor& colour = barColour)
{
    return p == colour.rgb();
}
bool isRed(QRgb p)
{
    return qRed(p) > 150 && qGreen(p) < 90 && qBlue(p) < 90;
}
bool isLineGrey(QRgb p)
{
    return qRed(p) == 140 && qGreen(p) == 140 && qBlue(p) == 140;
}

QImage render(HistogramWidget& w)
{
    return w.grab().toImage().convertToFormat(QImage::Format_RGB32);
}

int countPixels(const QImage& img, bool (*match)(QRgb))
{
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            n += match(img.pixel(x, y)) ? 1 : 0;
    return n;
}

/// The bars as the image shows them: the lowest row holding bar pixels (every bin with
/// points is at least one pixel high there), the left edges of the first and last bar, the
/// pitch between bars, and each bar's height in its middle column.
struct BarGeometry
{
    int bottomRow = -1;
    int firstLeft = -1;
    int lastLeft = -1;
    double pitch = 0.0;
    std::vector<int> heights;

    /// Image x of a curvature value, from the bars alone.
    double xOf(const RoundedCubeHistogram& h, double value) const
    {
        return firstLeft + (value - h.minimum) / h.binWidth * pitch;
    }
};

BarGeometry findBars(const QImage& img, int bins, const QColor& colour = barColour)
{
    BarGeometry g;
    for (int y = img.height() - 1; y >= 0 && g.bottomRow < 0; --y)
        for (int x = 0; x < img.width(); ++x)
            if (isBar(img.pixel(x, y), colour)) {
                g.bottomRow = y;
                break;
            }
    if (g.bottomRow < 0)
        return g;
    for (int x = 0; x < img.width(); ++x) {
        const bool bar = isBar(img.pixel(x, g.bottomRow), colour);
        const bool before = x > 0 && isBar(img.pixel(x - 1, g.bottomRow), colour);
        if (bar && !before) {
            if (g.firstLeft < 0)
                g.firstLeft = x;
            g.lastLeft = x;
        }
    }
    g.pitch = double(g.lastLeft - g.firstLeft) / (bins - 1);
    for (int i = 0; i < bins; ++i) {
        const int x = static_cast<int>(std::lround(g.firstLeft + (i + 0.5) * g.pitch));
        int h = 0;
        for (int y = g.bottomRow; y >= 0 && isBar(img.pixel(x, y), colour); --y)
            ++h;
        g.heights.push_back(h);
    }
    return g;
}

/// Centres (in image x, pixel boundaries) of the vertical lines made of `match` pixels: runs
/// of adjacent columns holding at least `minPixels` of them.
std::vector<double> lineCentres(const QImage& img, bool (*match)(QRgb), int minPixels)
{
    std::vector<double> centres;
    int runStart = -1;
    for (int x = 0; x <= img.width(); ++x) {
        int n = 0;
        for (int y = 0; x < img.width() && y < img.height(); ++y)
            n += match(img.pixel(x, y)) ? 1 : 0;
        if (n >= minPixels && runStart < 0)
            runStart = x;
        if (n < minPixels && runStart >= 0) {
            centres.push_back(0.5 * (runStart + x));
            runStart = -1;
        }
    }
    return centres;
}

class HistogramWidgetTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        widget.setPalette(lightPalette());
        widget.resize(360, 200);
        widget.setHistogram(cube.counts, cube.minimum, cube.binWidth);
        // Sec. 2.4: values above the histogram's end dropped as outliers.
        widget.setOutlierCut(cube.minimum + 40 * cube.binWidth);
        widget.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&widget));
    }

    RoundedCubeHistogram cube;
    HistogramWidget widget;
};

TEST_F(HistogramWidgetTest, BarHeightsFollowTheCountsAndTheFilletPeakIsVisible)
{
    const QImage img = render(widget);
    const BarGeometry g = findBars(img, 40);
    ASSERT_GE(g.bottomRow, 0) << "no bars drawn";
    ASSERT_EQ(g.heights.size(), 40u);
    ASSERT_GT(g.pitch, 4.0) << "bars narrower than 4 pixels at 360 pixels width";

    // The largest bin's bar is the tallest, and a larger count never gets a shorter bar.
    const auto largest =
        std::max_element(cube.counts.begin(), cube.counts.end()) - cube.counts.begin();
    const auto tallest = std::max_element(g.heights.begin(), g.heights.end()) - g.heights.begin();
    EXPECT_EQ(tallest, largest);
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            if (cube.counts[i] > cube.counts[j]) {
                EXPECT_GE(g.heights[i], g.heights[j]) << "bins " << i << " and " << j;
            }
        }
    }

    // The log scale shows the fillet peak (10 % of the plane points) as a peak of its own,
    // with the valley before it (where threshold tau_2 goes) well below it.
    const int plane = g.heights[cube.binOf(0.0)];
    const int fillet = g.heights[cube.binOf(2.5)];
    const int valley = g.heights[cube.binOf(1.25)];
    EXPECT_GT(fillet, 0.5 * plane);
    EXPECT_LT(valley, 0.5 * fillet);

    // On a linear scale the same peak shrinks to a few pixels: why log is the default.
    widget.setScale(HistogramWidget::Scale::Linear);
    const BarGeometry linear = findBars(render(widget), 40);
    EXPECT_LT(linear.heights[cube.binOf(2.5)], 0.15 * linear.heights[cube.binOf(0.0)]);
    widget.setScale(HistogramWidget::Scale::Log);
}

TEST_F(HistogramWidgetTest, ThresholdLinesLieAtTheirValues)
{
    // tau_1 after the fillets, accepted earlier: tau_2 after the planes (Sec. 2.3, Fig. 5),
    // and one more below the planes' peak's end to check a second earlier line.
    const double current = 3.6;
    const std::vector<double> earlier{1.2, 0.45};
    widget.setThresholds(current, earlier);
    const QImage img = render(widget);
    img.save(outputPath("histogram_widget_light.png"));
    const BarGeometry g = findBars(img, 40);
    ASSERT_GE(g.bottomRow, 0);
    const int plotHeight = *std::max_element(g.heights.begin(), g.heights.end());

    const std::vector<double> red = lineCentres(img, isRed, plotHeight / 2);
    ASSERT_EQ(red.size(), 1u) << "one red line";
    EXPECT_NEAR(red[0], g.xOf(cube, current), 1.5);

    const std::vector<double> grey = lineCentres(img, isLineGrey, plotHeight / 4);
    ASSERT_EQ(grey.size(), earlier.size()) << "one grey dashed line per earlier threshold";
    std::vector<double> expected{g.xOf(cube, earlier[0]), g.xOf(cube, earlier[1])};
    std::sort(expected.begin(), expected.end());
    for (std::size_t i = 0; i < grey.size(); ++i)
        EXPECT_NEAR(grey[i], expected[i], 1.5);

    // Dashed, not solid: the column has gaps.
    const int column = static_cast<int>(grey[0]);
    int greyPixels = 0;
    for (int y = g.bottomRow - plotHeight + 1; y <= g.bottomRow; ++y)
        greyPixels += isLineGrey(img.pixel(column, y)) ? 1 : 0;
    EXPECT_LT(greyPixels, plotHeight * 0.8);

    // No threshold: no red line.
    widget.setThresholds(nan, {});
    EXPECT_TRUE(lineCentres(render(widget), isRed, plotHeight / 2).empty());
}

TEST_F(HistogramWidgetTest, ClickEmitsTheValueUnderTheCursor)
{
    std::vector<double> emitted;
    QObject::connect(&widget, &HistogramWidget::valueClicked,
                     [&](double v) { emitted.push_back(v); });
    const BarGeometry g = findBars(render(widget), 40);
    ASSERT_GE(g.bottomRow, 0);
    const int y = g.bottomRow - 5;

    for (double value : {0.0, 1.3, 2.5, 4.1}) {
        emitted.clear();
        const int x = static_cast<int>(std::lround(g.xOf(cube, value)));
        QTest::mouseClick(&widget, Qt::LeftButton, Qt::NoModifier, QPoint(x, y));
        ASSERT_EQ(emitted.size(), 1u) << "click at " << value;
        EXPECT_NEAR(emitted[0], value, cube.binWidth) << "click at " << value;
    }
    // The middle of a bar gives a value inside that bar's bin.
    for (int bin : {3, 17, 31}) {
        emitted.clear();
        const int x = static_cast<int>(std::lround(g.firstLeft + (bin + 0.5) * g.pitch));
        QTest::mouseClick(&widget, Qt::LeftButton, Qt::NoModifier, QPoint(x, y));
        ASSERT_EQ(emitted.size(), 1u);
        EXPECT_EQ(cube.binOf(emitted[0]), bin);
    }
    // Outside the plot (the count labels on the left), or with the message shown: nothing.
    emitted.clear();
    QTest::mouseClick(&widget, Qt::LeftButton, Qt::NoModifier, QPoint(2, y));
    widget.setMessage(QStringLiteral("no valley"));
    QTest::mouseClick(&widget, Qt::LeftButton, Qt::NoModifier,
                      QPoint(static_cast<int>(g.xOf(cube, 2.5)), y));
    EXPECT_TRUE(emitted.empty());
}

TEST_F(HistogramWidgetTest, HoverShowsTheBinRangeAndCount)
{
    const BarGeometry g = findBars(render(widget), 40);
    ASSERT_GE(g.bottomRow, 0);
    const int bin = cube.binOf(2.5);
    const QPoint pos(static_cast<int>(std::lround(g.firstLeft + (bin + 0.5) * g.pitch)),
                     g.bottomRow - 2);

    QHelpEvent help(QEvent::ToolTip, pos, widget.mapToGlobal(pos));
    QApplication::sendEvent(&widget, &help);
    const QString tip = QToolTip::text();
    const QLocale locale = widget.locale();
    EXPECT_TRUE(tip.contains(locale.toString(qlonglong(cube.counts[bin])) + " points"))
        << tip.toStdString();
    EXPECT_TRUE(tip.contains(locale.toString(cube.minimum + bin * cube.binWidth, 'g', 4)))
        << tip.toStdString();

    // The hovered bar is drawn in another shade, the others keep theirs.
    QTest::mouseMove(&widget, pos);
    const QImage img = render(widget);
    EXPECT_FALSE(isBar(img.pixel(pos)));
    EXPECT_TRUE(isBar(
        img.pixel(static_cast<int>(std::lround(g.firstLeft + (bin + 1.5) * g.pitch)), pos.y())));
}

TEST_F(HistogramWidgetTest, ClearAndMessageDrawNoBars)
{
    ASSERT_GT(countPixels(render(widget), [](QRgb p) { return isBar(p); }), 100);

    widget.setThresholds(2.0, {1.0});
    widget.setMessage(QStringLiteral("no valley"));
    QImage img = render(widget);
    img.save(outputPath("histogram_widget_message.png"));
    EXPECT_EQ(countPixels(img, [](QRgb p) { return isBar(p); }), 0);
    EXPECT_EQ(countPixels(img, isRed), 0);
    // The message itself is drawn: dark text pixels on the white plot.
    EXPECT_GT(countPixels(img, [](QRgb p) { return qGray(p) < 180; }), 20);

    widget.setMessage(QString());
    EXPECT_GT(countPixels(render(widget), [](QRgb p) { return isBar(p); }), 100);

    widget.clear();
    img = render(widget);
    EXPECT_EQ(countPixels(img, [](QRgb p) { return isBar(p); }), 0);
    EXPECT_EQ(countPixels(img, isRed), 0);
    EXPECT_GT(countPixels(img, [](QRgb p) { return qGray(p) < 180; }), 20) << "no text";
}

TEST_F(HistogramWidgetTest, BadInputDoesNotCrash)
{
    auto bars = [&] { return countPixels(render(widget), [](QRgb p) { return isBar(p); }); };

    widget.setHistogram({}, 0.0, 0.1);
    EXPECT_EQ(bars(), 0);
    widget.setHistogram({1, 2, 3}, nan, 0.1);
    EXPECT_EQ(bars(), 0);
    widget.setHistogram({1, 2, 3}, 0.0, 0.0);
    EXPECT_EQ(bars(), 0);
    widget.setHistogram({1, 2, 3}, 0.0, -1.0);
    EXPECT_EQ(bars(), 0);
    widget.setHistogram({1, 2, 3}, 0.0, inf);
    EXPECT_EQ(bars(), 0);

    // NaN, infinite and negative counts count nothing: one bar, for the bin holding 5.
    widget.setHistogram({nan, 5.0, -3.0, inf}, 0.0, 1.0);
    widget.setThresholds(nan, {nan, inf, -inf});
    widget.setOutlierCut(inf);
    const QImage img = render(widget);
    const BarGeometry g = findBars(img, 2);
    ASSERT_GE(g.bottomRow, 0);
    EXPECT_EQ(g.firstLeft, g.lastLeft) << "exactly one bar";
    EXPECT_EQ(countPixels(img, isRed), 0);

    // All counts zero, a single bin, thresholds far outside the histogram, a tiny widget.
    widget.setHistogram(std::vector<double>(10, 0.0), 0.0, 0.1);
    widget.setThresholds(1e12, {-1e12});
    widget.setOutlierCut(-5.0);
    EXPECT_EQ(bars(), 0);
    widget.setHistogram({7.0}, 1.0, 1e-9);
    widget.setThresholds(1.0, {});
    render(widget);
    widget.resize(30, 20);
    render(widget);
    widget.setHistogram(std::vector<double>(100000, 1.0), -1e6, 20.0);
    widget.resize(300, 160);
    render(widget);
    for (HistogramWidget::Scale s :
         {HistogramWidget::Scale::Linear, HistogramWidget::Scale::SquareRoot}) {
        widget.setScale(s);
        widget.setHistogram({0.0, 1e300, 1.0}, 0.0, 1.0);
        render(widget);
    }
}

TEST_F(HistogramWidgetTest, DarkThemeUsesThePalette)
{
    const QPalette dark = darkPalette();
    widget.setPalette(dark);
    widget.setThresholds(3.6, {1.2});
    widget.resize(320, 180); // sizeHint: the task panel's width
    const QImage img = render(widget);
    img.save(outputPath("histogram_widget_dark.png"));

    const QColor bars = dark.color(QPalette::Highlight);
    const BarGeometry g = findBars(img, 40, bars);
    ASSERT_GE(g.bottomRow, 0) << "bars in the palette's highlight colour";
    // Inside the plot above a short bar the background is the palette's Base colour...
    const int valleyX =
        static_cast<int>(std::lround(g.firstLeft + (cube.binOf(1.25) + 0.5) * g.pitch));
    EXPECT_EQ(QColor(img.pixel(valleyX, g.bottomRow - g.heights[cube.binOf(1.25)] - 2)),
              dark.color(QPalette::Base));
    // ... and the axis labels are light text, as the palette's WindowText.
    int light = 0;
    for (int y = g.bottomRow + 2; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            light += qGray(img.pixel(x, y)) > 180 ? 1 : 0;
    EXPECT_GT(light, 30);
    // The red line is still there at its value.
    const int plotHeight = *std::max_element(g.heights.begin(), g.heights.end());
    const std::vector<double> red = lineCentres(img, isRed, plotHeight / 2);
    ASSERT_EQ(red.size(), 1u);
    EXPECT_NEAR(red[0], g.xOf(cube, 3.6), 1.5);

    // Fig. 5: the histogram of the values below tau_1 only, tau_1 on the right edge.
    RoundedCubeHistogram below;
    below.counts.resize(25);
    widget.setHistogram(below.counts, below.minimum, below.binWidth);
    widget.setOutlierCut(nan);
    widget.setThresholds(1.2, {below.minimum + 25 * below.binWidth});
    widget.setPalette(lightPalette());
    widget.resize(400, 220);
    render(widget).save(outputPath("histogram_widget_below_tau1.png"));
}

} // namespace

int main(int argc, char** argv)
{
    // Runs without a display; a caller's QT_QPA_PLATFORM (e.g. xcb under Xvfb) wins.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
