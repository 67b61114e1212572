// SPDX-License-Identifier: LGPL-2.1-or-later
// featurelines: the core library's stages from the command line, for scripts and for checking
// a cloud before it goes into FreeCAD. Each command is one row of the `commands` table.
//
// Exit codes: 0 success, 1 bad input data (unreadable file, too few points, ...), 2 a usage
// error (unknown command or option, missing or absurd value). Errors print one line on stderr,
// "featurelines: <reason>". A bound that follows from the call or the machine (--k above 256,
// --threads above 4 x the cores, an output file that is the input) is a usage error; one that
// follows from the cloud (--k or --bins not below its point count) or the file system (an output
// folder that does not exist, a failed write) is bad input.
//
// Outputs are checked before any work, then written whole or not at all (OutputFiles.h).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/cli/Arguments.h"
#include "FeatureLines/cli/CurveOutput.h"
#include "FeatureLines/cli/Inputs.h"
#include "FeatureLines/cli/Json.h"
#include "FeatureLines/cli/LineOutput.h"
#include "FeatureLines/cli/OutputFiles.h"
#include "FeatureLines/cli/Progress.h"
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "FeatureLines/io/CloudIO.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/HistogramThreshold.h"

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

#ifndef FEATURELINES_VERSION
#define FEATURELINES_VERSION "unknown"
#endif

