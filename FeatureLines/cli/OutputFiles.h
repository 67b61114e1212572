// SPDX-License-Identifier: LGPL-2.1-or-later
// The featurelines tool's output files: checked before any work, written whole or not at all.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

#include "FeatureLines/cli/Arguments.h"

namespace featurelines::cli {

namespace fs = std::filesystem;

/// True when paths a and b name the same file: the same inode where both exist (through links
/// and different spellings alike), the same canonical path otherwise.
inline bool sameFile(const std::string& a, const std::string& b)
{
    std::error_code error;
    if (fs::exists(a, error) && fs::exists(b, error)) {
        const bool same = fs::equivalent(a, b, error);
        return !error && same;
    }
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, error), error);
    const fs::path cb = fs::weakly_canonical(fs::absolute(b, error), error);
    return ca == cb;
}

/// The folder a file named `path` is written into ("." for a bare name).
inline fs::path folderOf(const std::string& path)
{
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

/// The file written for `path`: the file a symbolic link names (the link is kept), else
/// `path` itself.
inline std::string linkTarget(const std::string& path)
{
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(path, error))) {
        return path;
    }
    const fs::path target = fs::weakly_canonical(path, error);
    return error ? path : target.string();
}

/// The temporary file beside `path` that is renamed over it once complete.
inline std::string temporaryFor(const std::string& path)
{
#if __has_include(<unistd.h>)
    const std::string id = std::to_string(static_cast<long>(getpid()));
#else
    const std::string id = "0";
#endif
    return (folderOf(path) /
            ("." + fs::path(path).filename().string() + ".featurelines-" + id + ".tmp"))
        .string();
}

/// One output file of a run: the option that names it and its path.
struct OutputFile
{
    std::string option;
    std::string path;
};

/// Checks the output files of a run before any work is done; "-" is standard output. UsageError
/// (exit 2) for an empty name, two outputs to standard output, an output that is the input, or two
/// outputs that are one file; std::runtime_error (exit 1) for a folder that does not exist or
/// cannot be written, and a name that is a folder.
inline void checkOutputs(const std::string& input, const std::vector<OutputFile>& outputs)
{
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const OutputFile& o = outputs[i];
        if (o.path.empty()) {
            throw UsageError(o.option + ": the output file name is empty");
        }
        if (o.path == "-") {
            for (std::size_t j = 0; j < i; ++j) {
                if (outputs[j].path == "-") {
                    throw UsageError(o.option + " and " + outputs[j].option +
                                     " cannot both write to standard output (-)");
                }
            }
            continue; // standard output: written directly (writeWhole)
        }
        if (input != "-" && sameFile(o.path, input)) {
            throw UsageError(o.option + " " + o.path +
                             " is the input file; it would be overwritten: choose another name");
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (sameFile(o.path, outputs[j].path)) {
                throw UsageError(o.option + " " + o.path + " is also the file of " +
                                 outputs[j].option + ": choose another name");
            }
        }
        std::error_code error;
        const fs::file_status status = fs::status(o.path, error);
        if (fs::is_directory(status)) {
            throw std::runtime_error(o.path + ": is a folder; the output needs a file name");
        }
        if (fs::exists(status) && !fs::is_regular_file(status)) {
            continue; // a device such as /dev/stdout, written directly (writeWhole)
        }
        const fs::path folder = folderOf(linkTarget(o.path));
        if (!fs::is_directory(folder, error)) {
            throw std::runtime_error(o.path + ": the folder " + folder.string() +
                                     " does not exist");
        }
        // Whether the folder takes a new file (permissions, a read-only file system): the
        // temporary file the result is written to first, created and removed.
        const std::string probe = temporaryFor(linkTarget(o.path));
        std::FILE* file = std::fopen(probe.c_str(), "wb");
        if (!file) {
            throw std::runtime_error(o.path + ": cannot write in the folder " + folder.string() +
                                     " (" + std::strerror(errno) + ")");
        }
        std::fclose(file);
        fs::remove(probe, error);
    }
}

/// Writes `content` to `path` whole or not at all: into a temporary file beside it, flushed
/// and synced to the disk, then renamed over `path`, so a failed or cut-short write leaves a
/// previous file of that name as it was. A symbolic link is followed (the file it names is
/// replaced, the link kept); a path that exists and is not a regular file (a device such as
/// /dev/stdout) is written directly, and so is "-", standard output. Throws
/// std::runtime_error naming the file.
inline void writeWhole(const std::string& path, const std::string& content)
{
    if (path == "-") {
        std::fwrite(content.data(), 1, content.size(), stdout);
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
            throw std::runtime_error("standard output: writing failed (" +
                                     std::string(std::strerror(errno)) + ")");
        }
        return;
    }
    std::error_code error;
    const bool direct = fs::exists(path, error) && !fs::is_regular_file(path, error);
    const std::string finalPath = linkTarget(path);
    const std::string target = direct ? path : temporaryFor(finalPath);
    const auto failed = [&](const std::string& reason) {
        if (!direct) {
            std::error_code ignored;
            fs::remove(target, ignored);
        }
        return std::runtime_error(path + ": writing the file failed (" + reason + ")");
    };
    std::FILE* file = std::fopen(target.c_str(), "wb");
    if (!file) {
        throw failed(std::strerror(errno));
    }
    const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
    int reason = written ? 0 : errno;
    if (std::fflush(file) != 0 && reason == 0) {
        reason = errno;
    }
#if __has_include(<unistd.h>)
    if (reason == 0 && !direct && fsync(fileno(file)) != 0) {
        reason = errno;
    }
#endif
    if (std::fclose(file) != 0 && reason == 0) {
        reason = errno;
    }
    if (reason != 0 || !written) {
        throw failed(std::strerror(reason != 0 ? reason : EIO));
    }
    if (!direct) {
        fs::rename(target, finalPath, error);
        if (error) {
            throw failed(error.message());
        }
    }
}

} // namespace featurelines::cli
