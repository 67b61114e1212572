// SPDX-License-Identifier: LGPL-2.1-or-later
// featurelines_accuracy: the accuracy benchmark on CAD parts with known edges.
//
// For every part (CadShapes.h), clean and with noise along the normal: sample a scan-like
// cloud (ShapeSampling.h), take the typed edges of the B-rep as truth, run every detector,
// and score it (LineScore.h): precision, recall and F1 per edge type, closedness. With
// --random, the random parts instead (PartFamilies.h), each sampled by its drawn scanner model
// (ScanSampling.h) and aggregated per family, model and noise (RandomBenchmark.h). Method and
// results: docs/ACCURACY.md.
#include <BRepTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/curves/CurveFit.h"
#include "FeatureLines/curves/CurveNetwork.h"

#include "Baselines.h"
#include "CadFiles.h"
#include "CadShapes.h"
#include "LineScore.h"
#include "PartFamilies.h"
#include "RandomBenchmark.h"
#include "ScanSampling.h"
#include "ShapeSampling.h"
#include "SurfaceScore.h"
#include "VcmBaseline.h"

using featurelines::PointMatrix;
using namespace featurelines::bench;

namespace {

// ---------------------------------------------------------------------------------------------
// The project's extraction with its default options, on the cloud only, as a user runs it
// (--max-scale changes the one option a robustness run may set).
featurelines::ExtractionOptions extractionOptions;
/// The curve network's options (--corner-angle).
featurelines::CurveFitOptions curveOptions;

/// The extraction's lines, and the same lines as CAD geometry (issue 18): the fitted curve
/// network and its patches' borders.
struct FeatureLinesRun
{
    featurelines::ExtractionResult result;
    std::vector<TypedPolyline> lines;
    featurelines::CurveNetwork network;
    std::vector<featurelines::PatchBorder> borders;
};

std::optional<FeatureLinesRun> runFeatureLines(const PointMatrix& cloud)
{
    const featurelines::ExtractionResult result =
        featurelines::extractFeatureLines(cloud, extractionOptions);
    FeatureLinesRun run;
    for (const featurelines::FeatureLine& l : result.lines) {
        TypedPolyline t;
        t.type = lineTypeFromName(featurelines::lineTypeName(l.type));
        t.closed = l.closed;
        t.points = l.points;
        t.angle = l.angle;
        t.radius = l.blendRadius;
        run.lines.push_back(std::move(t));
    }
    run.network = featurelines::fitCurveNetwork(result, curveOptions);
    run.borders = featurelines::patchBorders(run.network, result, cloud);
    run.result = result;
    return run;
}

/// How the fitted curves sit on the true edges: their LineQuality (distances of their samples
/// to the true edges, edges per true edge), the count of each kind, and the share of patches
/// with a closed border.
struct CurveQuality
{
    LineQuality quality;
    int edges = 0;
    std::array<int, 4> kinds{};
    int patches = 0;
    int closedPatches = 0;
    /// Vertices where the curves cut a line at a corner (--corner-angle), and those within
    /// the tolerance of a true vertex (an end of a true edge).
    int corners = 0;
    int trueCorners = 0;
};

CurveQuality measureCurves(const FeatureLinesRun& run, const std::vector<TypedPolyline>& truth,
                           const LineScoreOptions& scoring)
{
    CurveQuality q;
    std::vector<TypedPolyline> curves;
    for (const featurelines::NetworkEdge& e : run.network.edges) {
        TypedPolyline t;
        t.type = lineTypeFromName(featurelines::lineTypeName(e.type));
        t.points = featurelines::sampleCurve(e.curve, scoring.resampleFactor * scoring.spacing);
        curves.push_back(std::move(t));
        ++q.kinds[static_cast<size_t>(e.curve.kind)];
    }
    q.edges = static_cast<int>(curves.size());
    q.quality = measureLineQuality(curves, truth, scoring);
    for (const featurelines::PatchBorder& b : run.borders) {
        ++q.patches;
        q.closedPatches += b.closed() ? 1 : 0;
    }
    // A corner: a vertex where one edge of a run ends and another of the same run starts.
    const auto& edges = run.network.edges;
    std::map<int, std::vector<std::pair<size_t, bool>>> ends; // vertex -> (edge, arrives)
    for (size_t i = 0; i < edges.size(); ++i) {
        ends[edges[i].startVertex].push_back({i, false});
        ends[edges[i].endVertex].push_back({i, true});
    }
    const double tolerance = scoring.toleranceFactor * scoring.spacing;
    for (const auto& [vertex, at] : ends) {
        if (at.size() != 2 || at[0].first == at[1].first || at[0].second == at[1].second ||
            edges[at[0].first].run != edges[at[1].first].run) {
            continue;
        }
        ++q.corners;
        const Eigen::RowVector3d v = run.network.vertices.row(vertex);
        for (const TypedPolyline& t : truth) {
            const Eigen::Index n = t.points.rows();
            if (!t.closed && n > 0 &&
                std::min((t.points.row(0) - v).norm(), (t.points.row(n - 1) - v).norm()) <=
                    tolerance) {
                ++q.trueCorners;
                break;
            }
        }
    }
    return q;
}
// ---------------------------------------------------------------------------------------------

/// The measured parts, then the held-out ones (whose seeds follow on, so that the measured
/// parts' clouds do not change).
std::vector<std::string> allShapeNames()
{
    std::vector<std::string> names = cadShapeNames();
    for (const std::string& n : heldOutShapeNames()) {
        names.push_back(n);
    }
    return names;
}

bool isHeldOut(const std::string& name)
{
    const std::vector<std::string> held = heldOutShapeNames();
    return std::find(held.begin(), held.end(), name) != held.end();
}

struct Arguments
{
    std::vector<std::string> shapes = allShapeNames();
    /// Points per part; the sampling radius follows from the part's area.
    double points = 50000.0;
    /// --points was given: random parts are sized for it instead of their drawn count.
    bool pointsGiven = false;
    /// --random: the seeds of the random parts to measure instead of the built-in parts.
    std::vector<std::uint32_t> randomSeeds;
    /// --floor: lowest acceptable means over the random parts (exit 1 below).
    RandomFloors floors;
    /// --surface-floor: the surfaces' floors (exit 1 past one).
    SurfaceFloors surfaceFloors;
    /// --bspline: how a patch no analytic surface fits gets its face.
    featurelines::surfaces::BSplineFace bspline = featurelines::surfaces::BSplineFace::HeightField;
    /// When > 0: sampling radius as this fraction of the part's bounding-box diagonal
    /// (overrides `points`).
    double spacingFraction = 0.0;
    /// Noise standard deviation along the normal, as a multiple of the mean point spacing.
    double noiseSigma = 0.3;
    /// Share of the sampled points kept, each at random: below 1 an irregular sampling (a
    /// thinned or patchy scan) instead of the Poisson disk's even one.
    double keep = 1.0;
    unsigned seed = 1;
    std::string writeDir;
    std::string linesDir;
    /// A folder of real CAD models (STEP, IGES, BREP) measured after the built-in parts.
    std::string stepDir;
    std::string demoCloud;
    double demoPoints = 40000.0;
    bool markdown = false;
    /// Run the per-point baselines beside the extraction.
    bool baselines = true;
    /// Fit, sew and score the patch surfaces too (issue 21).
    bool surfaces = false;
};

const char* usage =
    "Usage: featurelines_accuracy [options]\n"
    "  --shapes a,b,c          parts to run (default: all): box_fillets, box_chamfers,\n"
    "                          variable_fillet, boss_blend, plate_holes, open_sheet,\n"
    "                          close_fillets, and the held-out wedge, chamfered_cylinder\n"
    "  --points N              points per part (default 50000)\n"
    "  --random A-B,C          the random parts of these seeds instead of the built-in\n"
    "                          parts, each sampled by its drawn scanner model\n"
    "  --floor sharp=F,smooth=F,closed=F\n"
    "                          with --random: exit 1 when a mean is below its floor\n"
    "  --spacing-fraction F    Poisson-disk radius as a fraction of the part's bounding-box\n"
    "                          diagonal (overrides --points)\n"
    "  --noise-sigma S         noise along the normal, x mean spacing (default 0.3)\n"
    "  --keep F                keep each sampled point with probability F (default 1): an\n"
    "                          irregular sampling, as of a thinned or patchy scan\n"
    "  --seed S                seed of sampling, thinning and noise (default 1)\n"
    "  --write DIR             write DIR/<part>-<clean|noisy>/cloud.xyz, truth.json (the true\n"
    "                          edges) and truth.brep (the part)\n"
    "                          (random parts: DIR/random-<seed>/)\n"
    "  --lines DIR             also score DIR/<part>-<clean|noisy>/lines.json (the lines JSON\n"
    "                          of any detector, e.g. the featurelines CLI run on cloud.xyz)\n"
    "  --step-dir DIR          also measure every STEP, IGES or BREP model in DIR (real\n"
    "                          CAD parts, reported apart; --shapes none for these only)\n"
    "  --demo-cloud FILE       write the demo cloud (boss_blend, clean, 6 digits) to FILE\n"
    "  --demo-points N         points of the demo cloud (default 40000)\n"
    "  --markdown              print tables as Markdown\n"
    "  --no-baselines          score the extraction only (no PCL or VCM baselines, no sweeps)\n"
    "  --boundary-gap DEG      the extraction's boundary gap angle (default 120)\n"
    "  --max-scale S           coarsest curvature scale of the extraction, x spacing\n"
    "                          (default 8; 1: the cloud's own sampling only)\n"
    "  --no-line-placement     leave the smooth lines where the curvature's levels put\n"
    "                          them (no fit of the curvature step)\n"
    "  --corner-angle DEG      also cut the fitted curves where a line's direction breaks\n"
    "                          by this much (default 180: at junctions only)\n"
    "  --surfaces              also fit the patches' surfaces, sew them and measure them\n"
    "                          against the true B-rep (a table of its own)\n"
    "  --bspline M             with --surfaces: a patch no analytic surface fits gets the\n"
    "                          B-spline height field (heightfield, the default) or\n"
    "                          OpenCASCADE's plate through its border and points (plate)\n"
    "  --surface-floor kinds=F,solids=N,truth=D\n"
    "                          with --surfaces: exit 1 when the share of true faces of their\n"
    "                          kind is below F, the valid solids fewer than N, or the faces'\n"
    "                          mean distance to the truth above D spacings\n";

/// Each point of `cloud` kept with probability `share` (seeded); all of them at share 1.
SampledCloud keptAtRandom(SampledCloud cloud, double share, unsigned seed)
{
    if (share >= 1.0) {
        return cloud;
    }
    std::mt19937 random(seed);
    std::bernoulli_distribution kept(share);
    Eigen::Index rows = 0;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        if (kept(random)) {
            cloud.points.row(rows) = cloud.points.row(i);
            cloud.normals.row(rows) = cloud.normals.row(i);
            ++rows;
        }
    }
    cloud.points.conservativeResize(rows, 3);
    cloud.normals.conservativeResize(rows, 3);
    return cloud;
}

