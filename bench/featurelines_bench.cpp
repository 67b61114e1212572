// SPDX-License-Identifier: LGPL-2.1-or-later
// Performance benchmark of the core stages on seeded rounded cubes of 100k and 1M points, with
// PCL's NormalEstimationOMP (and KdTreeFLANN for the kNN step) as the yardstick.
// A program, not a test: timings depend on the machine. docs/PERFORMANCE.md shows a run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <malloc.h>
#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include "FeatureLines/io/CloudIO.h"
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/Extraction.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "FeatureLines/cli/Arguments.h"
#include "PclYardstick.h"
#include "SampledShapes.h"

#ifndef FEATURELINES_BENCH_FLAGS
#define FEATURELINES_BENCH_FLAGS "unknown"
#endif

namespace featurelines::bench {
namespace {

using cli::Arguments;
using cli::OptionSpec;
using cli::UsageError;

// ---- the shape ----------------------------------------------------------------------------

/// The benchmark's rounded cube: edge 40, fillet radius 6 (the proportions of the paper's
/// Fig. 7), sampled at the spacing that gives about `points` points.
constexpr double cubeEdge = 40.0;
constexpr double cubeRadius = 6.0;
constexpr unsigned cubeSeed = 2008;

double spacingFor(long points)
{
    const double pi = std::acos(-1.0);
    const double flat = cubeEdge - 2.0 * cubeRadius;
    // Six flat squares, twelve quarter cylinders, eight eighth spheres.
    const double area =
        6.0 * flat * flat + 6.0 * pi * cubeRadius * flat + 4.0 * pi * cubeRadius * cubeRadius;
    return std::sqrt(area / static_cast<double>(points));
}

// ---- memory -------------------------------------------------------------------------------

/// Resets the kernel's peak-RSS mark to the current RSS (Linux >= 4.0), so that ru_maxrss
/// afterwards is the peak of one stage. False where that is not possible: then ru_maxrss is
/// the peak since the program started.
bool resetPeakRss()
{
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.close();
    return static_cast<bool>(clear);
}

double peakRssMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // KiB on Linux
}

/// User plus system CPU seconds of all threads of the process so far.
double cpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double currentRssMiB()
{
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
           (1024.0 * 1024.0);
}

// ---- measuring ----------------------------------------------------------------------------

struct Row
{
    std::string stage;
    std::vector<double> seconds;
    /// CPU seconds of all threads: less sensitive than wall time to other processes on a
    /// shared machine.
    std::vector<double> cpu;
    double outputMiB = 0.0;
    double startRssMiB = 0.0;
    double peakRssMiB = 0.0;
    /// A share of the whole extraction (timed by its progress callback, not run on its own):
    /// no memory columns.
    bool part = false;

    double median() const { return medianOf(seconds); }
    double medianCpu() const { return medianOf(cpu); }

