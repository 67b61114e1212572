// SPDX-License-Identifier: LGPL-2.1-or-later
// Real CAD parts for the accuracy benchmark: B-rep models read from STEP, IGES or BREP files in
// a folder the user names (the files stay where they are; none is shipped with the project).
#pragma once

#include <string>
#include <vector>

#include "CadShapes.h"

namespace featurelines::bench {

/// What became of one file of the folder.
struct CadFileReport
{
    std::string file;
    /// Empty when the file was read; else why not (the reader's words).
    std::string error;
};

struct CadFolder
{
    /// The parts read, named by their file name without its folder, in file-name order.
    std::vector<CadShape> parts;
    /// Every file with a CAD ending, read or not, in the same order.
    std::vector<CadFileReport> files;
};

/// The file endings read: .step/.stp (STEP), .iges/.igs (IGES), .brep/.brp (OpenCASCADE's
/// own format), in any letter case.
bool isCadFile(const std::string& path);

/// Reads one CAD file into one shape (all roots of a STEP or IGES file in one compound).
/// Throws std::invalid_argument for an unknown ending, std::runtime_error when the file cannot
/// be read or holds no face.
CadShape readCadFile(const std::string& path);

/// Reads every CAD file directly in `folder`. A file that fails is reported, not fatal.
/// Throws std::invalid_argument when the folder does not exist or holds no CAD file.
CadFolder readCadFolder(const std::string& folder);

} // namespace featurelines::bench