std::vector<std::string> splitComma(const std::string& text)
{
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        if (!part.empty()) {
            parts.push_back(part);
        }
    }
    return parts;
}

Arguments parseArguments(int argc, char** argv)
{
    Arguments a;
    for (int i = 1; i < argc; ++i) {
        const std::string opt = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                throw std::invalid_argument(opt + " needs a value.");
            }
            return argv[++i];
        };
        if (opt == "--shapes") {
            const std::string list = value();
            a.shapes = list == "none" ? std::vector<std::string>{} : splitComma(list);
        } else if (opt == "--points") {
            a.points = parseNumber(value(), opt);
            a.pointsGiven = true;
        } else if (opt == "--random") {
            a.randomSeeds = parseSeedList(value());
        } else if (opt == "--floor") {
            a.floors = parseFloors(value());
        } else if (opt == "--spacing-fraction") {
            a.spacingFraction = parseNumber(value(), opt);
        } else if (opt == "--noise-sigma") {
            a.noiseSigma = parseNumber(value(), opt);
        } else if (opt == "--keep") {
            a.keep = parseNumber(value(), opt);
        } else if (opt == "--seed") {
            a.seed = static_cast<unsigned>(parseNumber(value(), opt));
        } else if (opt == "--write") {
            a.writeDir = value();
        } else if (opt == "--lines") {
            a.linesDir = value();
        } else if (opt == "--step-dir") {
            a.stepDir = value();
        } else if (opt == "--demo-cloud") {
            a.demoCloud = value();
        } else if (opt == "--demo-points") {
            a.demoPoints = parseNumber(value(), opt);
        } else if (opt == "--markdown") {
            a.markdown = true;
        } else if (opt == "--no-baselines") {
            a.baselines = false;
        } else if (opt == "--boundary-gap") {
            extractionOptions.sharp.boundary.minGapAngle = parseNumber(value(), opt);
        } else if (opt == "--max-scale") {
            extractionOptions.smooth.scales.maxScale = parseNumber(value(), opt);
        } else if (opt == "--surfaces") {
            a.surfaces = true;
        } else if (opt == "--bspline") {
            const std::string v = value();
            using featurelines::surfaces::BSplineFace;
            if (v == "heightfield") {
                a.bspline = BSplineFace::HeightField;
            } else if (v == "plate") {
                a.bspline = BSplineFace::Plate;
            } else {
                throw std::invalid_argument("--bspline is heightfield or plate, not \"" + v +
                                            "\".");
            }
        } else if (opt == "--surface-floor") {
            a.surfaceFloors = parseSurfaceFloors(value());
        } else if (opt == "--corner-angle") {
            curveOptions.cornerAngle = parseNumber(value(), opt);
        } else if (opt == "--no-line-placement") {
            extractionOptions.smooth.placeCoarseLines = false;
            extractionOptions.smooth.placeOwnScaleLines = false;
        } else if (opt == "--help" || opt == "-h") {
            std::cout << usage;
            std::exit(0);
        } else {
            throw std::invalid_argument("Unknown option " + opt + ".\n" + usage);
        }
    }
    if (!(a.points >= 100.0)) {
        throw std::invalid_argument("--points must be at least 100.");
    }
    const bool floorGiven = !std::isnan(a.floors.sharpF1) || !std::isnan(a.floors.smoothF1) ||
                            !std::isnan(a.floors.closedness);
    if (floorGiven && a.randomSeeds.empty()) {
        throw std::invalid_argument("--floor applies to the random parts: give --random too.");
    }
    const bool surfaceFloorGiven = !std::isnan(a.surfaceFloors.kinds) ||
                                   !std::isnan(a.surfaceFloors.solids) ||
                                   !std::isnan(a.surfaceFloors.toTruth);
    if (surfaceFloorGiven && !a.surfaces) {
        throw std::invalid_argument("--surface-floor applies to the surfaces: give --surfaces "
                                    "too.");
    }
    if (a.spacingFraction < 0.0 || a.spacingFraction > 0.1) {
        throw std::invalid_argument("--spacing-fraction must lie between 0 and 0.1.");
    }
    if (a.noiseSigma < 0.0) {
        throw std::invalid_argument("--noise-sigma must not be negative.");
    }
    if (!(a.keep > 0.0 && a.keep <= 1.0)) {
        throw std::invalid_argument("--keep must lie in (0, 1].");
    }
    for (const std::string& s : a.shapes) {
        bool known = false;
        for (const std::string& n : allShapeNames()) {
            known = known || n == s;
        }
        if (!known) {
            makeCadShape(s); // throws the message listing the known parts
        }
    }
    return a;
}