    static double medianOf(std::vector<double> s)
    {
        std::sort(s.begin(), s.end());
        const std::size_t n = s.size();
        return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    }
};

bool peakIsPerStage = true;

/// Runs `stage` `runs` times; it returns the bytes of its output. The peak RSS is the largest
/// over the runs (of the whole process: the cloud and the earlier stages' outputs included),
/// the start RSS the one before the first run.
Row measure(const std::string& name, int runs, const std::function<std::size_t()>& stage)
{
    Row row;
    row.stage = name;
    // Memory freed by earlier stages goes back to the system, or a stage reusing it would not
    // show in its peak.
    malloc_trim(0);
    row.startRssMiB = currentRssMiB();
    for (int r = 0; r < runs; ++r) {
        malloc_trim(0);
        peakIsPerStage = resetPeakRss() && peakIsPerStage;
        const double cpuStart = cpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        const std::size_t bytes = stage();
        const auto stop = std::chrono::steady_clock::now();
        row.seconds.push_back(std::chrono::duration<double>(stop - start).count());
        row.cpu.push_back(cpuSeconds() - cpuStart);
        row.outputMiB = static_cast<double>(bytes) / (1024.0 * 1024.0);
        row.peakRssMiB = std::max(row.peakRssMiB, peakRssMiB());
    }
    return row;
}

/// Adds one more run's figures to `into` (empty: the run's row itself).
void append(Row& into, const Row& run)
{
    if (into.seconds.empty()) {
        into = run;
        return;
    }
    into.seconds.insert(into.seconds.end(), run.seconds.begin(), run.seconds.end());
    into.cpu.insert(into.cpu.end(), run.cpu.begin(), run.cpu.end());
    into.outputMiB = run.outputMiB;
    into.peakRssMiB = std::max(into.peakRssMiB, run.peakRssMiB);
}

/// Runs two stages in turn, `runs` times each (a, b, a, b, ...). A machine whose speed drifts
/// over minutes (a shared virtual machine, a throttled processor) then slows both alike: their
/// ratio, run by run, holds where two medians taken a minute apart would not.
std::pair<Row, Row> measureInTurn(const std::string& nameA, const std::function<std::size_t()>& a,
                                  const std::string& nameB, const std::function<std::size_t()>& b,
                                  int runs)
{
    Row first, second;
    for (int r = 0; r < runs; ++r) {
        append(first, measure(nameA, 1, a));
        append(second, measure(nameB, 1, b));
    }
    return {first, second};
}

std::size_t bytesOf(const Neighbourhoods& N)
{
    return static_cast<std::size_t>(N.indices.size()) * sizeof(int) +
           static_cast<std::size_t>(N.squaredDistances.size()) * sizeof(double);
}

struct Result
{
    std::string cloud; // what was measured, for the table's title
    long points = 0;
    double spacing = 0.0;
    std::vector<Row> rows;
    std::string lines; // what the whole extraction found

    const Row& row(const std::string& stage) const
    {
        return *std::find_if(rows.begin(), rows.end(),
                             [&](const Row& r) { return r.stage == stage; });
    }
    bool has(const std::string& stage) const
    {
        return std::any_of(rows.begin(), rows.end(),
                           [&](const Row& r) { return r.stage == stage; });
    }
};

const char* const knnStage = "nearestNeighbours k=16";
const char* const normalsStage = "pcaNormals";
const char* const curvatureStage = "meanCurvature";
const char* const wholeStage = "extractFeatureLines (whole, default options)";
const char* const pclNormalsStage = "PCL NormalEstimationOMP k=16";
const char* const pclKnnStage = "PCL KdTreeFLANN kNN k=16";

/// Times the steps of one extraction through its progress callback: each call ends the step
/// named by the previous one. The region steps are summed over the regions.
class StepClock
{
public:
    StepClock() { mark("validation, duplicates merged"); }

    bool operator()(double, const std::string& stage)
    {
        mark(stage);
        return true;
    }

    /// Per step, in the order first met: wall and CPU seconds.
    const std::vector<std::pair<std::string, std::pair<double, double>>>& steps() const
    {
        return steps_;
    }

private:
    void mark(const std::string& stage)
    {
        const auto now = std::chrono::steady_clock::now();
        const double cpu = cpuSeconds();
        if (!current_.empty()) {
            auto it = std::find_if(steps_.begin(), steps_.end(),
                                   [&](const auto& s) { return s.first == current_; });
            if (it == steps_.end()) {
                steps_.push_back({current_, {0.0, 0.0}});
                it = steps_.end() - 1;
            }
            it->second.first += std::chrono::duration<double>(now - start_).count();
            it->second.second += cpu - cpuStart_;
        }
        // "curvature of smooth region 3" and "smooth edges of region 3": one step each.
        std::string name = stage;
        const auto digits = name.find_last_not_of("0123456789");
        if (digits != std::string::npos && digits + 1 < name.size() && name[digits] == ' ') {
            name = name.substr(0, digits) + "s";
        }
        current_ = name == "done" ? std::string() : name;
        start_ = now;
        cpuStart_ = cpu;
    }

