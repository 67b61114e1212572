// SPDX-License-Identifier: LGPL-2.1-or-later
// Reading real CAD models for the benchmark (bench/cad/CadFiles.h): a box written as BREP and
// as STEP reads back with its 6 faces and 12 sharp edges; bad files are reported, not fatal.
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "CadFiles.h"
#include "ShapeSampling.h"

using namespace featurelines::bench;
namespace fs = std::filesystem;

namespace {

int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum type)
{
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, type, map);
    return map.Extent();
}

/// A fresh folder under the test's working folder.
fs::path freshFolder(const std::string& name)
{
    const fs::path dir = fs::current_path() / ("cad-files-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

int sharpEdges(const TopoDS_Shape& shape)
{
    int n = 0;
    for (const TypedPolyline& e : truthEdges(shape, TruthOptions{})) {
        n += e.type == LineType::Sharp ? 1 : 0;
    }
    return n;
}

} // namespace

TEST(CadFiles, BoxWrittenAsBrepAndStepReadsBackWithItsEdges)
{
    const fs::path dir = freshFolder("box");
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape();
    ASSERT_TRUE(BRepTools::Write(box, (dir / "box.brep").string().c_str()));
    STEPControl_Writer writer;
    ASSERT_EQ(writer.Transfer(box, STEPControl_AsIs), IFSelect_RetDone);
    ASSERT_EQ(writer.Write((dir / "Box.STP").string().c_str()), IFSelect_RetDone);
    std::ofstream(dir / "notes.txt") << "not a model\n"; // no CAD ending: not listed

    const CadFolder folder = readCadFolder(dir.string());
    ASSERT_EQ(folder.files.size(), 2u);
    ASSERT_EQ(folder.parts.size(), 2u);
    for (const CadShape& part : folder.parts) {
        EXPECT_EQ(countOf(part.shape, TopAbs_FACE), 6) << part.name;
        EXPECT_EQ(sharpEdges(part.shape), 12) << part.name;
    }
    // File-name order, as written.
    EXPECT_EQ(folder.parts[0].name, "Box.STP");
    EXPECT_EQ(folder.parts[1].name, "box.brep");
}

TEST(CadFiles, BrokenFileIsReportedAndTheOthersRead)
{
    const fs::path dir = freshFolder("broken");
    ASSERT_TRUE(BRepTools::Write(BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape(),
                                 (dir / "a.brep").string().c_str()));
    std::ofstream(dir / "b.step") << "ISO-10303-21;\nthis is no STEP data\n";
    std::ofstream(dir / "c.brep") << "garbage";
    const CadFolder folder = readCadFolder(dir.string());
    ASSERT_EQ(folder.files.size(), 3u);
    EXPECT_EQ(folder.parts.size(), 1u);
    EXPECT_TRUE(folder.files[0].error.empty());
    EXPECT_NE(folder.files[1].error.find("b.step"), std::string::npos) << folder.files[1].error;
    EXPECT_NE(folder.files[2].error.find("c.brep"), std::string::npos) << folder.files[2].error;
}

TEST(CadFiles, MissingOrEmptyFolderIsRefused)
{
    EXPECT_THROW(readCadFolder((fs::current_path() / "no-such-folder").string()),
                 std::invalid_argument);
    const fs::path dir = freshFolder("empty");
    std::ofstream(dir / "readme.md") << "nothing\n";
    EXPECT_THROW(readCadFolder(dir.string()), std::invalid_argument);
    EXPECT_THROW(readCadFile((dir / "readme.md").string()), std::invalid_argument);
}