// ---------------------------------------------------------------------------------------------
// Lines JSON: {"lines":[{"type":"sharp","closed":false,"points":[[x,y,z],...]}, ...], ...}

/// A minimal JSON reader: enough for the lines format (objects, arrays, strings without
/// escapes beyond \" and \\, numbers, true/false/null).
class JsonReader
{
public:
    explicit JsonReader(std::string text) : s(std::move(text)) {}

    std::vector<TypedPolyline> readLines()
    {
        std::vector<TypedPolyline> lines;
        expect('{');
        if (peek() == '}') {
            return lines;
        }
        while (true) {
            const std::string key = string();
            expect(':');
            if (key == "lines") {
                expect('[');
                if (peek() != ']') {
                    while (true) {
                        lines.push_back(line());
                        if (peek() == ',') {
                            ++pos;
                            continue;
                        }
                        break;
                    }
                }
                expect(']');
            } else {
                skipValue();
            }
            if (peek() == ',') {
                ++pos;
                continue;
            }
            expect('}');
            return lines;
        }
    }

private:
    TypedPolyline line()
    {
        TypedPolyline l;
        std::vector<double> xyz;
        expect('{');
        while (peek() != '}') {
            const std::string key = string();
            expect(':');
            if (key == "type") {
                l.type = lineTypeFromName(string());
            } else if (key == "closed") {
                l.closed = literal() == "true";
            } else if (key == "points") {
                expect('[');
                while (peek() != ']') {
                    expect('[');
                    for (int c = 0; c < 3; ++c) {
                        xyz.push_back(number());
                        if (c < 2) {
                            expect(',');
                        }
                    }
                    expect(']');
                    if (peek() == ',') {
                        ++pos;
                    }
                }
                expect(']');
            } else {
                skipValue();
            }
            if (peek() == ',') {
                ++pos;
            }
        }
        expect('}');
        l.points.resize(static_cast<Eigen::Index>(xyz.size() / 3), 3);
        for (size_t i = 0; i < xyz.size(); ++i) {
            l.points(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)) = xyz[i];
        }
        return l;
    }

    char peek()
    {
        while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) {
            ++pos;
        }
        if (pos >= s.size()) {
            throw std::invalid_argument("The lines file ends too early.");
        }
        return s[pos];
    }

    void expect(char c)
    {
        if (peek() != c) {
            throw std::invalid_argument(std::string("The lines file is not valid JSON: '") + c +
                                        "' expected at character " + std::to_string(pos) + ".");
        }
        ++pos;
    }

    std::string string()
    {
        expect('"');
        std::string out;
        while (pos < s.size() && s[pos] != '"') {
            if (s[pos] == '\\' && pos + 1 < s.size()) {
                ++pos;
            }
            out += s[pos++];
        }
        expect('"');
        return out;
    }

    std::string literal()
    {
        peek();
        const size_t start = pos;
        while (pos < s.size() && std::isalpha(static_cast<unsigned char>(s[pos]))) {
            ++pos;
        }
        return s.substr(start, pos - start);
    }

    double number()
    {
        peek();
        const char* begin = s.c_str() + pos;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin) {
            throw std::invalid_argument("The lines file has a point coordinate that is not a "
                                        "number, at character " +
                                        std::to_string(pos) + ".");
        }
        pos += static_cast<size_t>(end - begin);
        return v;
    }

    void skipValue()
    {
        const char c = peek();
        if (c == '"') {
            string();
        } else if (c == '{' || c == '[') {
            const char close = c == '{' ? '}' : ']';
            ++pos;
            while (peek() != close) {
                if (c == '{') {
                    string();
                    expect(':');
                }
                skipValue();
                if (peek() == ',') {
                    ++pos;
                }
            }
            ++pos;
        } else if (std::isalpha(static_cast<unsigned char>(c))) {
            literal();
        } else {
            number();
        }
    }

    std::string s;
    size_t pos = 0;
};

std::vector<TypedPolyline> readLinesJson(const std::string& path)
{
    std::ifstream in(path);
    if (!in) {
        throw std::invalid_argument("Cannot read the lines file " + path + ".");
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    try {
        return JsonReader(buffer.str()).readLines();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(path + ": " + e.what());
    }
}

void writeLinesJson(const std::string& path, const std::vector<TypedPolyline>& lines,
                    const std::string& shape, double spacing)
{
    std::ofstream out(path);
    out.precision(9);
    out << "{\"shape\":\"" << shape << "\",\"spacing\":" << spacing << ",\"lines\":[";
    for (size_t l = 0; l < lines.size(); ++l) {
        const TypedPolyline& line = lines[l];
        out << (l ? ",\n" : "\n") << "{\"type\":\"" << lineTypeName(line.type)
            << "\",\"closed\":" << (line.closed ? "true" : "false") << ",\"points\":[";
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            out << (i ? "," : "") << '[' << line.points(i, 0) << ',' << line.points(i, 1) << ','
                << line.points(i, 2) << ']';
        }
        out << "]}";
    }
    out << "\n]}\n";
    if (!out) {
        throw std::runtime_error("Cannot write " + path + ".");
    }
}