    std::string current_;
    std::chrono::steady_clock::time_point start_;
    double cpuStart_ = 0.0;
    std::vector<std::pair<std::string, std::pair<double, double>>> steps_;
};

/// The cloud measured: a seeded rounded cube of about `points` points, with normal noise of
/// `noise` spacings, or the points of a file.
struct Cloud
{
    std::string name;
    PointMatrix points;
    double spacing = 0.0; // 0: not known before the neighbours
};

Cloud roundedCubeCloud(long points, double noise)
{
    Cloud c;
    c.spacing = spacingFor(points);
    shapes::Sample cube = shapes::roundedCube(cubeEdge, cubeRadius, c.spacing, cubeSeed);
    if (noise > 0.0) {
        shapes::addNormalNoise(cube, noise * c.spacing, cubeSeed + 1);
    }
    c.points = std::move(cube.points);
    std::ostringstream name;
    name.imbue(std::locale::classic());
    name << "rounded cube";
    if (noise > 0.0) {
        name << ", normal noise " << noise << " x spacing";
    }
    c.name = name.str();
    return c;
}

Result runOne(const Cloud& cloud, int runs, int threads, bool stages)
{
    Result result;
    result.cloud = cloud.name;
    result.spacing = cloud.spacing;
    const PointMatrix& P = cloud.points;
    result.points = static_cast<long>(P.rows());
    const auto n = static_cast<std::size_t>(P.rows());
    std::cerr << cloud.name << ": " << result.points << " points\n";

    NeighbourOptions nopt;
    nopt.k = 16;
    nopt.threads = threads;
    Neighbourhoods N;
    NormalEstimate normals;
    Eigen::VectorXd H;
    RingNeighbourhoods rings;
    PointMatrix smoothed;
    std::vector<int> all(n);
    std::iota(all.begin(), all.end(), 0);

    // Each stage drops its previous output first, so the peak holds one copy of it.
    result.rows.push_back(measure(knnStage, runs, [&] {
        N = Neighbourhoods{};
        N = nearestNeighbours(P, nopt);
        return bytesOf(N);
    }));
    if (result.spacing == 0.0) {
        result.spacing = meanSpacing(N);
    }
    result.rows.push_back(measure(normalsStage, runs, [&] {
        normals = NormalEstimate{};
        NormalOptions o;
        o.threads = threads;
        normals = pcaNormals(P, N, o);
        return n * (3 + 1) * sizeof(double);
    }));
    result.rows.push_back(measure(curvatureStage, runs, [&] {
        H = Eigen::VectorXd{};
        CurvatureOptions o;
        o.threads = threads;
        H = meanCurvature(P, normals.normals, N, o);
        return n * sizeof(double);
    }));
    if (stages) {
        result.rows.push_back(measure("ringNeighbourhoods", runs, [&] {
            rings = RingNeighbourhoods{};
            RingOptions o;
            o.threads = threads;
            rings = ringNeighbourhoods(P, normals.normals, N, o);
            return (rings.offsets.size() + rings.indices.size()) * sizeof(int);
        }));
        result.rows.push_back(measure("laplacianSmooth (5 Taubin passes, all points)", runs, [&] {
            smoothed = PointMatrix{};
            smoothed = laplacianSmooth(P, N, all);
            return n * 3 * sizeof(double);
        }));
        const std::vector<double> values(H.data(), H.data() + H.size());
        result.rows.push_back(measure("findThreshold (L_start 50, all starts)", runs, [&] {
            const ThresholdResult r = findThreshold(values);
            return r.histogram.counts.size() * sizeof(long);
        }));
    }
    N = Neighbourhoods{};
    normals = NormalEstimate{};
    H = Eigen::VectorXd{};
    rings = RingNeighbourhoods{};
    smoothed = PointMatrix{};

    // The whole method with its default options, as `featurelines extract` runs it, in turn
    // with the yardstick on the same points (converted once to PCL's type); its steps are
    // timed through the progress callback (medians over the runs).
    const PclCloud pcl(P);
    std::vector<StepClock> clocks;
    const auto whole = [&] {
        ExtractionResult extraction;
        ExtractionOptions o;
        o.neighbours.threads = threads;
        clocks.emplace_back();
        StepClock& clock = clocks.back();
        o.progress = [&clock](double done, const std::string& stage) { return clock(done, stage); };
        extraction = extractFeatureLines(P, o);
        std::size_t bytes = extraction.region.size() * (2 * sizeof(int) + 1 + sizeof(double));
        for (const FeatureLine& l : extraction.lines) {
            bytes += static_cast<std::size_t>(l.points.size()) * sizeof(double);
        }
        result.lines = std::to_string(extraction.lines.size()) + " lines (sharp " +
                       std::to_string(extraction.countLines(LineType::Sharp)) + ", smooth " +
                       std::to_string(extraction.countLines(LineType::Smooth)) + ", boundary " +
                       std::to_string(extraction.countLines(LineType::Boundary)) + "), " +
                       std::to_string(extraction.junctions.rows()) + " junctions, " +
                       std::to_string(extraction.regions.size()) + " smooth regions";
        return bytes;
    };
    auto [wholeRow, pclRow] = measureInTurn(
        wholeStage, whole, pclNormalsStage, [&] { return pcl.normalEstimationOmp(16, threads); },
        runs);
    result.rows.push_back(std::move(wholeRow));
    for (const auto& [name, seconds] : clocks.front().steps()) {
        Row part;
        part.stage = "- " + name;
        part.part = true;
        for (const StepClock& clock : clocks) {
            for (const auto& [other, s] : clock.steps()) {
                if (other == name) {
                    part.seconds.push_back(s.first);
                    part.cpu.push_back(s.second);
                }
            }
        }
        result.rows.push_back(part);
    }
    result.rows.push_back(std::move(pclRow));
    if (stages) {
        result.rows.push_back(
            measure(pclKnnStage, runs, [&] { return pcl.kdTreeFlannKnn(16, threads); }));
    }
    return result;
}

// ---- reporting ----------------------------------------------------------------------------

std::string fixed(double v, int digits)
{
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << std::fixed << std::setprecision(digits) << v;
    return out.str();
}

std::string firstLineOf(const std::string& path, const std::string& key)
{
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.compare(0, key.size(), key) == 0) {
            const auto colon = line.find(':');
            std::string value = colon == std::string::npos ? line : line.substr(colon + 1);
            value.erase(0, value.find_first_not_of(" \t"));
            return value;
        }
    }
    return "unknown";
}

