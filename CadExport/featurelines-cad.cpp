// SPDX-License-Identifier: LGPL-2.1-or-later
// featurelines-cad: the fitted line network of a cloud, or the patches' surfaces sewn along it
// (--surfaces), as a CAD file (STEP or BREP) that other CAD tools read. The core's extraction and curve fitting (FeatureLines/curves/CurveNetwork.h),
// the shapes of CurveShapes.h, OpenCASCADE's writers; no FreeCAD.
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "CurveShapes.h"
#include "PatchSurfaces.h"
#include "FeatureLines/Extraction.h"
#include "FeatureLines/cli/Arguments.h"
#include "FeatureLines/cli/Inputs.h"
#include "FeatureLines/cli/OutputFiles.h"

namespace featurelines::cad {
namespace {

using cli::Arguments;
using cli::OptionSpec;
using cli::UsageError;

const std::vector<OptionSpec>& extractOptions()
{
    static const std::vector<OptionSpec> specs{
        {"--output", "FILE",
         "the file to write: .step or .stp (STEP AP214: the curves) or .brep (OpenCASCADE: the "
         "curves and their shared vertices)",
         "-o"},
        {"--borders", "",
         "BREP only: also the closed border wires of the patches, on the same edges"},
        {"--surfaces", "",
         "write the patches' fitted surfaces instead of the lines: a plane, sphere, cylinder, "
         "cone, torus or B-spline per patch with a closed border, trimmed by it, the faces sewn (a solid "
         "where they close)"},
        {"--tolerance", "T",
         "curve fitting tolerance, x point spacing (default 0.25; raised to twice the noise)"},
        {"--corner-angle", "DEG",
         "also cut the curves where a line's direction breaks by DEG degrees or more, 0 to 180 "
         "(default 180: at junctions only; 30 cuts a flat face's border at its corners)"},
        {"--thresholds", "T1,T2", "explicit curvature thresholds (1/length) for every region"},
        {"--no-sharp", "", "no sharp edges"},
        {"--no-smooth", "", "no smooth edges"},
        {"--no-boundary", "", "no boundary lines of an open cloud"},
        {"--k", "N", "neighbours per point, 3 to 256 (default 16)"},
        {"--format", "F", "the format of standard input (-): xyz, txt, asc, csv, ply or pcd"},
    };
    return specs;
}

void printHelp()
{
    std::cout
        << "usage: featurelines-cad extract INPUT -o OUT.step|OUT.stp|OUT.brep [OPTIONS]\n\n"
           "The feature lines of a point cloud fitted by lines, arcs, circles and B-splines,\n"
           "one edge per line piece, written as a CAD file.\n"
           "INPUT: .xyz .txt .asc .csv (x y z per line), .ply or .pcd; - for standard "
           "input.\n\noptions:\n";
    for (const OptionSpec& o : extractOptions()) {
        std::string left = "  " + (o.shortName.empty() ? "" : o.shortName + ", ") + o.name;
        left += o.valueName.empty() ? "" : " " + o.valueName;
        std::cout << left << std::string(left.size() < 24 ? 24 - left.size() : 1, ' ') << o.help
                  << "\n";
    }
}

enum class CadFormat
{
    Step,
    Brep,
};

CadFormat formatOf(const std::string& path)
{
    const std::string ext = cli::lowerExtension(path);
    if (ext == "step" || ext == "stp") {
        return CadFormat::Step;
    }
    if (ext == "brep" || ext == "brp") {
        return CadFormat::Brep;
    }
    throw UsageError("--output must end in .step, .stp or .brep, got '" + path + "'");
}

std::vector<double> thresholdList(const std::string& text)
{
    std::vector<double> values;
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const double v = Arguments::parseNumber("--thresholds", text.substr(at, comma - at));
        if (!(v > 0.0)) {
            throw UsageError("--thresholds must be positive, got " + Arguments::format(v));
        }
        values.push_back(v);
        at = comma + 1;
    }
    return values;
}

ExtractionOptions extractionOptions(const Arguments& a)
{
    ExtractionOptions o;
    o.neighbours.k = static_cast<int>(a.integer("--k", 16, 3, 256));
    o.sharpEdges = !a.has("--no-sharp");
    o.smoothEdges = !a.has("--no-smooth");
    o.sharp.includeBoundary = !a.has("--no-boundary");
    if (!o.sharpEdges && !o.smoothEdges && !o.sharp.includeBoundary) {
        throw UsageError("--no-sharp, --no-smooth and --no-boundary leave nothing to extract");
    }
    if (a.has("--thresholds")) {
        o.thresholdMode = ThresholdMode::Explicit;
        o.thresholds = thresholdList(a.text("--thresholds"));
    }
    return o;
}

/// The shape written: the network's edges, with --borders also the patches' border wires.
TopoDS_Shape outputShape(const NetworkShapes& shapes, const std::vector<BorderWires>& borders)
{
    BRep_Builder builder;
    TopoDS_Compound all;
    builder.MakeCompound(all);
    builder.Add(all, makeEdgeCompound(shapes));
    for (const BorderWires& b : borders) {
        for (const TopoDS_Wire& w : b.wires) {
            builder.Add(all, w);
        }
    }
    return all;
}

/// Writes `shape` to `path` through a temporary file beside it, renamed over it once complete.
void writeShape(const TopoDS_Shape& shape, const std::string& path, CadFormat format)
{
    const std::string target = cli::linkTarget(path);
    const std::string temporary = cli::temporaryFor(target);
    bool written = false;
    if (format == CadFormat::Brep) {
        written = BRepTools::Write(shape, temporary.c_str());
    } else {
        STEPControl_Writer writer;
        written = writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone &&
                  writer.Write(temporary.c_str()) == IFSelect_RetDone;
    }
    std::error_code error;
    if (written) {
        std::filesystem::rename(temporary, target, error);
    }
    if (!written || error) {
        std::filesystem::remove(temporary, error);
        throw std::runtime_error(path + ": OpenCASCADE could not write the file");
    }
}

/// --surfaces: the sewn patch surfaces written, the faces left out named on standard error.
int writeSurfaces(const std::string& input, const PointMatrix& P, const ExtractionResult& result,
                  const CurveFitOptions& fit, const std::string& output, CadFormat format)
{
    const surfaces::PatchSurfaces sewn = surfaces::surfacesOfExtraction(P, result, fit);
    for (const std::string& problem : sewn.problems) {
        std::cerr << "featurelines-cad: " << cli::inputName(input) << ": " << problem << "\n";
    }
    if (sewn.shape.IsNull()) {
        throw std::runtime_error(cli::inputName(input) + ": no patch got a surface (" +
                                 std::to_string(sewn.faces.size()) +
                                 " patches; see the lines above), nothing written");
    }
    writeShape(sewn.shape, output, format);
    int counts[6] = {0, 0, 0, 0, 0, 0};
    int faces = 0;
    for (const surfaces::PatchFace& f : sewn.faces) {
        if (!f.face.IsNull()) {
            ++counts[static_cast<int>(f.surface.kind)];
            ++faces;
        }
    }
    std::cout << cli::inputName(input) << ": " << faces << " of " << sewn.faces.size()
              << " patches got a face (" << counts[0] << " planes, " << counts[1] << " spheres, "
              << counts[2] << " cylinders, " << counts[3] << " cones, " << counts[4] << " tori, "
              << counts[5] << " B-splines), sewn into "
              << (sewn.solid ? (sewn.valid ? "a valid solid" : "a solid BRepCheck finds invalid")
                             : "an open shell")
              << ", tolerance " << sewn.tolerance << " -> " << output << "\n";
    return 0;
}

int runExtract(const Arguments& a)
{
    if (a.positional().size() != 1) {
        throw UsageError(a.positional().empty()
                             ? "no INPUT point cloud given"
                             : "one INPUT only, got " + std::to_string(a.positional().size()));
    }
    const std::string input = a.positional()[0];
    if (!a.has("--output")) {
        throw UsageError("no --output FILE given (.step, .stp or .brep)");
    }
    const std::string output = a.text("--output");
    if (output == "-") {
        throw UsageError("--output must name a file: STEP and BREP are not written to standard "
                         "output");
    }
    const CadFormat format = formatOf(output);
    if (a.has("--borders") && a.has("--surfaces")) {
        throw UsageError("--borders and --surfaces write different shapes: give one");
    }
    if (a.has("--borders") && format != CadFormat::Brep) {
        throw UsageError("--borders needs a .brep output: STEP keeps no shared edges, so each "
                         "border would repeat them");
    }
    CurveFitOptions fit;
    fit.tolerance = a.number("--tolerance", fit.tolerance, 0.0, 100.0, true);
    fit.cornerAngle = a.number("--corner-angle", fit.cornerAngle, 0.0, 180.0, true);
    const ExtractionOptions options = extractionOptions(a);
    const std::string stdinFormat = cli::standardInputFormat(a, input == "-");
    cli::checkOutputs(input, {{"--output", output}});

    const PointMatrix P = cli::readInput(input, stdinFormat);
    const ExtractionResult result = extractFeatureLines(P, options);
    if (a.has("--surfaces")) {
        return writeSurfaces(input, P, result, fit, output, format);
    }
    const CurveNetwork network = fitCurveNetwork(result, fit);
    // As the FreeCAD module: a curve straying more than 2 spacings from its points is a failed
    // fit, written as its polyline.
    const NetworkShapes shapes = makeNetworkShapes(network, gp_Trsf(), 2.0 * result.spacing);
    std::vector<BorderWires> borders;
    int closed = 0;
    for (const PatchBorder& border : patchBorders(network, result, P)) {
        borders.push_back(makeBorderWires(border, shapes));
        closed += borders.back().wires.empty() ? 0 : 1;
    }
    for (const std::string& problem : shapes.problems) {
        std::cerr << "featurelines-cad: " << cli::inputName(input) << ": " << problem << "\n";
    }
    if (!a.has("--borders")) {
        borders.clear();
    }
    writeShape(outputShape(shapes, borders), output, format);
    const auto edges = std::count_if(shapes.edges.begin(), shapes.edges.end(),
                                     [](const TopoDS_Edge& e) { return !e.IsNull(); });
    std::cout << cli::inputName(input) << ": " << edges << " edges, " << network.vertices.rows()
              << " vertices, " << result.lines.size() << " lines, " << closed
              << " closed patch borders -> " << output << "\n";
    return 0;
}

int runMain(const std::vector<std::string>& words)
{
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        printHelp();
        return words.empty() ? 2 : 0;
    }
    if (words[0] != "extract") {
        throw UsageError("unknown command '" + words[0] + "' (featurelines-cad --help)");
    }
    const std::vector<std::string> rest(words.begin() + 1, words.end());
    if (std::find(rest.begin(), rest.end(), "--help") != rest.end() ||
        std::find(rest.begin(), rest.end(), "-h") != rest.end()) {
        printHelp();
        return 0;
    }
    try {
        return runExtract(Arguments(rest, extractOptions()));
    } catch (const UsageError& e) {
        throw UsageError(std::string(e.what()) + " (featurelines-cad --help)");
    }
}

} // namespace
} // namespace featurelines::cad

int main(int argc, char** argv)
{
    using namespace featurelines;
    // OpenCASCADE's STEP writer reports its statistics on standard output: the tool's own line
    // is the only one there.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    try {
        return cad::runMain(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const cli::UsageError& e) {
        std::cerr << "featurelines-cad: " << e.what() << std::endl;
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "featurelines-cad: out of memory" << std::endl;
        return 1;
    } catch (const Standard_Failure& e) {
        std::cerr << "featurelines-cad: OpenCASCADE: " << e.GetMessageString() << std::endl;
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "featurelines-cad: " << e.what() << std::endl;
        return 1;
    }
}
