// SPDX-License-Identifier: LGPL-2.1-or-later
// The featurelines tool's inputs: files, folders of clouds, and "-" for standard input.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

#include "FeatureLines/cli/Arguments.h"
#include "FeatureLines/io/CloudIO.h"

namespace featurelines::cli {

/// The extensions readCloud reads (CloudIO.h), lower case and without the dot.
inline const std::vector<std::string>& cloudExtensions()
{
    static const std::vector<std::string> list{"xyz", "txt", "asc", "csv", "ply", "pcd"};
    return list;
}

/// The extension of `path` in lower case, without the dot ("" when it has none).
inline std::string lowerExtension(const std::string& path)
{
    std::string e = std::filesystem::path(path).extension().string();
    if (!e.empty()) {
        e.erase(0, 1);
    }
    std::transform(e.begin(), e.end(), e.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

inline bool isCloudFile(const std::string& path)
{
    const std::vector<std::string>& known = cloudExtensions();
    return std::find(known.begin(), known.end(), lowerExtension(path)) != known.end();
}

/// The input words expanded: a folder stands for the cloud files directly in it (by known
/// extension, sorted by name; hidden files left out), a file or "-" for itself. A folder with
/// no cloud file is a std::runtime_error (bad input, exit 1).
inline std::vector<std::string> expandInputs(const std::vector<std::string>& words)
{
    namespace fs = std::filesystem;
    std::vector<std::string> inputs;
    for (const std::string& word : words) {
        std::error_code error;
        if (word == "-" || !fs::is_directory(word, error)) {
            inputs.push_back(word);
            continue;
        }
        std::vector<std::string> found;
        for (const fs::directory_entry& e : fs::directory_iterator(word, error)) {
            const std::string name = e.path().filename().string();
            if (!name.empty() && name[0] != '.' && e.is_regular_file(error) && isCloudFile(name)) {
                found.push_back(e.path().string());
            }
        }
        if (error) {
            throw std::runtime_error(word + ": cannot list the folder (" + error.message() + ")");
        }
        if (found.empty()) {
            throw std::runtime_error(word + ": the folder has no point cloud file (.xyz .txt .asc "
                                            ".csv .ply .pcd)");
        }
        std::sort(found.begin(), found.end());
        inputs.insert(inputs.end(), found.begin(), found.end());
    }
    return inputs;
}

/// How an input is named in messages: "standard input" for "-".
inline std::string inputName(const std::string& input)
{
    return input == "-" ? std::string("standard input") : input;
}

/// The format of standard input from --format (default xyz); UsageError for an unknown one or
/// for --format with an input that is a file (whose extension says its format).
inline std::string standardInputFormat(const Arguments& a, bool readsStandardInput)
{
    if (!a.has("--format")) {
        return "xyz";
    }
    if (!readsStandardInput) {
        throw UsageError("--format is for standard input (-) only: a file's extension gives its "
                         "format");
    }
    std::string f = a.text("--format");
    if (!f.empty() && f[0] == '.') {
        f.erase(0, 1);
    }
    if (!isCloudFile("x." + f)) {
        throw UsageError("--format must be one of xyz, txt, asc, csv, ply, pcd, got '" +
                         a.text("--format") + "'");
    }
    return f;
}

/// Reads the cloud of `input`: a file by its extension, or "-": all of standard input, in
/// `format`, through a temporary file (readCloud reads regular files only) removed afterwards.
/// Messages name "standard input" rather than the temporary file.
inline PointMatrix readInput(const std::string& input, const std::string& format)
{
    if (input != "-") {
        return readCloud(input);
    }
    namespace fs = std::filesystem;
#if __has_include(<unistd.h>)
    const std::string id = std::to_string(static_cast<long>(getpid()));
#else
    const std::string id = "0";
#endif
    std::error_code error;
    const fs::path folder = fs::temp_directory_path(error);
    const std::string temporary =
        ((error ? fs::path(".") : folder) / ("featurelines-stdin-" + id + "." + format)).string();
    struct Removal
    {
        std::string path;
        ~Removal()
        {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
    } removal{temporary};
    {
        std::ofstream copy(temporary, std::ios::binary);
        if (!copy) {
            throw std::runtime_error("standard input: cannot make a temporary copy in " +
                                     folder.string());
        }
        copy << std::cin.rdbuf();
        copy.flush();
        if (!copy) {
            // An empty standard input makes << fail without writing: readCloud says "no point".
            if (std::cin.bad()) {
                throw std::runtime_error("standard input: reading failed");
            }
        }
    }
    try {
        return readCloud(temporary);
    } catch (const std::exception& e) {
        std::string message = e.what();
        for (std::size_t at = message.find(temporary); at != std::string::npos;
             at = message.find(temporary, at)) {
            message.replace(at, temporary.size(), "standard input");
        }
        throw std::invalid_argument(message);
    }
}

} // namespace featurelines::cli