std::string loadAverage()
{
    std::ifstream in("/proc/loadavg");
    double one = 0, five = 0, fifteen = 0;
    in >> one >> five >> fifteen;
    return fixed(one, 2) + " " + fixed(five, 2) + " " + fixed(fifteen, 2);
}

void printMachine(std::ostream& out, int threads, int runs)
{
    out << "CPU: " << firstLineOf("/proc/cpuinfo", "model name") << ", "
        << std::thread::hardware_concurrency() << " logical CPUs\n"
        << "memory: " << firstLineOf("/proc/meminfo", "MemTotal") << "\n"
        << "compiler: " << __VERSION__ << "; build: " << FEATURELINES_BENCH_FLAGS << "\n"
        << "threads: " << (threads > 0 ? threads : omp_get_max_threads())
        << ", runs per stage: " << runs << " (median shown)\n";
}

void printTable(std::ostream& out, const Result& r, bool markdown)
{
    const std::vector<std::string> header{"stage",        "median s",        "min..max s",
                                          "CPU s",        "Mpoints/s",       "output MiB",
                                          "peak RSS MiB", "peak - start MiB"};
    std::vector<std::vector<std::string>> cells;
    for (const Row& row : r.rows) {
        const auto [lo, hi] = std::minmax_element(row.seconds.begin(), row.seconds.end());
        cells.push_back(
            {row.stage, fixed(row.median(), 3), fixed(*lo, 3) + ".." + fixed(*hi, 3),
             fixed(row.medianCpu(), 3), fixed(r.points / row.median() / 1e6, 2),
             row.part ? "" : fixed(row.outputMiB, 1), row.part ? "" : fixed(row.peakRssMiB, 0),
             row.part ? "" : fixed(std::max(0.0, row.peakRssMiB - row.startRssMiB), 0)});
    }
    out << "\n"
        << (markdown ? "### " : "") << r.points << " points (" << r.cloud << ", spacing "
        << fixed(r.spacing, 4) << ")\n\n";
    std::vector<std::size_t> width(header.size());
    for (std::size_t c = 0; c < header.size(); ++c) {
        width[c] = header[c].size();
        for (const auto& line : cells) {
            width[c] = std::max(width[c], line[c].size());
        }
    }
    const auto printLine = [&](const std::vector<std::string>& line) {
        for (std::size_t c = 0; c < line.size(); ++c) {
            const std::string pad(width[c] - line[c].size(), ' ');
            out << (markdown ? "| " : (c ? "  " : "")) << (c == 0 ? line[c] + pad : pad + line[c])
                << (markdown ? " " : "");
        }
        out << (markdown ? "|" : "") << "\n";
    };
    printLine(header);
    if (markdown) {
        for (std::size_t c = 0; c < header.size(); ++c) {
            out << "|"
                << (c ? std::string(width[c] + 1, '-') + ":" : std::string(width[c] + 2, '-'));
        }
        out << "|\n";
    }
    for (const auto& line : cells) {
        printLine(line);
    }

    const auto ratio = [&](const char* what, const std::vector<const char*>& ours,
                           const char* theirs, double (Row::*measure)() const) {
        double sum = 0.0;
        for (const char* stage : ours) {
            sum += (r.row(stage).*measure)();
        }
        const double pcl = (r.row(theirs).*measure)();
        out << what << fixed(sum, 3) << " s / " << fixed(pcl, 3) << " s = " << fixed(sum / pcl, 2)
            << (markdown ? "  \n" : "\n");
    };
    const std::vector<const char*> perPoint{knnStage, normalsStage, curvatureStage};
    out << "\n";
    if (!r.lines.empty()) {
        out << "whole extraction found " << r.lines << (markdown ? "  \n" : "\n");
    }
    ratio("whole extraction / PCL NormalEstimationOMP, wall: ", {wholeStage}, pclNormalsStage,
          &Row::median);
    ratio("whole extraction / PCL NormalEstimationOMP, CPU: ", {wholeStage}, pclNormalsStage,
          &Row::medianCpu);
    // The two ran in turn: the ratio of each run to the yardstick's run after it.
    const auto runByRun = [&](const char* what, std::vector<double> Row::*times) {
        const std::vector<double>& ours = r.row(wholeStage).*times;
        const std::vector<double>& theirs = r.row(pclNormalsStage).*times;
        std::vector<double> ratios;
        for (std::size_t i = 0; i < ours.size() && i < theirs.size(); ++i) {
            ratios.push_back(ours[i] / theirs[i]);
        }
        const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
        out << what << fixed(*lo, 2) << ".." << fixed(*hi, 2) << " (median "
            << fixed(Row::medianOf(ratios), 2) << ")" << (markdown ? "  \n" : "\n");
    };
    runByRun("whole extraction / PCL NormalEstimationOMP run by run, wall: ", &Row::seconds);
    runByRun("whole extraction / PCL NormalEstimationOMP run by run, CPU: ", &Row::cpu);
    const Row& whole = r.row(wholeStage);
    const double millions = static_cast<double>(r.points) / 1e6;
    out << "whole extraction, memory per million points: peak RSS "
        << fixed(whole.peakRssMiB / millions, 0) << " MiB, peak - start "
        << fixed((whole.peakRssMiB - whole.startRssMiB) / millions, 0) << " MiB"
        << (markdown ? "  \n" : "\n");
    ratio("(neighbours + normals + curvature) / PCL NormalEstimationOMP, wall: ", perPoint,
          pclNormalsStage, &Row::median);
    ratio("(neighbours + normals + curvature) / PCL NormalEstimationOMP, CPU: ", perPoint,
          pclNormalsStage, &Row::medianCpu);
    if (r.has(pclKnnStage)) {
        ratio("kNN alone, nearestNeighbours / PCL KdTreeFLANN, wall: ", {knnStage}, pclKnnStage,
              &Row::median);
        ratio("kNN alone, nearestNeighbours / PCL KdTreeFLANN, CPU: ", {knnStage}, pclKnnStage,
              &Row::medianCpu);
    }
}