void writeXyz(const std::string& path, const PointMatrix& P, int digits)
{
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        throw std::runtime_error("Cannot write " + path + ".");
    }
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        std::fprintf(f, "%.*g %.*g %.*g\n", digits, P(i, 0), digits, P(i, 1), digits, P(i, 2));
    }
    if (std::fclose(f) != 0) {
        throw std::runtime_error("Cannot write " + path + ".");
    }
}

/// --write: the cloud and its truth as DIR/<caseName>/cloud.xyz, truth.json (the true edges)
/// and truth.brep (the part's B-rep, which the surfaces are measured against).
void writeCase(const std::string& writeDir, const std::string& caseName, const PointMatrix& points,
               const std::vector<TypedPolyline>& truth, const std::string& shape, double spacing,
               const TopoDS_Shape& part)
{
    const std::filesystem::path dir = std::filesystem::path(writeDir) / caseName;
    std::filesystem::create_directories(dir);
    writeXyz((dir / "cloud.xyz").string(), points, 9);
    writeLinesJson((dir / "truth.json").string(), truth, shape, spacing);
    if (!BRepTools::Write(part, (dir / "truth.brep").string().c_str())) {
        throw std::runtime_error("cannot write " + (dir / "truth.brep").string());
    }
}

// ---------------------------------------------------------------------------------------------
// Detectors and the table.

/// Fixed thresholds of the per-point baselines, chosen once, before any run, from the
/// geometry of a k = 16 neighbourhood (radius about 2.3 spacings):
///  - surface variation 0.05: noise of 0.3 spacing along the normal gives a plane's
///    neighbourhood about 0.09 h^2 of variance across against about 1.3 h^2 along each
///    in-plane axis, a variation near 0.03; 0.05 leaves noisy planes unflagged.
///  - normal angle 20 degrees: across a neighbourhood a fillet of radius 6 spacings turns the
///    normal by about 2.3 / 6 rad = 22 degrees at most, one of 8 spacings by 16; a designed
///    crease (45 degrees and more) turns it by its full angle.
constexpr double fixedSurfaceVariation = 0.05;
constexpr double fixedNormalAngle = 20.0;
/// Sweeps reported beside the fixed thresholds, so that the baselines are not judged by one
/// unlucky choice.
const std::vector<double> surfaceVariationSweep = {0.005, 0.01, 0.02, 0.03, 0.05, 0.08, 0.12};
const std::vector<double> normalAngleSweep = {5.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0};
/// CGAL's VCM edge ratio (VcmBaseline.h), fixed at CGAL's example threshold, radii 5 and 2
/// spacings (VcmOptions' defaults).
const std::vector<double> vcmSweep = {0.04, 0.06, 0.08, 0.10, 0.12, 0.16, 0.20, 0.25};

struct Row
{
    Row(std::string shape_, std::string noise_, std::string detector_)
        : shape(std::move(shape_)), noise(std::move(noise_)), detector(std::move(detector_))
    {
    }
    std::string shape;
    std::string noise;
    std::string detector;
    bool available = false;
    LineScore score;
    double seconds = 0.0;
    bool perPoint = false;
    /// "measured", "held-out" (CadShapes.h) or "real" (--step-dir): means per group.
    std::string group = "measured";
    /// For line detectors: F1 at a tolerance of one spacing, and LineQuality.
    LineScore scoreAtOneSpacing;
    LineQuality quality;
    /// For the extraction: its fitted curves, and with --surfaces its sewn patch surfaces.
    std::optional<CurveQuality> curves;
    std::optional<SurfaceQuality> surfaces;
};

void printTable(const std::vector<std::string>& header,
                const std::vector<std::vector<std::string>>& rows, bool markdown)
{
    if (markdown) {
        const auto line = [](const std::vector<std::string>& cells) {
            std::string s = "|";
            for (const std::string& c : cells) {
                s += " " + c + " |";
            }
            return s;
        };
        std::cout << line(header) << "\n|";
        for (size_t i = 0; i < header.size(); ++i) {
            std::cout << (i < 3 ? "---|" : "--:|");
        }
        std::cout << "\n";
        for (const auto& r : rows) {
            std::cout << line(r) << "\n";
        }
        std::cout << "\n";
        return;
    }
    std::vector<size_t> width(header.size(), 0);
    for (size_t i = 0; i < header.size(); ++i) {
        width[i] = header[i].size();
        for (const auto& r : rows) {
            width[i] = std::max(width[i], r[i].size());
        }
    }
    const auto line = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i) {
            std::cout << (i ? "  " : "") << cells[i]
                      << std::string(width[i] - cells[i].size(), ' ');
        }
        std::cout << "\n";
    };
    line(header);
    for (const auto& r : rows) {
        line(r);
    }
    std::cout << "\n";
}

std::vector<std::string> scoreCells(const LineScore& s, bool available)
{
    std::vector<std::string> cells;
    for (int t = 0; t < lineTypeCount; ++t) {
        const TypeScore& ts = s.types[static_cast<size_t>(t)];
        cells.push_back(available ? formatNumber(ts.precision) : "-");
        cells.push_back(available ? formatNumber(ts.recall) : "-");
        cells.push_back(available ? formatNumber(ts.f1) : "-");
    }
    return cells;
}

const std::vector<std::string> scoreHeader = {"sharp P",  "sharp R",  "sharp F1",
                                              "smooth P", "smooth R", "smooth F1",
                                              "bnd P",    "bnd R",    "bnd F1"};

/// Mean of the defined values.
double meanOf(const std::vector<double>& v)
{
    double sum = 0.0;
    int n = 0;
    for (double x : v) {
        if (!std::isnan(x)) {
            sum += x;
            ++n;
        }
    }
    return n ? sum / n : std::nan("");
}

/// Mean precision, recall and F1 per type over the rows (parts without an edge type do not
/// count for it), and mean closedness.
LineScore meanScore(const std::vector<const Row*>& rows)
{
    LineScore mean;
    for (int t = 0; t < lineTypeCount; ++t) {
        std::vector<double> p, r, f;
        for (const Row* row : rows) {
            const TypeScore& ts = row->score.types[static_cast<size_t>(t)];
            if (ts.truthSamples == 0) {
                continue;
            }
            p.push_back(ts.precision);
            r.push_back(ts.recall);
            f.push_back(ts.f1);
        }
        mean.types[static_cast<size_t>(t)] = {meanOf(p), meanOf(r), meanOf(f), 0, 0};
    }
    std::vector<double> c, cs;
    for (const Row* row : rows) {
        c.push_back(row->score.closedness);
        cs.push_back(row->score.sharpClosedness);
    }
    mean.closedness = meanOf(c);
    mean.sharpClosedness = meanOf(cs);
    return mean;
}

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// One sweep point: mean F1 per type over the parts, at one threshold of one baseline.
struct SweepResult
{
    std::string baseline;
    std::string noise;
    double threshold;
    std::array<std::vector<double>, lineTypeCount> f1;
};

