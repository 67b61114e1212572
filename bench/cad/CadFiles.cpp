// SPDX-License-Identifier: LGPL-2.1-or-later
#include "CadFiles.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace featurelines::bench {

namespace {

std::string lowerExtension(const std::string& path)
{
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

/// Reads a STEP or IGES file through the data exchange reader `R` (all roots transferred).
template <class Reader> TopoDS_Shape readExchangeFile(const std::string& path, const char* format)
{
    Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
        throw std::runtime_error(std::string("not a readable ") + format + " file");
    }
    if (reader.TransferRoots() == 0) {
        throw std::runtime_error(std::string("the ") + format + " file holds no shape");
    }
    return reader.OneShape();
}

TopoDS_Shape readBrepFile(const std::string& path)
{
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder)) {
        throw std::runtime_error("not a readable BREP file");
    }
    return shape;
}

} // namespace

bool isCadFile(const std::string& path)
{
    const std::string e = lowerExtension(path);
    return e == ".step" || e == ".stp" || e == ".iges" || e == ".igs" || e == ".brep" ||
           e == ".brp";
}

CadShape readCadFile(const std::string& path)
{
    const std::string e = lowerExtension(path);
    if (!isCadFile(path)) {
        throw std::invalid_argument(path + ": not a STEP, IGES or BREP file");
    }
    CadShape part;
    part.name = std::filesystem::path(path).filename().string();
    part.description = "real CAD model read from " + part.name;
    try {
        if (e == ".step" || e == ".stp") {
            part.shape = readExchangeFile<STEPControl_Reader>(path, "STEP");
        } else if (e == ".iges" || e == ".igs") {
            part.shape = readExchangeFile<IGESControl_Reader>(path, "IGES");
        } else {
            part.shape = readBrepFile(path);
        }
    } catch (const Standard_Failure& failure) {
        throw std::runtime_error(path + ": OpenCASCADE failed reading it (" +
                                 failure.GetMessageString() + ")");
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(path + ": " + error.what());
    }
    if (part.shape.IsNull() || !TopExp_Explorer(part.shape, TopAbs_FACE).More()) {
        throw std::runtime_error(path + ": the model has no face");
    }
    return part;
}

CadFolder readCadFolder(const std::string& folder)
{
    namespace fs = std::filesystem;
    if (!fs::is_directory(folder)) {
        throw std::invalid_argument(folder + ": no such folder");
    }
    std::vector<std::string> paths;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file() && isCadFile(entry.path().string())) {
            paths.push_back(entry.path().string());
        }
    }
    if (paths.empty()) {
        throw std::invalid_argument(folder + ": no .step, .stp, .iges, .igs, .brep or .brp file");
    }
    std::sort(paths.begin(), paths.end());
    CadFolder result;
    for (const std::string& path : paths) {
        CadFileReport report{fs::path(path).filename().string(), {}};
        try {
            result.parts.push_back(readCadFile(path));
        } catch (const std::exception& e) {
            report.error = e.what();
        }
        result.files.push_back(report);
    }
    return result;
}

} // namespace featurelines::bench
