// SPDX-License-Identifier: LGPL-2.1-or-later
// featurelines-cad run as a user would, on a sampled cube: its BREP and STEP files read back
// with OpenCASCADE hold the cube's twelve straight edges (the BREP on eight shared corners);
// with --surfaces the STEP holds one valid solid of six faces and the cube's volume; a wrong
// call exits with 2 and a message.
#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "SampledShapes.h"
#include "ShapeCounts.h"

namespace fs = std::filesystem;

namespace {

constexpr double edge = 20.0, spacing = 0.5;

/// A scratch folder of this process's own (ctest runs each test in a process of its own, in
/// parallel with -j), emptied.
fs::path scratch()
{
    const fs::path dir =
        fs::temp_directory_path() / ("featurelines-cad-test-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// The tool's exit code on `arguments` (its output in `log`).
int runTool(const std::string& arguments, const fs::path& log)
{
    const std::string command =
        std::string(FEATURELINES_CAD_TOOL) + " " + arguments + " > " + log.string() + " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string textOf(const fs::path& file)
{
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Every edge is a straight line as long as a cube edge, within a spacing.
void expectCubeEdges(const TopoDS_Shape& shape)
{
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); ++i) {
        double first = 0.0, last = 0.0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(edges(i)), first, last);
        ASSERT_FALSE(curve.IsNull());
        EXPECT_EQ(GeomAdaptor_Curve(curve).GetType(), GeomAbs_Line) << "edge " << i;
        EXPECT_NEAR(curve->Value(first).Distance(curve->Value(last)), edge, spacing)
            << "edge " << i;
    }
}

class FeatureLinesCad : public ::testing::Test
{
protected:
    static void SetUpTestSuite()
    {
        dir = new fs::path(scratch());
        const featurelines::shapes::Sample cube = featurelines::shapes::cube(edge, spacing, 5);
        std::ofstream out(*dir / "cube.xyz");
        out.precision(17);
        for (Eigen::Index i = 0; i < cube.points.rows(); ++i) {
            out << cube.points(i, 0) << " " << cube.points(i, 1) << " " << cube.points(i, 2)
                << "\n";
        }
    }
    static void TearDownTestSuite()
    {
        fs::remove_all(*dir);
        delete dir;
    }
    static fs::path* dir;
};
fs::path* FeatureLinesCad::dir = nullptr;

} // namespace

TEST_F(FeatureLinesCad, ABrepOfACubeHoldsTwelveLinesOnEightSharedCorners)
{
    const fs::path out = *dir / "cube.brep";
    ASSERT_EQ(
        runTool("extract " + (*dir / "cube.xyz").string() + " -o " + out.string() + " --borders",
                *dir / "brep.log"),
        0)
        << textOf(*dir / "brep.log");
    TopoDS_Shape shape;
    BRep_Builder builder;
    ASSERT_TRUE(BRepTools::Read(shape, out.string().c_str(), builder));
    EXPECT_EQ(countOf(shape, TopAbs_EDGE), 12);
    EXPECT_EQ(countOf(shape, TopAbs_VERTEX), 8);
    // --borders: the six faces' closed wires, on the same twelve edges.
    EXPECT_EQ(countOf(shape, TopAbs_WIRE), 6);
    expectCubeEdges(shape);
    EXPECT_NE(textOf(*dir / "brep.log").find(": 12 edges, 8 vertices"), std::string::npos)
        << textOf(*dir / "brep.log");
}

TEST_F(FeatureLinesCad, AStepOfACubeReadsBackWithTwelveLines)
{
    const fs::path out = *dir / "cube.step";
    ASSERT_EQ(runTool("extract " + (*dir / "cube.xyz").string() + " -o " + out.string(),
                      *dir / "step.log"),
              0)
        << textOf(*dir / "step.log");
    STEPControl_Reader reader;
    ASSERT_EQ(reader.ReadFile(out.string().c_str()), IFSelect_RetDone);
    ASSERT_GT(reader.TransferRoots(), 0);
    const TopoDS_Shape shape = reader.OneShape();
    EXPECT_EQ(countOf(shape, TopAbs_EDGE), 12);
    expectCubeEdges(shape);
}

TEST_F(FeatureLinesCad, SurfacesOfACubeAreAStepSolidOfSixPlanes)
{
    // --surfaces: the patches' planes trimmed by the lines and sewn, read back from STEP as one
    // valid solid of the cube's volume.
    const fs::path out = *dir / "cube-surfaces.step";
    ASSERT_EQ(runTool("extract " + (*dir / "cube.xyz").string() + " -o " + out.string() +
                          " --surfaces",
                      *dir / "surfaces.log"),
              0)
        << textOf(*dir / "surfaces.log");
    STEPControl_Reader reader;
    ASSERT_EQ(reader.ReadFile(out.string().c_str()), IFSelect_RetDone);
    ASSERT_GT(reader.TransferRoots(), 0);
    const TopoDS_Shape shape = reader.OneShape();
    EXPECT_EQ(countOf(shape, TopAbs_SOLID), 1);
    EXPECT_EQ(countOf(shape, TopAbs_FACE), 6);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    EXPECT_NEAR(std::abs(props.Mass()), edge * edge * edge, 0.01 * edge * edge * edge);
    EXPECT_NE(textOf(*dir / "surfaces.log").find("6 of 6 patches got a face (6 planes"),
              std::string::npos)
        << textOf(*dir / "surfaces.log");
}

TEST_F(FeatureLinesCad, AWrongCallExitsWithTwoAndSaysWhy)
{
    const fs::path log = *dir / "usage.log";
    EXPECT_EQ(
        runTool("extract " + (*dir / "cube.xyz").string() + " -o " + (*dir / "cube.obj").string(),
                log),
        2);
    EXPECT_NE(textOf(log).find("--output must end in .step, .stp or .brep"), std::string::npos)
        << textOf(log);
    EXPECT_EQ(runTool("extract " + (*dir / "cube.xyz").string() + " -o " +
                          (*dir / "cube.step").string() + " --borders",
                      log),
              2);
    EXPECT_NE(textOf(log).find("--borders needs a .brep output"), std::string::npos);
    EXPECT_EQ(runTool("extract " + (*dir / "cube.xyz").string() + " -o " +
                          (*dir / "cube.brep").string() + " --borders --surfaces",
                      log),
              2);
    EXPECT_NE(textOf(log).find("--borders and --surfaces write different shapes"),
              std::string::npos);
    EXPECT_EQ(
        runTool("extract " + (*dir / "missing.xyz").string() + " -o " + (*dir / "x.brep").string(),
                log),
        1);
    EXPECT_FALSE(fs::exists(*dir / "x.brep"));
}