/// Everything measured: the rows of every part, noise level and detector, the baselines'
/// sweeps, and one row per part describing it.
struct Results
{
    std::vector<Row> rows;
    std::vector<SweepResult> sweeps;
    std::vector<std::vector<std::string>> partRows;

    SweepResult& sweepSlot(const std::string& baseline, const std::string& noise, double threshold)
    {
        for (SweepResult& s : sweeps) {
            if (s.baseline == baseline && s.noise == noise && s.threshold == threshold) {
                return s;
            }
        }
        sweeps.push_back({baseline, noise, threshold, {}});
        return sweeps.back();
    }
};

/// One part's clean cloud, its spacing and its true edges.
struct SampledPart
{
    SampledCloud clean;
    double spacing = 0.0;
    std::vector<TypedPolyline> truth;
    unsigned seed = 0;
};

SampledPart samplePart(const CadShape& part, unsigned seed, const Arguments& args, Results& results)
{
    const auto buildStart = std::chrono::steady_clock::now();
    SamplingOptions sampling;
    sampling.radius = args.spacingFraction > 0.0
                          ? args.spacingFraction * boundingDiagonal(part.shape)
                          : radiusForPointCount(shapeArea(part.shape), args.points);
    sampling.seed = seed;
    SampledPart s;
    s.seed = seed;
    s.clean = keptAtRandom(sampleShape(part.shape, sampling), args.keep, sampling.seed + 700u);
    s.spacing = meanNearestSpacing(s.clean.points);
    TruthOptions truthOptions;
    truthOptions.step = 0.5 * s.spacing;
    s.truth = truthEdges(part.shape, truthOptions);
    std::array<int, lineTypeCount> edgeCount{};
    for (const TypedPolyline& l : s.truth) {
        ++edgeCount[static_cast<size_t>(l.type)];
    }
    results.partRows.push_back(
        {part.name, std::to_string(s.clean.points.rows()), formatNumber(s.spacing, 3),
         formatNumber(sampling.radius, 3),
         part.smallestRadius > 0 ? formatNumber(part.smallestRadius / s.spacing, 1) : "-",
         std::to_string(edgeCount[0]), std::to_string(edgeCount[1]), std::to_string(edgeCount[2]),
         formatNumber(seconds(buildStart), 1)});
    return s;
}

/// A row of a line detector: scored at the benchmark's tolerance and at one spacing, with its
/// LineQuality.
Row lineRow(const std::string& name, const std::string& noise, const std::string& detector,
            const std::vector<TypedPolyline>& lines, const SampledPart& s)
{
    Row row(name, noise, detector);
    row.available = true;
    LineScoreOptions scoring;
    scoring.spacing = s.spacing;
    row.score = scoreLines(lines, s.truth, scoring);
    row.quality = measureLineQuality(lines, s.truth, scoring);
    scoring.toleranceFactor = 1.0;
    row.scoreAtOneSpacing = scoreLines(lines, s.truth, scoring);
    return row;
}

/// The extraction's row: its lines scored (lineRow) and its fitted curves measured.
Row featureLinesRow(const std::string& name, const std::string& noise, const FeatureLinesRun& run,
                    const SampledPart& s)
{
    Row row = lineRow(name, noise, "featurelines", run.lines, s);
    LineScoreOptions scoring;
    scoring.spacing = s.spacing;
    row.curves = measureCurves(run, s.truth, scoring);
    return row;
}

/// --surfaces: the run's patch surfaces fitted, sewn and measured against the true shape.
SurfaceQuality surfaceRow(const FeatureLinesRun& run, const PointMatrix& cloud,
                          const TopoDS_Shape& truth, double spacing,
                          featurelines::surfaces::BSplineFace bspline)
{
    const auto start = std::chrono::steady_clock::now();
    SurfaceQuality q;
    try {
        featurelines::surfaces::PatchSurfaceOptions options;
        options.bspline = bspline;
        const featurelines::surfaces::PatchSurfaces fitted =
            featurelines::surfaces::surfacesOfExtraction(cloud, run.result, curveOptions, options);
        const double fitSeconds = seconds(start);
        q = measureSurfaces(fitted, truth, cloud, spacing);
        q.seconds = fitSeconds;
    } catch (const std::exception& e) {
        std::cerr << "surfaces not measured: " << e.what() << "\n";
    }
    return q;
}

/// The per-point baselines on one cloud: a row at each fixed threshold, and the sweeps over
/// the measured parts.
void runBaselines(const std::string& name, const std::string& noise, const std::string& group,
                  const SampledCloud& cloud, const SampledPart& s, Results& results)
{
    LineScoreOptions scoring;
    scoring.spacing = s.spacing;
    const auto baseline = [&](const std::string& label, double fixed,
                              const std::vector<double>& sweep,
                              const std::function<std::vector<double>()>& values) {
        const auto start = std::chrono::steady_clock::now();
        const std::vector<double> v = values();
        Row row(name, noise, label + " > " + formatNumber(fixed, fixed < 1 ? 2 : 0));
        row.group = group;
        row.seconds = seconds(start);
        row.available = true;
        row.perPoint = true;
        row.score = scoreFlaggedPoints(pointsAbove(cloud.points, v, fixed), s.truth, scoring);
        results.rows.push_back(row);
        // The sweeps are over the measured parts only, like the means.
        for (double t : group == "measured" ? sweep : std::vector<double>{}) {
            const LineScore score =
                scoreFlaggedPoints(pointsAbove(cloud.points, v, t), s.truth, scoring);
            SweepResult& slot = results.sweepSlot(label, noise, t);
            for (int ty = 0; ty < lineTypeCount; ++ty) {
                if (score.types[static_cast<size_t>(ty)].truthSamples > 0) {
                    slot.f1[static_cast<size_t>(ty)].push_back(
                        score.types[static_cast<size_t>(ty)].f1);
                }
            }
        }
    };
    baseline("pcl-surface-variation", fixedSurfaceVariation, surfaceVariationSweep,
             [&] { return surfaceVariation(cloud.points); });
    baseline("pcl-normal-angle", fixedNormalAngle, normalAngleSweep,
             [&] { return normalAngleDegrees(cloud.points); });
    baseline("cgal-vcm", vcmDefaultThreshold, vcmSweep, [&] {
        VcmOptions vcm;
        vcm.spacing = s.spacing;
        return vcmEdgeRatio(cloud.points, vcm);
    });
}