namespace featurelines::cli {
namespace {

using Run = int (*)(const Arguments&);

struct Command
{
    std::string name;
    std::string summary;
    /// What follows "featurelines NAME" in the usage line.
    std::string synopsis;
    std::vector<OptionSpec> options;
    Run run;
};

// ---- options shared by several commands ---------------------------------------------------

OptionSpec kOption()
{
    return {"--k", "N",
            "neighbours per point for normals and curvature, 3 to 256 and below the point count "
            "(default 16)"};
}
OptionSpec threadsOption()
{
    return {"--threads", "T", "worker threads, 0 for all cores, at most 4 x the cores (default 0)"};
}
OptionSpec smoothOption()
{
    return {"--smooth", "N",
            "Taubin smoothing passes over all points before the curvature, for noisy scans "
            "(Sec. 2.4; default 0)"};
}
OptionSpec signedOption()
{
    return {"--signed", "",
            "signed mean curvature; the sign follows the unoriented PCA normal, so it is only "
            "meaningful within one consistently oriented region (default: |H|)"};
}

OptionSpec formatOption()
{
    return {"--format", "F",
            "the format of standard input (INPUT -): xyz, txt, asc, csv, ply or pcd (default xyz)"};
}

/// The single positional argument INPUT ("-": standard input), or a UsageError.
std::string inputPath(const Arguments& a)
{
    if (a.positional().empty()) {
        throw UsageError("no INPUT point cloud given");
    }
    if (a.positional().size() > 1) {
        throw UsageError("unexpected argument '" + a.positional()[1] + "'");
    }
    return a.positional()[0];
}

/// The largest --k: the quadric fit and the neighbour search grow with k, and 256 neighbours
/// already span several spacings of any cloud the extraction reads well.
constexpr long maximumK = 256;

int neighbourCount(const Arguments& a)
{
    return static_cast<int>(a.integer("--k", 16, 3, maximumK));
}

/// At most 4 threads per core: more only cost memory and switching.
int threadCount(const Arguments& a)
{
    const long cores = std::max(1u, std::thread::hardware_concurrency());
    const long threads = a.integer("--threads", 0, 0, std::numeric_limits<int>::max());
    if (threads > 4 * cores) {
        throw UsageError("--threads must be at most " + std::to_string(4 * cores) + " (4 x the " +
                         std::to_string(cores) + " cores), got " + std::to_string(threads));
    }
    return static_cast<int>(threads);
}

/// std::runtime_error (exit 1) unless the option `name`, when given, is below the cloud's
/// point count: k neighbours need k + 1 points, L bins more values than bins.
void requireBelowPointCount(const Arguments& a, const std::string& name, long value,
                            const std::string& input, Eigen::Index points)
{
    if (a.has(name) && value >= points) {
        throw std::runtime_error(name + " " + std::to_string(value) +
                                 " must be below the point count of " + inputName(input) + " (" +
                                 std::to_string(points) + ")");
    }
}

/// The options of the curvature stages, read (and checked) before the cloud is.
struct CurvatureSettings
{
    NeighbourOptions neighbours;
    int smoothingPasses = 0;
    bool isSigned = false;
};

CurvatureSettings curvatureSettings(const Arguments& a)
{
    CurvatureSettings s;
    s.neighbours.k = neighbourCount(a);
    s.neighbours.threads = threadCount(a);
    s.smoothingPasses = static_cast<int>(a.integer("--smooth", 0, 0, 1000));
    s.isSigned = a.has("--signed");
    return s;
}

/// Sec. 2.1: mean curvature from the quadric fitted over the k nearest neighbours, after the
/// optional smoothing of Sec. 2.4. The cloud is checked as extract checks it (duplicates only,
/// points on a line: no curvature to measure).
Eigen::VectorXd curvatureOf(const CurvatureSettings& s, const PointMatrix& cloud)
{
    requireSurfaceCloud(cloud, s.neighbours.k);
    PointMatrix P = cloud;
    Neighbourhoods N = nearestNeighbours(P, s.neighbours);
    if (s.smoothingPasses > 0) {
        SmoothingOptions sopt;
        sopt.iterations = s.smoothingPasses;
        std::vector<int> all(static_cast<std::size_t>(P.rows()));
        std::iota(all.begin(), all.end(), 0);
        P = laplacianSmooth(P, N, all, sopt);
        // The points moved: the neighbourhoods of the smoothed cloud, not the noisy one.
        N = nearestNeighbours(P, s.neighbours);
    }
    NormalOptions normalOpt;
    normalOpt.threads = s.neighbours.threads;
    const NormalEstimate normals = pcaNormals(P, N, normalOpt);
    CurvatureOptions copt;
    copt.signedCurvature = s.isSigned;
    copt.threads = s.neighbours.threads;
    return meanCurvature(P, normals.normals, N, copt);
}

// ---- info ---------------------------------------------------------------------------------

int runInfo(const Arguments& a)
{
    const std::string input = inputPath(a);
    const int requestedK = neighbourCount(a);
    const int threads = threadCount(a);
    const PointMatrix P = readInput(input, standardInputFormat(a, input == "-"));
    const Eigen::RowVector3d lo = P.colwise().minCoeff();
    const Eigen::RowVector3d hi = P.colwise().maxCoeff();
    const auto triple = [](const Eigen::RowVector3d& v) {
        return Arguments::format(v.x()) + " " + Arguments::format(v.y()) + " " +
               Arguments::format(v.z());
    };
    std::cout << "points: " << P.rows() << "\n"
              << "bounding box min: " << triple(lo) << "\n"
              << "bounding box max: " << triple(hi) << "\n"
              << "size: " << triple(hi - lo) << "\n";
    // info describes any cloud: with few points, fewer neighbours suffice for the spacing.
    const Eigen::Index k = std::min<Eigen::Index>(requestedK, P.rows() - 1);
    if (k < 3) {
        std::cout << "mean spacing: unknown (fewer than 4 points)\n";
        return 0;
    }
    NeighbourOptions nopt;
    nopt.k = static_cast<int>(k);
    nopt.threads = threads;
    // Computed before anything is printed: a refused cloud leaves no half-written line.
    const double spacing = meanSpacing(nearestNeighbours(P, nopt));
    std::cout << "mean spacing: " << Arguments::format(spacing) << "\n";
    return 0;
}

// ---- curvature ----------------------------------------------------------------------------

int runCurvature(const Arguments& a)
{
    const std::string input = inputPath(a);
    if (!a.has("--output")) {
        throw UsageError("curvature needs an output file: -o FILE");
    }
    const std::string output = a.text("--output");
    const CurvatureSettings settings = curvatureSettings(a);
    const std::string format = standardInputFormat(a, input == "-");
    checkOutputs(input, {{"--output", output}});
    const PointMatrix cloud = readInput(input, format);
    requireBelowPointCount(a, "--k", settings.neighbours.k, input, cloud.rows());
    const Eigen::VectorXd H = curvatureOf(settings, cloud);

    std::string text;
    for (Eigen::Index i = 0; i < H.size(); ++i) {
        text += Arguments::format(H[i]) + '\n';
    }
    writeWhole(output, text);
    return 0;
}

// ---- threshold ----------------------------------------------------------------------------

/// The L + 1 edges of the histogram's bins.
std::vector<double> binEdges(const Histogram& h)
{
    std::vector<double> edges(h.counts.size() + 1);
    for (std::size_t i = 0; i < edges.size(); ++i) {
        edges[i] = h.minimum + static_cast<double>(i) * h.binWidth;
    }
    if (h.binWidth > 0.0) {
        edges.back() = h.maximum; // the last edge is the maximum itself, not a rounded sum
    }
    return edges;
}

/// The histogram as a JSON object: its range, bin width and counts.
std::string histogramJson(const Histogram& h)
{
    using namespace json;
    Object histogram;
    histogram.add("minimum", number(h.minimum))
        .add("maximum", number(h.maximum))
        .add("bin_width", number(h.binWidth))
        .add("counts", array(h.counts));
    return histogram.str();
}

int runThreshold(const Arguments& a)
{
    const std::string input = inputPath(a);
    ThresholdOptions options;
    // The all-starts search costs O(L^2): a million bins is already minutes.
    options.bins = static_cast<int>(a.integer("--bins", options.bins, 2, 1000000));
    options.outlierPercent = a.number("--outliers", options.outlierPercent, 0.0, 100.0, false);
    options.minPeakPercent = a.number("--min-peak", options.minPeakPercent, 0.0, 100.0, true);
    if (a.has("--single-run")) {
        options.search = ThresholdSearch::SingleRun;
    }
    if (a.has("--below") && a.has("--above")) {
        throw UsageError("--below and --above exclude each other");
    }
    const bool below = a.has("--below"), above = a.has("--above");
    const double previous = below   ? Arguments::parseNumber("--below", a.text("--below"))
                            : above ? Arguments::parseNumber("--above", a.text("--above"))
                                    : 0.0;
    const CurvatureSettings settings = curvatureSettings(a);

    const PointMatrix cloud = readInput(input, standardInputFormat(a, input == "-"));
    requireBelowPointCount(a, "--k", settings.neighbours.k, input, cloud.rows());
    requireBelowPointCount(a, "--bins", options.bins, input, cloud.rows());
    const Eigen::VectorXd H = curvatureOf(settings, cloud);
    const std::vector<double> values(H.data(), H.data() + H.size());
    // Sec. 2.3: the next lower (higher) threshold searches only the values below (above) T.
    const ThresholdResult r = below   ? findLowerThreshold(values, previous, options)
                              : above ? findHigherThreshold(values, previous, options)
                                      : findThreshold(values, options);
    const long low =
        std::count_if(values.begin(), values.end(), [&](double v) { return v <= r.threshold; });
    const long high = static_cast<long>(values.size()) - low;

    if (!a.has("--json")) {
        std::cout << "threshold: " << Arguments::format(r.threshold) << "\n"
                  << "ratio: " << Arguments::format(r.ratio) << "\n"
                  << "low points: " << low << "\n"
                  << "high points: " << high << "\n";
        return 0;
    }
    using namespace json;
    Object result;
    result.add("points", number(static_cast<long>(values.size())))
        .add("threshold", number(r.threshold))
        .add("ratio", number(r.ratio))
        .add("start_curv", number(r.startCurv))
        .add("joined_bins", number(static_cast<long>(r.joinedBins)))
        .add("peak_count", number(r.peakCount))
        .add("valley_count", number(r.valleyCount))
        .add("outlier_cut", number(r.outlierCut))
        .add("low_points", number(low))
        .add("high_points", number(high))
        .add("search",
             string(options.search == ThresholdSearch::SingleRun ? "single-run" : "all-starts"))
        .add("range", string(below ? "below" : (above ? "above" : "all")))
        .add("histogram", histogramJson(r.histogram))
        .add("bin_edges", array(binEdges(r.histogram)));
    std::cout << result.str() << "\n";
    return 0;
}

// ---- extract ------------------------------------------------------------------------------

/// One of the words in `allowed` (the option's value), or a UsageError listing them.
int choice(const Arguments& a, const std::string& name, const std::vector<std::string>& allowed,
           int fallback)
{
    if (!a.has(name)) {
        return fallback;
    }
    const std::string value = a.text(name);
    for (std::size_t i = 0; i < allowed.size(); ++i) {
        if (allowed[i] == value) {
            return static_cast<int>(i);
        }
    }
    std::string list;
    for (const std::string& w : allowed) {
        list += (list.empty() ? "" : ", ") + w;
    }
    throw UsageError(name + " must be one of " + list + ", got '" + value + "'");
}

/// "0.3,0.05" -> {0.3, 0.05}: finite, not negative.
std::vector<double> thresholdList(const std::string& text)
{
    std::vector<double> values;
    std::stringstream words(text);
    std::string word;
    while (std::getline(words, word, ',')) {
        const double v = Arguments::parseNumber("--thresholds", word);
        if (v < 0.0) {
            throw UsageError("--thresholds must not be negative, got " + word);
        }
        values.push_back(v);
    }
    if (values.empty()) {
        throw UsageError("--thresholds needs at least one value, e.g. --thresholds 0.3,0.05");
    }
    return values;
}

ExtractionOptions extractionOptions(const Arguments& a)
{
    ExtractionOptions o;
    o.neighbours.k = neighbourCount(a);
    o.neighbours.threads = threadCount(a);
    o.sharpEdges = !a.has("--no-sharp");
    o.smoothEdges = !a.has("--no-smooth");
    o.sharp.includeBoundary = !a.has("--no-boundary");
    o.smooth.smoothing =
        static_cast<SmoothingMode>(choice(a, "--smoothing", {"automatic", "always", "never"}, 0));
    o.smooth.smoothingOptions.iterations =
        static_cast<int>(a.integer("--smooth", o.smooth.smoothingOptions.iterations, 0, 1000));
    o.smooth.histogram.bins =
        static_cast<int>(a.integer("--bins", o.smooth.histogram.bins, 2, 1000000));
    o.smooth.scales.maxScale = a.number("--max-scale", o.smooth.scales.maxScale, 1.0, 1000.0, true);
    o.smooth.placeCoarseLines = !a.has("--no-line-placement");
    o.smooth.placeOwnScaleLines = o.smooth.placeCoarseLines;
    if (a.has("--outliers")) {
        o.smooth.histogram.outlierPercent = a.number("--outliers", 0.0, 0.0, 100.0, false);
    }
    o.thresholdMode = static_cast<ThresholdMode>(
        choice(a, "--threshold-mode", {"automatic", "first", "explicit"}, 0));
    if (a.has("--thresholds")) {
        if (a.has("--threshold-mode") && o.thresholdMode != ThresholdMode::Explicit) {
            throw UsageError("--thresholds goes with --threshold-mode explicit");
        }
        o.thresholdMode = ThresholdMode::Explicit;
        o.thresholds = thresholdList(a.text("--thresholds"));
    } else if (o.thresholdMode == ThresholdMode::Explicit) {
        throw UsageError("--threshold-mode explicit needs --thresholds T1,T2,...");
    }
    return o;
}

/// Every scale a region's curvature weighed, as a JSON array.
std::string scaleTrialsJson(const std::vector<RegionGeometry::ScaleTrial>& scaleTrials)
{
    using namespace json;
    std::string trials = "[";
    for (std::size_t t = 0; t < scaleTrials.size(); ++t) {
        const RegionGeometry::ScaleTrial& st = scaleTrials[t];
        Object trial;
        trial.add("scale", number(st.scale))
            .add("points", number(static_cast<long>(st.points)))
            .add("noise", number(st.noise))
            .add("accepted_thresholds", number(static_cast<long>(st.acceptedThresholds)))
            .add("separation", number(st.separation));
        trials += (t ? ", " : "") + trial.str();
    }
    return trials + "]";
}

/// The region reports of the result as a JSON array.
std::string regionsJson(const ExtractionResult& r)
{
    using namespace json;
    std::string regions = "[";
    for (std::size_t i = 0; i < r.regions.size(); ++i) {
        const RegionReport& rr = r.regions[i];
        Object region;
        region.add("region", number(static_cast<long>(rr.region)))
            .add("points", number(static_cast<long>(rr.points)))
            .add("noise", number(rr.noise))
            .add("smoothed", rr.smoothed ? "true" : "false")
            .add("curvature_scale", number(rr.curvatureScale));
        if (!rr.scaleTrials.empty()) {
            region.add("scale_trials", scaleTrialsJson(rr.scaleTrials));
        }
        region.add("thresholds", array(rr.thresholds));
        regions += (i ? ", " : "") + region.str();
    }
    return regions + "]";
}

/// The lines file (--output): the input, its point count and the result.
void writeLinesFile(const std::string& output, const std::string& input, Eigen::Index points,
                    const ExtractionResult& r, const CurveNetwork& net,
                    const std::vector<PatchBorder>& borders)
{
    using namespace json;
    Object result;
    result.add("input", string(input))
        .add("points", number(static_cast<long>(points)))
        .add("spacing", number(r.spacing))
        .add("lines", linesJson(r))
        .add("junctions", json::points(r.junctions))
        .add("regions", regionsJson(r))
        .add("network", networkJson(net, borders));
    writeWhole(output, result.str() + "\n");
}

/// "curves: 12 (segment 12, arc 0, circle 0, bspline 0), vertices 8, patches closed 6 of 6".
std::string curveSummary(const CurveNetwork& net, const std::vector<PatchBorder>& borders)
{
    int kinds[4] = {0, 0, 0, 0};
    for (const NetworkEdge& e : net.edges) {
        ++kinds[static_cast<int>(e.curve.kind)];
    }
    int closed = 0;
    for (const PatchBorder& b : borders) {
        closed += b.closed() ? 1 : 0;
    }
    std::ostringstream out;
    out << "curves: " << net.edges.size() << " (segment " << kinds[0] << ", arc " << kinds[1]
        << ", circle " << kinds[2] << ", bspline " << kinds[3] << "), vertices "
        << net.vertices.rows() << ", patches closed " << closed << " of " << borders.size();
    return out.str();
}

/// The labels file (--labels): per input point its region, patch, label and curvature; -1
/// where a point has none (the Python API's convention), NaN curvature off every region.
void writeLabelsFile(const std::string& file, const ExtractionResult& r)
{
    std::ostringstream labels;
    labels << "# region patch label curvature (region -1: on a sharp edge's band; patch -1: "
              "in no region; label: 0 low, 1 inner, 2 border, 3 noisy, -1 outside every region)\n"
           << std::setprecision(9);
    for (std::size_t i = 0; i < r.region.size(); ++i) {
        const int label = r.label[i] == PointLabel::Outside ? -1 : static_cast<int>(r.label[i]);
        labels << r.region[i] << ' ' << r.patch[i] << ' ' << label << ' '
               << r.curvature[static_cast<Eigen::Index>(i)] << '\n';
    }
    writeWhole(file, labels.str());
}

/// "lines: 12 (sharp 12, smooth 0, boundary 0), closed 12, junctions 8, regions 6".
std::string lineSummary(const ExtractionResult& r)
{
    int closed = 0;
    for (const FeatureLine& l : r.lines) {
        closed += l.closed ? 1 : 0;
    }
    std::ostringstream out;
    out << "lines: " << r.lines.size() << " (sharp " << r.countLines(LineType::Sharp) << ", smooth "
        << r.countLines(LineType::Smooth) << ", boundary " << r.countLines(LineType::Boundary)
        << "), closed " << closed << ", junctions " << r.junctions.rows() << ", regions "
        << r.regions.size();
    return out.str();
}

/// Where one input's results go: its lines file and, with --labels, its labels file ("" none).
struct ExtractTarget
{
    std::string input;
    std::string lines;
    std::string labels;
    /// With --curves: the fitted curves as polylines, OBJ or PLY by its extension.
    std::string curves;
};

/// How progress is shown (Progress.h): not at all, rewritten in place, or line by line.
enum class ProgressMode
{
    None,
    Terminal,
    Lines
};

ProgressMode progressMode(const Arguments& a)
{
    if (a.has("--quiet") && a.has("--progress")) {
        throw UsageError("--quiet and --progress exclude each other");
    }
    if (a.has("--progress-every") && !a.has("--progress")) {
        throw UsageError("--progress-every needs --progress");
    }
    if (a.has("--quiet")) {
        return ProgressMode::None;
    }
    if (a.has("--progress")) {
        return ProgressMode::Lines;
    }
#if __has_include(<unistd.h>)
    return isatty(STDERR_FILENO) ? ProgressMode::Terminal : ProgressMode::None;
#else
    return ProgressMode::None;
#endif
}

/// The folder `option` names in a batch; std::runtime_error (bad input) unless it is one.
std::filesystem::path batchFolder(const Arguments& a, const std::string& option,
                                  const std::string& what)
{
    const std::string folder = a.text(option);
    if (folder == "-") {
        throw UsageError(option + " - (standard output) takes one input only, not several");
    }
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) {
        throw std::runtime_error(folder + ": is not a folder; with several inputs " + option +
                                 " names the folder for their " + what);
    }
    return folder;
}

/// The inputs of extract and their outputs. One INPUT file (or -): -o and --labels name files
/// (or - for standard output). Several inputs or a folder: -o and --labels name folders, and
/// INPUT's results are FOLDER/NAME.json and LABELS/NAME.labels.txt (NAME: INPUT's name without
/// its extension). UsageError for two inputs that would write one file.
std::vector<ExtractTarget> extractTargets(const Arguments& a)
{
    if (a.positional().empty()) {
        throw UsageError("no INPUT point cloud given");
    }
    if (!a.has("--output")) {
        throw UsageError("no output file given (-o LINES.json; -o FOLDER for several inputs)");
    }
    std::error_code error;
    const bool batch =
        a.positional().size() > 1 || std::filesystem::is_directory(a.positional()[0], error);
    if (!batch) {
        const std::string curves = a.text("--curves");
        if (!curves.empty() && curves != "-") {
            curveFileFormat(curves);
        }
        return {{a.positional()[0], a.text("--output"), a.text("--labels"), curves}};
    }
    const std::vector<std::string> inputs = expandInputs(a.positional());
    if (std::find(inputs.begin(), inputs.end(), "-") != inputs.end()) {
        throw UsageError("standard input (-) can only be the one INPUT, not one of several");
    }
    const std::filesystem::path linesFolder = batchFolder(a, "--output", "lines files");
    const std::filesystem::path labelsFolder =
        a.has("--labels") ? batchFolder(a, "--labels", "labels files") : std::filesystem::path();
    const std::filesystem::path curvesFolder =
        a.has("--curves") ? batchFolder(a, "--curves", "curve files") : std::filesystem::path();
    std::vector<ExtractTarget> targets;
    for (const std::string& input : inputs) {
        const std::string name = std::filesystem::path(input).stem().string();
        ExtractTarget t{input, (linesFolder / (name + ".json")).string(), {}};
        if (a.has("--labels")) {
            t.labels = (labelsFolder / (name + ".labels.txt")).string();
        }
        if (a.has("--curves")) {
            t.curves = (curvesFolder / (name + ".obj")).string();
        }
        for (const ExtractTarget& other : targets) {
            if (other.lines == t.lines) {
                throw UsageError(other.input + " and " + input + " would both write " + t.lines +
                                 ": rename one of them");
            }
        }
        targets.push_back(t);
    }
    return targets;
}

/// The output files of every target, checked before any work (checkOutputs); in a batch also
/// no output may be another input.
void checkTargets(const std::vector<ExtractTarget>& targets)
{
    for (const ExtractTarget& t : targets) {
        std::vector<OutputFile> outputs{{"--output", t.lines}};
        if (!t.labels.empty()) {
            outputs.push_back({"--labels", t.labels});
        }
        if (!t.curves.empty()) {
            outputs.push_back({"--curves", t.curves});
        }
        checkOutputs(t.input, outputs);
        for (const ExtractTarget& other : targets) {
            for (const OutputFile& o : outputs) {
                if (&other != &t && sameFile(o.path, other.input)) {
                    throw UsageError(o.path + " (for " + t.input + ") is the input " + other.input +
                                     "; it would be overwritten");
                }
            }
        }
    }
}

/// One input's extraction: read, extract, write its files. Returns its summary line.
std::string extractOne(const Arguments& a, const ExtractTarget& t, ExtractionOptions options,
                       const std::string& format, ProgressMode mode)
{
    const PointMatrix cloud = readInput(t.input, format);
    requireBelowPointCount(a, "--k", options.neighbours.k, t.input, cloud.rows());
    requireBelowPointCount(a, "--bins", options.smooth.histogram.bins, t.input, cloud.rows());
    const double every = a.number("--progress-every", 1.0, 0.0, 3600.0, true);
    ProgressReport report(std::cerr, inputName(t.input), mode == ProgressMode::Terminal, every);
    if (mode != ProgressMode::None) {
        options.progress = [&report](double done, const std::string& stage) {
            return report(done, stage);
        };
        options.progressInterval = std::min(options.progressInterval, every);
    }
    ExtractionResult r;
    try {
        r = extractFeatureLines(cloud, options);
    } catch (...) {
        report.abandon();
        throw;
    }
    if (mode != ProgressMode::None) {
        report.finish();
    }
    // The lines as CAD geometry: fitted curves on shared vertices, the patches' borders.
    CurveFitOptions fit;
    fit.cornerAngle = a.number("--corner-angle", fit.cornerAngle, 0.0, 180.0, true);
    const CurveNetwork net = fitCurveNetwork(r, fit);
    const std::vector<PatchBorder> borders = patchBorders(net, r, cloud);
    writeLinesFile(t.lines, t.input, cloud.rows(), r, net, borders);
    if (!t.labels.empty()) {
        writeLabelsFile(t.labels, r);
    }
    if (!t.curves.empty()) {
        // Half a spacing between samples: a curve's polyline stays within a small fraction of
        // a spacing of it.
        const CurveFileFormat format =
            t.curves == "-" ? CurveFileFormat::Obj : curveFileFormat(t.curves);
        writeWhole(t.curves, curveFileText(net, 0.5 * r.spacing, format));
    }
    return lineSummary(r) + (r.lines.empty() ? "\nno feature lines: the cloud has no sharp edge, "
                                               "boundary or curvature valley"
                                             : "\n" + curveSummary(net, borders));
}

int runExtract(const Arguments& a)
{
    const std::vector<ExtractTarget> targets = extractTargets(a);
    const ExtractionOptions options = extractionOptions(a);
    const ProgressMode mode = progressMode(a);
    const std::string format = standardInputFormat(a, targets.front().input == "-");
    checkTargets(targets);
    if (targets.size() == 1) {
        const ExtractTarget& t = targets.front();
        const std::string summary = extractOne(a, t, options, format, mode);
        // A result on standard output keeps it clean: the summary goes to standard error.
        (t.lines == "-" || t.labels == "-" || t.curves == "-" ? std::cerr : std::cout)
            << summary << "\n";
        return 0;
    }
    // A batch: every input is tried; one summary line each, and the exit code 1 when any failed.
    int failed = 0;
    for (const ExtractTarget& t : targets) {
        std::string summary;
        try {
            summary = extractOne(a, t, options, format, mode);
            summary = summary.substr(0, summary.find('\n'));
        } catch (const std::exception& e) {
            ++failed;
            const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
            const std::string reason = memory ? std::string("out of memory") : e.what();
            const bool named = reason.find(t.input) != std::string::npos;
            std::cerr << "featurelines: " << (named ? "" : t.input + ": ") << reason << std::endl;
            summary = "failed";
        }
        std::cout << t.input << ": " << summary << std::endl;
    }
    std::cout << targets.size() << " inputs: " << targets.size() - failed << " done, " << failed
              << " failed\n";
    return failed == 0 ? 0 : 1;
}

// ---- the table ----------------------------------------------------------------------------

const std::vector<Command>& commands()
{
    static const std::vector<Command> table{
        {"info",
         "point count, bounding box and mean point spacing of a cloud",
         "INPUT [--k N]",
         {{"--k", "N", "neighbours searched for the spacing (default 16; fewer on tiny clouds)"},
          formatOption(),
          threadsOption()},
         runInfo},
        {"curvature",
         "mean curvature of every point, one value per line in input order (Sec. 2.1)",
         "INPUT -o FILE [--k N] [--signed] [--smooth N]",
         {{"--output", "FILE", "the file to write (- for standard output)", "-o"},
          kOption(),
          signedOption(),
          smoothOption(),
          formatOption(),
          threadsOption()},
         runCurvature},
        {"threshold",
         "curvature threshold by multi-resolution histogram analysis (Sec. 2.2-2.4)",
         "INPUT [--below T | --above T] [--bins L] [--outliers PCT] [--single-run] [--k N] "
         "[--json]",
         {{"--below", "T", "next lower threshold: search only the values <= T (Sec. 2.3)"},
          {"--above", "T", "next higher threshold: search only the values > T (Sec. 2.3)"},
          {"--bins", "L",
           "start resolution L_start, 2 to 1000000 and below the point count (default 50, "
           "Sec. 2.2)"},
          {"--outliers", "PCT",
           "drop this percentage of the highest curvatures first, 0 <= PCT < 100 (default 0, "
           "Sec. 2.4)"},
          {"--min-peak", "PCT",
           "smallest peak a threshold may follow, in percent of the values (default 1)"},
          {"--single-run", "", "start_curv = min(curv) only, the paper's short pseudo-code"},
          {"--json", "", "print one JSON object with the histogram and its bin edges"},
          kOption(),
          signedOption(),
          smoothOption(),
          formatOption(),
          threadsOption()},
         runThreshold},
        {"extract",
         "closed feature lines: sharp edges, smooth edges (fillet borders) and boundary",
         "INPUT... -o LINES.json|FOLDER [--labels FILE|FOLDER] [--curves FILE|FOLDER] "
         "[--thresholds T1,T2 | "
         "--threshold-mode M] [--smoothing M] [--no-sharp] [--no-smooth] [--no-boundary] [--k N] "
         "[--progress [--progress-every S] | --quiet]",
         {{"--output", "FILE",
           "the lines as JSON: {\"lines\": [{\"type\", \"closed\", \"angle\" (sharp: "
           "degrees inside the wedge), \"blend_radius\" (smooth), null where not estimated, "
           "\"points\"}], \"junctions\", \"regions\" (per region: its noise, thresholds used, "
           "curvature scale and the coarser scales weighed, scale_trials), \"network\" (the "
           "fitted curves: vertices, edges, patch_borders)}; - for standard output. With several "
           "INPUTs or a folder: the folder that gets NAME.json for each "
           "input NAME.ext, one summary line each, exit 1 when any failed",
           "-o"},
          {"--labels", "FILE",
           "also write per input point: smooth region, patch, Sec. 3 label, curvature (-1: no "
           "region, patch or label); with several inputs the folder for NAME.labels.txt"},
          {"--curves", "FILE",
           "also write the fitted curves as polylines sampled every half spacing, sharing the "
           "network's vertices: FILE.obj (v and l records) or FILE.ply (vertex and edge "
           "elements), for CloudCompare, MeshLab or Blender; - for OBJ on standard output; "
           "with several inputs the folder for NAME.obj"},
          {"--threshold-mode", "M",
           "automatic (every significant valley per region), first (the first threshold only), "
           "explicit (--thresholds); default automatic"},
          {"--thresholds", "T1,T2", "explicit curvature thresholds (1/length) for every region"},
          {"--smoothing", "M",
           "automatic (when a region is noisy), always or never (Sec. 2.4; default automatic)"},
          {"--smooth", "N", "Taubin passes when a region is smoothed (default 20)"},
          {"--bins", "L",
           "start resolution L_start, 2 to 1000000 and below the point count (default 50, "
           "Sec. 2.2)"},
          {"--outliers", "PCT",
           "drop this percentage of the highest curvatures (default: 1 in noisy regions, else 0)"},
          {"--max-scale", "S",
           "coarsest scale of the curvature, x spacing, 1 to 1000 (default 8; 1: the cloud's "
           "own sampling only)"},
          {"--no-line-placement", "",
           "leave the smooth lines where the curvature's levels put them (default: moved onto "
           "the curvature step of the points under them)"},
          {"--corner-angle", "DEG",
           "also cut the fitted curves where a line's direction breaks by DEG degrees or more, "
           "0 to 180 (default 180: at junctions only; 30 cuts a flat face's border between "
           "fillets at its corners, on clean clouds)"},
          {"--no-sharp", "", "no sharp edges (the whole cloud is one smooth region)"},
          {"--no-smooth", "", "no smooth edges"},
          {"--no-boundary", "", "no boundary lines of an open cloud"},
          {"--progress", "",
           "progress and time left on standard error even when it is not a terminal (default: "
           "shown on a terminal only)"},
          {"--progress-every", "S",
           "with --progress, the least time between two lines within one stage, seconds "
           "(default 1; 0: a line at every report, each 1/64 of a long loop's points)"},
          {"--quiet", "", "no progress on standard error"},
          kOption(),
          formatOption(),
          threadsOption()},
         runExtract},
    };
    return table;
}

void printOverview(std::ostream& out)
{
    out << "usage: featurelines COMMAND [OPTIONS] INPUT\n"
           "       featurelines COMMAND --help\n"
           "       featurelines --version\n\n"
           "Closed feature lines of point clouds (Demarsin et al. 2008).\n"
           "INPUT: .xyz .txt .asc .csv (x y z per line), .ply or .pcd; - for standard input\n"
           "(--format says which). extract takes several INPUTs or a folder.\n\ncommands:\n";
    for (const Command& c : commands()) {
        out << "  " << c.name << std::string(12 - std::min<std::size_t>(11, c.name.size()), ' ')
            << c.summary << "\n";
    }
}

/// `text` broken at spaces into lines of at most 100 columns, lines after the first indented.
std::string wrapped(const std::string& text, std::size_t indent)
{
    const std::size_t width = 100 - indent;
    std::string out;
    std::size_t lineStart = 0;
    while (text.size() - lineStart > width) {
        std::size_t cut = text.rfind(' ', lineStart + width);
        if (cut == std::string::npos || cut <= lineStart) {
            cut = text.find(' ', lineStart + width);
            if (cut == std::string::npos) {
                break;
            }
        }
        out += text.substr(lineStart, cut - lineStart) + "\n" + std::string(indent, ' ');
        lineStart = cut + 1;
    }
    return out + text.substr(lineStart);
}

void printCommandHelp(const Command& c)
{
    const std::string prefix = "usage: featurelines " + c.name + " ";
    std::cout << prefix << wrapped(c.synopsis, prefix.size()) << "\n\n"
              << c.summary << "\n\noptions:\n";
    for (const OptionSpec& o : c.options) {
        std::string left = o.shortName.empty() ? o.name : o.shortName + ", " + o.name;
        if (!o.valueName.empty()) {
            left += " " + o.valueName;
        }
        std::cout << "  " << left << std::string(20 - std::min<std::size_t>(18, left.size()), ' ')
                  << wrapped(o.help, 22) << "\n";
    }
    std::cout << "  -h, --help          this text\n";
}

const Command* findCommand(const std::string& name)
{
    for (const Command& c : commands()) {
        if (c.name == name) {
            return &c;
        }
    }
    return nullptr;
}

int runMain(const std::vector<std::string>& words)
{
    if (words.empty()) {
        throw UsageError("no command given (featurelines --help lists them)");
    }
    if (words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        printOverview(std::cout);
        return 0;
    }
    if (words[0] == "--version") {
        std::cout << "featurelines " << FEATURELINES_VERSION << "\n";
        return 0;
    }
    const Command* command = findCommand(words[0]);
    if (!command) {
        throw UsageError("unknown command '" + words[0] + "' (featurelines --help lists them)");
    }
    const std::vector<std::string> rest(words.begin() + 1, words.end());
    if (std::find_if(rest.begin(), rest.end(), [](const std::string& w) {
            return w == "--help" || w == "-h";
        }) != rest.end()) {
        printCommandHelp(*command);
        return 0;
    }
    try {
        return command->run(Arguments(rest, command->options));
    } catch (const UsageError& e) {
        throw UsageError(std::string(e.what()) + " (featurelines " + command->name + " --help)");
    }
}

} // namespace
} // namespace featurelines::cli

int main(int argc, char** argv)
{
    using namespace featurelines::cli;
    try {
        return runMain(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::cerr << "featurelines: " << e.what() << std::endl;
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "featurelines: out of memory" << std::endl;
        return 1;
    } catch (const std::exception& e) {
        // std::invalid_argument from the core: the input data, not the call, is at fault.
        std::cerr << "featurelines: " << e.what() << std::endl;
        return 1;
    }
}