const std::vector<OptionSpec>& optionSpecs()
{
    static const std::vector<OptionSpec> specs{
        {"--points", "N", "one rounded cube of about N points (default: 100000, then 1000000)"},
        {"--noise", "S", "normal noise on the rounded cube, x spacing (default 0)"},
        {"--cloud", "FILE", "the points of FILE instead of a rounded cube (.xyz, .ply, .pcd)"},
        {"--write-cloud", "FILE", "write the rounded cube as .xyz and stop"},
        {"--whole", "", "the whole extraction and the yardstick only, not every stage"},
        {"--runs", "R", "runs per stage, the median is shown (default 3)"},
        {"--threads", "T", "worker threads, 0 for OpenMP's default (default 0)"},
        {"--markdown", "", "print the tables as Markdown"},
        {"--help", "", "this text", "-h"},
    };
    return specs;
}

int run(const std::vector<std::string>& words)
{
    const Arguments a(words, optionSpecs());
    if (a.has("--help")) {
        std::cout << "usage: featurelines_bench [--points N [--noise S] | --cloud FILE] [--runs R] "
                     "[--threads T] [--whole] [--markdown]\n\noptions:\n";
        for (const OptionSpec& o : optionSpecs()) {
            std::cout << "  " << std::left << std::setw(20)
                      << (o.name + (o.valueName.empty() ? "" : " " + o.valueName)) << o.help
                      << "\n";
        }
        return 0;
    }
    if (!a.positional().empty()) {
        throw UsageError("unexpected argument '" + a.positional()[0] + "'");
    }
    std::vector<long> sizes{100000, 1000000};
    if (a.has("--points")) {
        sizes = {a.integer("--points", 0, 100, 1000000000)};
    }
    const double noise = a.number("--noise", 0.0, 0.0, 10.0, true);
    const int runs = static_cast<int>(a.integer("--runs", 3, 1, 1000));
    const int threads = static_cast<int>(a.integer("--threads", 0, 0, 4096));
    const bool markdown = a.has("--markdown");
    const bool stages = !a.has("--whole");
    if (threads > 0) {
        // The stages without a threads option (smoothing, the region steps of the whole
        // extraction) follow OpenMP's default.
        omp_set_num_threads(threads);
    }
    if (a.has("--write-cloud")) {
        writeXyz(a.text("--write-cloud"), roundedCubeCloud(sizes.back(), noise).points);
        return 0;
    }

    const std::string loadBefore = loadAverage();
    std::vector<Result> results;
    if (a.has("--cloud")) {
        Cloud cloud;
        cloud.name = a.text("--cloud");
        cloud.points = readCloud(cloud.name);
        results.push_back(runOne(cloud, runs, threads, stages));
    } else {
        for (long points : sizes) {
            results.push_back(runOne(roundedCubeCloud(points, noise), runs, threads, stages));
        }
    }
    printMachine(std::cout, threads, runs);
    std::cout << "load average (1, 5, 15 min) before: " << loadBefore
              << ", after: " << loadAverage() << "\n";
    if (!peakIsPerStage) {
        std::cout << "peak RSS: since the program started (/proc/self/clear_refs unavailable)\n";
    }
    for (const Result& r : results) {
        printTable(std::cout, r, markdown);
    }
    return 0;
}

} // namespace
} // namespace featurelines::bench

int main(int argc, char** argv)
{
    try {
        return featurelines::bench::run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const featurelines::cli::UsageError& e) {
        std::cerr << "featurelines_bench: " << e.what() << std::endl;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "featurelines_bench: " << e.what() << std::endl;
        return 1;
    }
}