/// Samples `part` (seeded), clean and noisy, runs every detector on each cloud and scores it.
void measurePart(const CadShape& part, const std::string& group, unsigned seed,
                 const Arguments& args, Results& results)
{
    const SampledPart s = samplePart(part, seed, args, results);
    for (const bool noisy : {false, true}) {
        if (noisy && args.noiseSigma <= 0.0) {
            continue;
        }
        const std::string noise = noisy ? "noisy" : "clean";
        SampledCloud cloud = s.clean;
        if (noisy) {
            addNormalNoise(cloud, args.noiseSigma * s.spacing, s.seed + 500u);
        }
        const std::string caseName = part.name + "-" + noise;
        if (!args.writeDir.empty()) {
            writeCase(args.writeDir, caseName, cloud.points, s.truth, part.name, s.spacing,
                      part.shape);
        }

        // The project's extraction.
        const auto start = std::chrono::steady_clock::now();
        const auto run = runFeatureLines(cloud.points);
        const double extractionSeconds = seconds(start);
        Row row = run ? featureLinesRow(part.name, noise, *run, s)
                      : Row(part.name, noise, "featurelines");
        row.seconds = extractionSeconds;
        if (args.surfaces && run) {
            row.surfaces = surfaceRow(*run, cloud.points, part.shape, s.spacing, args.bspline);
        }
        row.group = group;
        results.rows.push_back(row);
        // Lines of an external run, when given.
        if (!args.linesDir.empty()) {
            const std::filesystem::path file =
                std::filesystem::path(args.linesDir) / caseName / "lines.json";
            Row external = std::filesystem::exists(file) ? lineRow(part.name, noise, "lines.json",
                                                                   readLinesJson(file.string()), s)
                                                         : Row(part.name, noise, "lines.json");
            external.group = group;
            results.rows.push_back(external);
        }
        if (args.baselines) {
            runBaselines(part.name, noise, group, cloud, s, results);
        }
    }
    std::cerr << "done: " << part.name << "\n";
}

/// The rows of every detector and their means per group, detector and noise level.
void printScores(const Results& results, bool markdown)
{
    std::vector<std::string> header = {"part", "noise", "detector"};
    header.insert(header.end(), scoreHeader.begin(), scoreHeader.end());
    header.insert(header.end(), {"closed", "sharp closed", "lines", "time s"});
    std::vector<std::vector<std::string>> table;
    for (const Row& r : results.rows) {
        std::vector<std::string> cells = {r.shape, r.noise, r.detector};
        const auto sc = scoreCells(r.score, r.available);
        cells.insert(cells.end(), sc.begin(), sc.end());
        cells.push_back(r.available && !r.perPoint ? formatNumber(r.score.closedness) : "-");
        cells.push_back(r.available && !r.perPoint ? formatNumber(r.score.sharpClosedness) : "-");
        cells.push_back(r.available && !r.perPoint ? std::to_string(r.score.lineCount) : "-");
        cells.push_back(r.available ? formatNumber(r.seconds, 2) : "-");
        table.push_back(cells);
    }
    printTable(header, table, markdown);

    // Mean per group, detector and noise level: the measured parts, then the held-out ones,
    // then the real CAD parts.
    std::vector<std::vector<std::string>> means;
    std::vector<std::tuple<std::string, std::string, std::string>> keys;
    for (const char* group : {"measured", "held-out", "real", "tuning", "other"}) {
        for (const Row& r : results.rows) {
            const auto key = std::make_tuple(std::string(group), r.detector, r.noise);
            if (r.group == group && std::find(keys.begin(), keys.end(), key) == keys.end()) {
                keys.push_back(key);
            }
        }
    }
    for (const auto& [group, detector, noise] : keys) {
        std::vector<const Row*> members;
        bool available = true;
        bool perPoint = false;
        for (const Row& r : results.rows) {
            if (r.group == group && r.detector == detector && r.noise == noise) {
                available = available && r.available;
                perPoint = r.perPoint;
                members.push_back(&r);
            }
        }
        const std::string label = group == "measured" ? "mean" : "mean " + group;
        std::vector<std::string> cells = {label, noise, detector};
        const LineScore m = available ? meanScore(members) : LineScore{};
        const auto sc = scoreCells(m, available);
        cells.insert(cells.end(), sc.begin(), sc.end());
        cells.push_back(available && !perPoint ? formatNumber(m.closedness) : "-");
        cells.push_back(available && !perPoint ? formatNumber(m.sharpClosedness) : "-");
        cells.push_back("-");
        cells.push_back("-");
        means.push_back(cells);
    }
    if (!markdown) {
        std::cout << "Mean over the parts that have the edge type (held-out and real parts "
                     "apart)\n";
    }
    printTable(header, means, markdown);
}

/// Per line detector and part: F1 at one spacing, distances to the true edges, type
/// confusion, boundary on closed parts and fragmentation (LineQuality).
void printLineQuality(const Results& results, bool markdown)
{
    std::vector<std::vector<std::string>> table;
    for (const Row& r : results.rows) {
        if (!r.available || r.perPoint) {
            continue;
        }
        const LineQuality& q = r.quality;
        const auto f1 = [&](LineType t) {
            return formatNumber(r.scoreAtOneSpacing.types[static_cast<size_t>(t)].f1);
        };
        table.push_back({r.shape, r.noise, r.detector, f1(LineType::Sharp), f1(LineType::Smooth),
                         formatNumber(q.medianDistance, 2), formatNumber(q.p95Distance, 2),
                         formatNumber(q.confusionShare(LineType::Sharp, LineType::Smooth)),
                         formatNumber(q.confusionShare(LineType::Smooth, LineType::Sharp)),
                         formatNumber(q.boundaryLength, 1), formatNumber(q.linesPerTrueEdge, 2),
                         std::to_string(q.freeEnds), formatNumber(q.medianAngleError, 1),
                         formatNumber(q.angleEstimatedShare, 2), formatNumber(q.medianRadiusError, 2),
                         formatNumber(q.radiusEstimatedShare, 2)});
    }
    if (table.empty()) {
        return;
    }
    if (!markdown) {
        std::cout << "Line quality (distances in spacings; confusion: share of the true edge "
                     "samples found as the other type; angle error in degrees, radius error "
                     "relative, medians, and the share of the lines on true edges of their type "
                     "that carry the estimate)\n";
    }
    printTable({"part", "noise", "detector", "sharp F1 @1h", "smooth F1 @1h", "median dist",
                "p95 dist", "sharp as smooth", "smooth as sharp", "boundary length", "lines/edge",
                "free ends", "angle err", "angles given", "radius err", "radii given"},
               table, markdown);
}

/// Per part the extraction's fitted curves (issue 18): their count by kind, their distance to
/// the true edges (samples within the tolerance of one), edges per true edge, the share of
/// the patches whose border is closed, and the corners cut (--corner-angle) with those on a
/// true vertex.
void printCurveQuality(const Results& results, bool markdown)
{
    std::vector<std::vector<std::string>> table;
    for (const Row& r : results.rows) {
        if (!r.curves) {
            continue;
        }
        const CurveQuality& c = *r.curves;
        table.push_back({r.shape, r.noise, std::to_string(c.edges), std::to_string(c.kinds[0]),
                         std::to_string(c.kinds[1]), std::to_string(c.kinds[2]),
                         std::to_string(c.kinds[3]), formatNumber(c.quality.medianDistance, 2),
                         formatNumber(c.quality.p95Distance, 2),
                         formatNumber(c.quality.linesPerTrueEdge, 2),
                         c.patches ? formatNumber(double(c.closedPatches) / c.patches) : "-",
                         std::to_string(c.closedPatches) + "/" + std::to_string(c.patches),
                         std::to_string(c.corners) + " (" + std::to_string(c.trueCorners) + ")"});
    }
    if (table.empty()) {
        return;
    }
    if (!markdown) {
        std::cout << "Fitted curves (distances in spacings, from the curves' samples within the "
                     "tolerance of a true edge)\n";
    }
    printTable({"part", "noise", "edges", "segment", "arc", "circle", "bspline", "median dist",
                "p95 dist", "edges/true edge", "closed patches", "closed/patches",
                "corners (true)"},
               table, markdown);
}

/// --surfaces: per part, the patch faces by kind, the sewn shape, its distances to the true
/// B-rep and the true faces recovered with their kind; then the means. Returns the totals.
SurfaceTotals printSurfaceQuality(const Results& results, bool markdown)
{
    std::vector<SurfaceQuality> measured;
    for (const Row& r : results.rows) {
        if (r.surfaces) {
            measured.push_back(*r.surfaces);
        }
    }
    const SurfaceTotals totals = surfaceTotals(measured);
    std::vector<std::vector<std::string>> table;
    int parts = 0;
    int solids = 0;
    int trueFaces = 0;
    int rightKind = 0;
    std::vector<double> to;
    std::vector<double> to95;
    std::vector<double> from;
    std::vector<double> from95;
    for (const Row& r : results.rows) {
        if (!r.surfaces) {
            continue;
        }
        const SurfaceQuality& q = *r.surfaces;
        ++parts;
        solids += q.solid && q.valid ? 1 : 0;
        trueFaces += q.trueFaces;
        rightKind += q.rightKind;
        for (auto [value, list] : {std::pair{q.toTruthMean, &to}, std::pair{q.toTruthP95, &to95},
                                   std::pair{q.fromTruthMean, &from},
                                   std::pair{q.fromTruthP95, &from95}}) {
            if (std::isfinite(value)) {
                list->push_back(value);
            }
        }
        table.push_back(
            {r.shape, r.noise, std::to_string(q.faces) + "/" + std::to_string(q.patches),
             std::to_string(q.kinds[0]), std::to_string(q.kinds[1]), std::to_string(q.kinds[2]),
             std::to_string(q.kinds[3]), std::to_string(q.kinds[4]),
             std::to_string(q.kinds[5]) +
                 (q.plates > 0 ? " (" + std::to_string(q.plates) + " plate)" : std::string()),
             q.solid ? (q.valid ? "valid solid" : "invalid solid") : (q.faces ? "open" : "-"),
             formatNumber(q.toTruthMean, 2), formatNumber(q.toTruthP95, 2),
             formatNumber(q.fromTruthMean, 2), formatNumber(q.fromTruthP95, 2),
             std::to_string(q.rightKind) + "/" + std::to_string(q.trueFaces),
             formatNumber(q.seconds, 1)});
    }
    if (table.empty()) {
        return totals;
    }
    auto mean = [](const std::vector<double>& v) { return v.empty() ? NAN : meanOf(v); };
    table.push_back({"mean", "", "", "", "", "", "", "", "",
                     std::to_string(solids) + " of " + std::to_string(parts) + " valid solids",
                     formatNumber(mean(to), 2), formatNumber(mean(to95), 2),
                     formatNumber(mean(from), 2), formatNumber(mean(from95), 2),
                     trueFaces ? formatNumber(double(rightKind) / trueFaces) : "-", ""});
    if (!markdown) {
        std::cout << "Patch surfaces (distances in spacings: from the fitted faces to the true "
                     "B-rep, and from the true faces the cloud saw to the fitted ones)\n";
    }
    printTable({"part", "noise", "faces/patches", "plane", "sphere", "cylinder", "cone", "torus",
                "bspline", "shape", "to truth mean", "to truth p95", "from truth mean",
                "from truth p95", "true faces of their kind", "fit s"},
               table, markdown);
    return totals;
}

/// The surfaces' floors' verdict: one line per failure; true when all pass.
bool surfaceFloorsPass(const SurfaceTotals& totals, const SurfaceFloors& floors)
{
    const std::vector<std::string> failures = surfaceFloorFailures(totals, floors);
    for (const std::string& f : failures) {
        std::cout << "below the surfaces' floor: " << f << "\n";
    }
    return failures.empty();
}

void printSweeps(const Results& results, bool markdown)
{
    std::vector<std::vector<std::string>> sweepRows;
    for (const SweepResult& s : results.sweeps) {
        sweepRows.push_back({s.baseline, s.noise,
                             formatNumber(s.threshold, s.threshold < 1 ? 3 : 0),
                             formatNumber(meanOf(s.f1[0])), formatNumber(meanOf(s.f1[1])),
                             formatNumber(meanOf(s.f1[2]))});
    }
    if (sweepRows.empty()) {
        return;
    }
    if (!markdown) {
        std::cout << "Baseline sweeps: mean F1 over the parts at each threshold\n";
    }
    printTable({"baseline", "noise", "threshold", "sharp F1", "smooth F1", "boundary F1"},
               sweepRows, markdown);
}

void writeDemoCloud(const Arguments& args)
{
    const CadShape part = makeCadShape("boss_blend");
    SamplingOptions sampling;
    sampling.radius = radiusForPointCount(shapeArea(part.shape), args.demoPoints);
    sampling.seed = args.seed;
    const SampledCloud demo = sampleShape(part.shape, sampling);
    writeXyz(args.demoCloud, demo.points, 6);
    std::cerr << "demo cloud: " << args.demoCloud << " (" << demo.points.rows()
              << " points, spacing " << meanNearestSpacing(demo.points) << ")\n";
}

// ---------------------------------------------------------------------------------------------
// Random parts (--random): one part per seed, one cloud by its drawn scanner model.

/// How far from the cloud a true edge still counts as seen (truthCoveredBy): the metric's
/// tolerance, and for the scan models one and a half row gaps, so that an edge running along
/// the rows between two of them is kept (tests/bench/test_scan_sampling.cpp).
double coveringDistance(const ScanOptions& scan, const ScannedCloud& cloud)
{
    const double tolerance = LineScoreOptions{}.toleranceFactor * cloud.spacing;
    const bool rows = scan.model == ScanModel::ScanLines || scan.model == ScanModel::MergedViews;
    return rows ? std::max(tolerance, 1.5 * scan.rowSpacingRatio * cloud.rowStep) : tolerance;
}

/// The true edges of `part` that `cloud` sees: cut to the reach of its points, outliers left
/// out (a point 20 spacings off the surface sees nothing).
std::vector<TypedPolyline> coveredTruth(const RandomPart& part, const ScanOptions& scan,
                                        const ScannedCloud& cloud)
{
    TruthOptions truthOptions;
    truthOptions.step = 0.5 * cloud.spacing;
    const std::vector<TypedPolyline> truth = truthEdges(part.shape, truthOptions);
    PointMatrix seen(cloud.points.rows(), 3);
    Eigen::Index rows = 0;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        if (!cloud.outlier[static_cast<size_t>(i)]) {
            seen.row(rows++) = cloud.points.row(i);
        }
    }
    seen.conservativeResize(rows, 3);
    return truthCoveredBy(truth, seen, coveringDistance(scan, cloud));
}

/// Builds the part of `seed`, samples it by its drawn scanner model, runs the extraction (and
/// the baselines) and scores them against the covered truth; the extraction's record joins
/// `records`, every detector's row `results`.
void measureRandomPart(std::uint32_t seed, const Arguments& args, Results& results,
                       std::vector<RandomPartRecord>& records)
{
    std::cerr << "random part " << seed << ": building" << std::endl;
    const auto buildStart = std::chrono::steady_clock::now();
    RandomPartOptions partOptions;
    partOptions.points = args.pointsGiven ? args.points : 0.0;
    const RandomPart part = makeRandomPart(seed, partOptions);
    ScanOptions scan = drawScanOptions(seed);
    scan.points = part.targetPoints; // the part is sized for its count at spacing 1
    const ScannedCloud cloud = sampleLikeAScanner(part.shape, scan);
    SampledPart s;
    s.seed = seed;
    s.spacing = cloud.spacing;
    s.truth = coveredTruth(part, scan, cloud);

    RandomPartRecord record;
    record.seed = seed;
    record.group = randomGroupOfSeed(seed);
    record.family = part.familyName;
    record.model = scanModelName(scan.model);
    record.noise = scan.normalNoise;
    record.points = static_cast<long>(cloud.points.rows());
    record.spacing = cloud.spacing;
    record.buildSeconds = seconds(buildStart);
    const std::string name = "seed " + std::to_string(seed);
    const std::string noise = formatNumber(scan.normalNoise, 1) + "h";
    std::cerr << "random part " << seed << ": " << part.familyName << ", " << record.model << ", "
              << record.points << " points, noise " << noise << std::endl;

    if (!args.writeDir.empty()) {
        writeCase(args.writeDir, "random-" + std::to_string(seed), cloud.points, s.truth, name,
                  s.spacing, part.shape);
    }

    const auto start = std::chrono::steady_clock::now();
    const auto run = runFeatureLines(cloud.points);
    Row row = featureLinesRow(name, noise, *run, s);
    row.seconds = seconds(start);
    row.group = record.group;
    if (args.surfaces) {
        row.surfaces = surfaceRow(*run, cloud.points, part.shape, s.spacing, args.bspline);
    }
    results.rows.push_back(row);
    record.seconds = row.seconds;
    record.score = row.score;
    record.scoreAtOneSpacing = row.scoreAtOneSpacing;
    record.quality = row.quality;
    records.push_back(record);
    if (args.baselines) {
        SampledCloud plain;
        plain.points = cloud.points;
        plain.normals = cloud.normals;
        runBaselines(name, noise, record.group, plain, s, results);
    }
}

void printTextTable(const TextTable& table, bool markdown)
{
    std::cout << (markdown ? "**" + table.title + "**\n\n" : table.title + "\n");
    printTable(table.header, table.rows, markdown);
}

/// --random: the random parts, their tables, and the floors' verdict (exit 1 below one).
int runRandom(const Arguments& args)
{
    Results results;
    std::vector<RandomPartRecord> records;
    for (const std::uint32_t seed : args.randomSeeds) {
        try {
            measureRandomPart(seed, args, results, records);
        } catch (const std::runtime_error& e) {
            std::cerr << "random part " << seed << ": not measured: " << e.what() << std::endl;
        }
    }
    printTextTable(randomPartTable(records), args.markdown);
    if (args.baselines) {
        printScores(results, args.markdown);
    }
    printLineQuality(results, args.markdown);
    printCurveQuality(results, args.markdown);
    const SurfaceTotals surfaces = printSurfaceQuality(results, args.markdown);
    for (const TextTable& table : randomAggregateTables(records)) {
        printTextTable(table, args.markdown);
    }
    const RandomMeans means = randomMeans(records);
    const std::vector<std::string> failures = floorFailures(means, args.floors);
    std::cout << "mean over the " << records.size() << " random parts: sharp F1 "
              << formatNumber(means.sharpF1) << ", smooth F1 " << formatNumber(means.smoothF1)
              << ", closedness " << formatNumber(means.closedness) << "\n";
    for (const std::string& f : failures) {
        std::cout << "below the floor: " << f << "\n";
    }
    const bool surfacesPass = surfaceFloorsPass(surfaces, args.surfaceFloors);
    return failures.empty() && surfacesPass ? 0 : 1;
}

int run(const Arguments& args)
{
    if (!args.randomSeeds.empty()) {
        return runRandom(args);
    }
    Results results;
    const auto names = allShapeNames();
    for (const std::string& name : args.shapes) {
        // Seeds follow the part's place in the full list, so a subset gives the same clouds.
        const size_t index =
            static_cast<size_t>(std::find(names.begin(), names.end(), name) - names.begin());
        measurePart(makeCadShape(name), isHeldOut(name) ? "held-out" : "measured",
                    args.seed * 1000u + static_cast<unsigned>(index), args, results);
    }
    if (!args.stepDir.empty()) {
        const CadFolder folder = readCadFolder(args.stepDir);
        for (const CadFileReport& f : folder.files) {
            if (!f.error.empty()) {
                std::cerr << "not measured: " << f.error << "\n";
            }
        }
        for (size_t i = 0; i < folder.parts.size(); ++i) {
            measurePart(folder.parts[i], "real",
                        args.seed * 1000u + 500u + static_cast<unsigned>(i), args, results);
        }
    }

    if (!args.markdown) {
        std::cout << "Parts (spacing: mean nearest-neighbour distance of the clean cloud; "
                     "tolerance 3 x spacing)\n";
    }
    printTable({"part", "points", "spacing", "Poisson r", "min fillet / spacing", "sharp edges",
                "smooth edges", "boundary edges", "build+sample s"},
               results.partRows, args.markdown);
    printScores(results, args.markdown);
    printLineQuality(results, args.markdown);
    printCurveQuality(results, args.markdown);
    const SurfaceTotals surfaces = printSurfaceQuality(results, args.markdown);
    printSweeps(results, args.markdown);
    if (!args.demoCloud.empty()) {
        writeDemoCloud(args);
    }
    return surfaceFloorsPass(surfaces, args.surfaceFloors) ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        return run(parseArguments(argc, argv));
    } catch (const std::invalid_argument& e) {
        std::cerr << "featurelines_accuracy: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "featurelines_accuracy: " << e.what() << "\n";
        return 1;
    }
}
